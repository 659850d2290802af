#include "python/python_project.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>

#include "app/cli.h"
#include "app/render_setup.h"
#include "app/render_volume.h"
#include "base/errors.h"
#include "edit/parameter_edit.h"
#include "io/parameter_paths.h"
#include "io/project_io.h"
#include "mesh/base_mesh.h"
#include "mesh/deterministic_ifs.h"
#include "model/volume_settings.h"
#include "python/python_arrays.h"
#include "render/image_file.h"
#include "schema/project_time.h"
#include "volume/condensation_mesh.h"
#include "volume/measure_attractor.h"
#include "volume/vdb_volume_file.h"

namespace gridifs::python {
namespace {

/// The command line's limits: a point cloud of a billion points is 24 GB of arrays.
constexpr std::int64_t kMaxPoints = 1'000'000'000;

/// Runs `work`, turning the errors of the command line's code into PythonError with its sentence.
template <class Work>
auto translated(const std::string& source, Work&& work) -> decltype(work()) {
  try {
    return work();
  } catch (const cli::CliError& e) {
    throw PythonError(cli::oneSentence(e.what()));
  } catch (const ModelError& e) {
    throw PythonError(cli::oneSentence(source + ": " + e.what()));
  } catch (const IoError& e) {
    throw PythonError(cli::oneSentence(e.what()));
  } catch (const RenderCancelled&) {
    throw PythonError("the work on " + source + " was stopped.");
  }
}

/// Runs `work` with the GIL released and the command line's errors as PythonError. What the
/// reporter caught (Ctrl-C, the progress callback's own exception) is raised rather than the error
/// it caused.
template <class Work>
void released(ProgressReporter& reporter, const std::string& source, Work&& work) {
  try {
    py::gil_scoped_release release;
    translated(source, work);
  } catch (const PythonError&) {
    reporter.rethrow();
    throw;
  }
  reporter.rethrow();
}

/// The keyword options of render(), by name: what each sets, as `gridifs render`'s flag does.
struct RenderCall {
  cli::RenderOverrides overrides;
  cli::FlameOptions flame;
  std::optional<int> motionBlur, resolution;
  bool hdr = false;
  py::object progress = py::none();
};

template <class T>
T cast(const py::handle& value, const char* name, const char* what) {
  try {
    return value.cast<T>();
  } catch (const py::cast_error&) {
    throw PythonError(std::string("render(): ") + name + " must be " + what + ", not " +
                      std::string(py::str(py::type::of(value).attr("__name__"))) + ".");
  }
}

RenderCall parseRenderOptions(const py::kwargs& options) {
  RenderCall call;
  auto& o = call.overrides;
  auto& f = call.flame;
  for (const auto& [key, value] : options) {
    const std::string name = py::str(key);
    if (name == "progress") {
      call.progress = py::reinterpret_borrow<py::object>(value);
      continue;
    }
    if (value.is_none()) continue;
    if (name == "width")
      o.width = cast<int>(value, "width", "an int");
    else if (name == "height")
      o.height = cast<int>(value, "height", "an int");
    else if (name == "samples")
      o.samples = std::string(py::str(value));
    else if (name == "quality")
      o.quality = cast<double>(value, "quality", "a number");
    else if (name == "seed")
      o.seed = cast<std::uint64_t>(value, "seed", "a non-negative int");
    else if (name == "threads")
      o.threads = cast<int>(value, "threads", "an int");
    else if (name == "device")
      o.device = cast<std::string>(value, "device", "'auto', 'gpu' or 'cpu'");
    else if (name == "time")
      o.time = cast<double>(value, "time", "a number of seconds");
    else if (name == "mode")
      f.mode = cast<std::string>(value, "mode", "a display mode name");
    else if (name == "palette")
      f.palette = cast<std::string>(value, "palette", "a palette reference");
    else if (name == "density_display")
      f.densityDisplay = cast<std::string>(value, "density_display", "a name");
    else if (name == "supersample")
      f.supersample = cast<int>(value, "supersample", "an int");
    else if (name == "hue")
      f.hue = cast<double>(value, "hue", "a number");
    else if (name == "filter_radius")
      f.filterRadius = cast<double>(value, "filter_radius", "a number");
    else if (name == "estimator_radius")
      f.estimatorRadius = cast<double>(value, "estimator_radius", "a number");
    else if (name == "estimator_minimum")
      f.estimatorMinimum = cast<double>(value, "estimator_minimum", "a number");
    else if (name == "estimator_curve")
      f.estimatorCurve = cast<double>(value, "estimator_curve", "a number");
    else if (name == "transparent")
      f.transparent = cast<bool>(value, "transparent", "True or False");
    else if (name == "motion_blur")
      call.motionBlur = cast<int>(value, "motion_blur", "an int");
    else if (name == "motion_fade")
      f.motionFadeOption = cast<double>(value, "motion_fade", "a number");
    else if (name == "resolution")
      call.resolution = cast<int>(value, "resolution", "an int");
    else if (name == "hdr")
      call.hdr = cast<bool>(value, "hdr", "True or False");
    else
      throw PythonError("render() has no option " + name + "; it takes " + std::string(kRenderOptionNames) + ".");
  }
  if (call.resolution && !(f.mode && *f.mode == "volume"))
    throw PythonError("render(): resolution applies to mode='volume' only.");
  return call;
}

/// How often progress= is called at most (a render polls its workers far more often).
constexpr auto kProgressInterval = std::chrono::milliseconds(50);

}  // namespace

bool ProgressReporter::report(double fraction) {
  if (failed_) return false;
  static thread_local auto last = std::chrono::steady_clock::time_point{};
  const auto now = std::chrono::steady_clock::now();
  if (fraction < 1.0 && now - last < kProgressInterval) return true;
  last = now;
  py::gil_scoped_acquire gil;
  try {
    // Ctrl-C: the interpreter's handler only flags the signal; PyErr_CheckSignals raises it (on
    // the main thread).
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    if (!callable_.is_none()) callable_(std::clamp(fraction, 0.0, 1.0));
  } catch (py::error_already_set& e) {
    error_.emplace(std::move(e));
    failed_ = true;
    return false;
  }
  return true;
}

void ProgressReporter::rethrow() {
  if (error_) {
    py::error_already_set e = std::move(*error_);
    error_.reset();
    throw e;
  }
}

PythonProject::PythonProject(Project project, std::filesystem::path folder, std::string source)
    : document_(std::move(project)), folder_(std::move(folder)), source_(std::move(source)) {
  // Setting a keyframed number keys it at the project's time, as in the modeller.
  document_.setRule(keyEditedParameters);
}

std::unique_ptr<PythonProject> PythonProject::load(const std::string& path) {
  Project project = translated(path, [&] { return cli::loadForVerb(path); });
  const std::filesystem::path file(path);
  return std::make_unique<PythonProject>(std::move(project), file.parent_path(), path);
}

std::unique_ptr<PythonProject> PythonProject::fromJson(const std::string& text, const std::string& folder) {
  Project project = translated("<json>", [&] { return parseProject(text); });
  return std::make_unique<PythonProject>(std::move(project), folder, "<json>");
}

void PythonProject::save(const std::string& path) {
  const std::lock_guard lock(mutex_);
  translated(path, [&] {
    saveProject(document_.project(), path);
    document_.markSaved(path);
  });
}

std::string PythonProject::toJson() const {
  const std::lock_guard lock(mutex_);
  return serializeProject(document_.project());
}

double PythonProject::get(const std::string& path) const {
  const std::lock_guard lock(mutex_);
  return translated(source_, [&] { return parameterValue(document_.project(), path); });
}

void PythonProject::set(const std::string& path, double value) {
  const std::lock_guard lock(mutex_);
  translated(source_, [&] { document_.apply(SetParameter{path, value}); });
}

bool PythonProject::undo() {
  const std::lock_guard lock(mutex_);
  return document_.undo();
}

bool PythonProject::redo() {
  const std::lock_guard lock(mutex_);
  return document_.redo();
}

py::list PythonProject::paths() const {
  const std::lock_guard lock(mutex_);
  py::list list;
  for (const std::string& path : parameterPaths(document_.project())) list.append(path);
  return list;
}

Project PythonProject::snapshot() const {
  const std::lock_guard lock(mutex_);
  return document_.project();
}

std::string PythonProject::repr() const {
  const Project project = snapshot();
  return "<gridifs.Project " + source_ + ": " + std::to_string(project.functions.size()) + " function" +
         (project.functions.size() == 1 ? "" : "s") + ">";
}

/// The file the command line would be given: a name in the project's folder, so that relative
/// paths resolve there and messages name the project as the CLI does.
static std::string fileFor(const std::filesystem::path& folder, const std::string& source) {
  const std::filesystem::path given(source);
  if (given.has_parent_path() || folder.empty()) return source;
  return (folder / given).string();
}

py::array PythonProject::render(const py::kwargs& options) {
  RenderCall call = parseRenderOptions(options);
  const Project project = snapshot();
  const std::string file = fileFor(folder_, source_);
  const bool volume = call.flame.mode && *call.flame.mode == "volume";
  // Never written: the capture below takes the pixels instead. Its extension picks the file the
  // pixels are laid out for (PNG: 8-bit; EXR: float).
  const std::filesystem::path out = std::filesystem::temp_directory_path() / (call.hdr ? "gridifs.exr" : "gridifs.png");
  ProgressReporter reporter(call.progress);
  call.overrides.observer = [&reporter](double f) { return reporter.report(f); };
  CapturedImage captured;
  released(reporter, file, [&] {
    const ImageCapture capture([&](const std::filesystem::path&, const ImageFileLayout& layout, bool isFloat,
                                   const void* pixels) { captured.take(layout, isFloat, pixels); });
    if (volume) {
      if (call.motionBlur || call.flame.anyFlameSetting() || call.flame.transparent || call.flame.motionFadeOption)
        throw PythonError("render(): the flame and motion-blur options do not apply to mode='volume'.");
      cli::runVolumeRenderOf(project, file, out.string(), call.overrides, call.resolution, true);
    } else {
      cli::renderImageOf(project, file, out.string(), call.overrides, call.flame, call.motionBlur, true);
    }
  });
  return captured.toArray(call.hdr);
}

py::tuple PythonProject::points(std::int64_t count, std::optional<std::uint64_t> seed, int threads,
                                std::optional<double> time, const py::object& progress) {
  if (count < 1 || count > kMaxPoints)
    throw PythonError("points(): n must be between 1 and " + std::to_string(kMaxPoints) + ", not " +
                      std::to_string(count) + ".");
  const Project project = snapshot();
  const std::string file = fileFor(folder_, source_);
  cli::RenderOverrides overrides;
  overrides.samples = std::to_string(count);
  overrides.seed = seed;
  overrides.time = time;
  if (threads > 0) overrides.threads = threads;
  PointArrays arrays(count);
  ProgressReporter reporter(progress);
  released(reporter, file, [&] {
    const PreparedRender setup = cli::prepareForVerb(
        project, file, cli::renderJobOptions(file, overrides, kMaxPoints, time.value_or(project.time)), kMaxPoints,
        false, true);
    generatePoints(*setup.ifs, setup.output, [&](const PointBatch& batch, const RenderStats& stats) {
      arrays.append(batch);
      return reporter.report(double(stats.samples) / double(std::max<std::int64_t>(1, setup.output.samples)));
    });
  });
  return arrays.take();
}

DensityVolume PythonProject::densityVolume(int resolution, const py::object& samples, std::optional<std::uint64_t> seed,
                                           int threads, std::optional<double> time, const py::object& progress) {
  if (resolution < kMinVolumeResolution || resolution > kMaxVolumeResolution)
    throw PythonError("volume(): resolution must be between " + std::to_string(kMinVolumeResolution) + " and " +
                      std::to_string(kMaxVolumeResolution) + ", not " + std::to_string(resolution) + ".");
  // An int or a string such as "1e8", parsed as the command line parses --samples.
  const std::optional<std::string> sampleText =
      samples.is_none() ? std::nullopt : std::optional<std::string>(py::str(samples));
  const Project loaded = snapshot();
  const std::string file = fileFor(folder_, source_);
  ProgressReporter reporter(progress);
  DensityVolume result;
  released(reporter, file, [&] {
    const Project project = cli::projectForVerbAt(loaded, file, time);
    VolumeJob job;
    job.settings = project.volume.value_or(VolumeSettings{});
    job.settings.resolution = resolution;
    if (sampleText) job.settings.samples = cli::parseSamples(*sampleText, limits::kMaxRenderSamples);
    if (seed) job.settings.seed = *seed;
    job.threads = threads;
    const std::filesystem::path parent = std::filesystem::path(file).parent_path();
    job.projectFolder = parent.empty() ? std::filesystem::path(".") : parent;
    std::atomic<bool> cancel{false};
    job.cancel = &cancel;
    job.progress = [&](double f) {
      if (!reporter.report(f)) cancel.store(true);
    };
    result = computeDensityVolume(project, job);
    if (result.totalMass <= 0.0)
      throw PythonError(file + ": no point of the attractor fell inside X, so the volume is empty.");
  });
  return result;
}

py::array PythonProject::volume(int resolution, const py::object& samples, std::optional<std::uint64_t> seed,
                                int threads, std::optional<double> time, const py::object& progress) {
  return volumeArray(densityVolume(resolution, samples, seed, threads, time, progress));
}

void PythonProject::volumeFile(const std::string& path, int resolution, const py::object& samples,
                               std::optional<std::uint64_t> seed, int threads, std::optional<double> time,
                               const py::object& progress) {
  translated(path, [&] {
    cli::checkOutputPath(path, {"vdb"}, "the volume");
    requireVdbVolumeWriter();  // before the work, not after it
  });
  const DensityVolume volume = densityVolume(resolution, samples, seed, threads, time, progress);
  py::gil_scoped_release release;
  translated(path, [&] { writeVdbVolume(volume, path); });
}

py::tuple PythonProject::mesh(int depth, const std::string& base, int threads, std::optional<double> time,
                              const py::object& progress) {
  const Project loaded = snapshot();
  const std::string file = fileFor(folder_, source_);
  ProgressReporter reporter(progress);
  std::optional<DeterministicMesh> result;
  released(reporter, file, [&] {
    Document document(cli::projectForVerbAt(loaded, file, time));
    if (usesSetIteration(document.project()))
      throw PythonError("mesh(): " + file +
                        " has median functions, whose sets have no mesh of their own; use volume().");
    DeterministicIfs ifs = snapshotDeterministicIfs(document.project(), document.evaluation());
    const std::filesystem::path parent = std::filesystem::path(file).parent_path();
    loadCondensationMeshes(ifs, document.project(), parent.empty() ? std::filesystem::path(".") : parent);
    const BaseShape shape = base == "cube" ? BaseShape::Cube : base == "sphere" ? BaseShape::Sphere : BaseShape::File;
    const BaseMeshSpec spec = baseMeshSpec(shape, base, 0, false, false, MeshFormat::Ply);
    DeterministicOptions options;
    options.depth = depth;
    options.threads = threads;
    IfsMesh coarse = loadCoarseBase(spec);
    const DeterministicPlan plan = planDeterministic(ifs, predictBaseCounts(coarse, spec), options);
    if (plan.overLimit) throw PythonError("mesh(): " + file + ": " + plan.message + ".");
    const IfsMesh start = refineBase(std::move(coarse), spec);
    result.emplace(buildDeterministicMesh(ifs, start, options, [&](double f) { return reporter.report(f); }));
  });
  return meshArrays(result->mesh);
}

}  // namespace gridifs::python
