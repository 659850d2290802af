#pragma once
// File > Export mesh… and Export points…: the options of `gridifs export-mesh` and
// `gridifs export-points` in a modal dialog, the face-count/memory plan before starting, the work
// on a background thread with a progress bar that can be cancelled, errors shown inline, and the
// output written atomically (a temporary file renamed over the target).
#include <atomic>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "mesh/base_mesh.h"
#include "mesh/deterministic_ifs.h"
#include "ui/base/file_browser.h"
#include "ui/base/modeller_state.h"
#include "ui/dialogs/dialog_task.h"

namespace gridifs::ui {

class ExportDialog {
 public:
  enum class Kind { Mesh, Points };
  ExportDialog() = default;
  ExportDialog(const ExportDialog&) = delete;
  ExportDialog& operator=(const ExportDialog&) = delete;

  /// The two File menu entries (menu_bar.cpp calls this inside its File menu).
  void drawMenuItems(ModellerState& state);
  /// Opens the dialog for `kind` (keeps the last options).
  void open(Kind kind, const ModellerState& state);
  /// Draws the dialog while open; call every frame at top level.
  void draw(ModellerState& state);
  bool running() const { return task_.running(); }
  bool isOpen() const { return open_; }
  nlohmann::json probeJson() const;

 private:
  void drawMeshOptions(ModellerState& state);
  /// The base-mesh spec of the dialog's options for an output of `outputFormat`.
  BaseMeshSpec meshSpec(std::optional<MeshFormat> outputFormat) const;
  void drawPointsOptions(ModellerState& state);
  void updatePlan(const ModellerState& state);
  void start(ModellerState& state);

  Kind kind_ = Kind::Mesh;
  bool open_ = false, justOpened_ = false;
  // Options (the CLI's flags).
  std::string meshOutput_, pointsOutput_;
  int depth_ = 3, subdivide_ = 0, base_ = 0;  // base: 0 cube, 1 sphere, 2 file
  std::string baseFile_;
  bool smooth_ = false, fit_ = false, ascii_ = false;
  std::int64_t samples_ = 1'000'000;
  // The plan for the current options (mesh), recomputed when they or the project change.
  struct {
    std::uint64_t revision = 0;
    int depth = -1, subdivide = -1, base = -1;
    std::string baseFile, output;
    bool smooth = false, fit = false;
    DeterministicPlan plan;
    std::string error;
    bool valid = false;
  } plan_;
  FileBrowser browser_;
  enum class Browsing { None, Output, Base } browsing_ = Browsing::None;
  // The running export.
  TaskPhase phase_ = TaskPhase::Options;
  std::atomic<int> stage_{0};  // 0 building / walking, 1 writing
  std::string message_;        // shown inline: the result or the error
  double startedAt_ = 0.0;
  DialogTask task_;  // last: destroyed first, it cancels and joins the worker that uses the rest
};

}  // namespace gridifs::ui
