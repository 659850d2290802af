#pragma once
// gridifs.Project: a project with its undo history (a core Document, as the modeller holds one),
// the folder its relative paths start from, and the calls that render it. Every render goes
// through the command line's own code (app/render_setup.h), so what Python gets is what
// `gridifs render` writes.
//
// Thread-safety: one Project is used by one Python thread at a time (a mutex serialises the
// calls, which run with the GIL released); separate Projects render in parallel.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "edit/document.h"
#include "volume/density_volume.h"

namespace gridifs::python {

namespace py = pybind11;

/// Raised as gridifs.Error: one sentence, the command line's.
class PythonError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class PythonProject {
 public:
  /// A project from `project`; relative paths (palettes, sets) start from `folder`, and messages
  /// name `source` (the file, or "<json>").
  PythonProject(Project project, std::filesystem::path folder, std::string source);

  static std::unique_ptr<PythonProject> load(const std::string& path);
  static std::unique_ptr<PythonProject> fromJson(const std::string& text, const std::string& folder);

  void save(const std::string& path);
  std::string toJson() const;

  double get(const std::string& path) const;
  void set(const std::string& path, double value);
  bool undo();
  bool redo();
  py::list paths() const;

  /// `gridifs render` with these keyword options; H×W×4 uint8 (PNG's pixels, alpha 255 where the
  /// file has none) or float32 with hdr (the EXR's R, G, B, A).
  py::array render(const py::kwargs& options);
  py::tuple points(std::int64_t count, std::optional<std::uint64_t> seed, int threads, std::optional<double> time,
                   const py::object& progress);
  py::array volume(int resolution, const py::object& samples, std::optional<std::uint64_t> seed, int threads,
                   std::optional<double> time, const py::object& progress);
  /// The density volume as `gridifs volume FILE -o PATH.vdb` writes it (OpenVDB).
  void volumeFile(const std::string& path, int resolution, const py::object& samples, std::optional<std::uint64_t> seed,
                  int threads, std::optional<double> time, const py::object& progress);
  py::tuple mesh(int depth, const std::string& base, int threads, std::optional<double> time,
                 const py::object& progress);

  /// The project as it stands (a copy).
  Project snapshot() const;

  std::string source() const { return source_; }
  std::string folder() const { return folder_.string(); }
  std::string repr() const;

 private:
  DensityVolume densityVolume(int resolution, const py::object& samples, std::optional<std::uint64_t> seed, int threads,
                              std::optional<double> time, const py::object& progress);

  mutable std::mutex mutex_;
  Document document_;
  std::filesystem::path folder_;
  std::string source_;
};

/// The progress= callable and Ctrl-C for a call that runs with the GIL released: report(f) takes
/// the GIL, calls the callable with f in [0, 1] and checks the interpreter's signals; it answers
/// false once either raised, and rethrow() raises that exception again after the call.
class ProgressReporter {
 public:
  explicit ProgressReporter(py::object callable) : callable_(std::move(callable)) {}
  bool report(double fraction);
  /// Raises the Python exception a callback or a signal raised, if any.
  void rethrow();
  bool failed() const { return failed_; }

 private:
  py::object callable_;
  bool failed_ = false;
  std::optional<py::error_already_set> error_;
};

}  // namespace gridifs::python
