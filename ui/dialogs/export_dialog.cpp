#include "ui/dialogs/export_dialog.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include "base/text_format.h"
#include "io/point_cloud_export.h"
#include "io/project_io.h"
#include "job/prepared_render.h"
#include "mesh/mesh_io.h"
#include "render/compiled_ifs.h"
#include "ui/base/widgets.h"
#include "volume/condensation_mesh.h"
#include "volume/measure_attractor.h"

namespace gridifs::ui {
namespace {

// The deterministic snapshot with the condensation sets' meshes read (A_n = C ∪ F(A_{n−1})).
DeterministicIfs deterministicSnapshot(const ModellerState& state) {
  DeterministicIfs ifs = snapshotDeterministicIfs(state.document.project(), state.document.evaluation());
  loadCondensationMeshes(ifs, state.document.project(), state.projectFolder());
  return ifs;
}

namespace fs = std::filesystem;

constexpr std::int64_t kMaxGuiPointSamples = 1'000'000'000;  // as the CLI: 15 GB of PLY

std::string megabytes(std::uint64_t bytes) {
  char text[32];
  if (bytes >= (std::uint64_t(1) << 30))
    std::snprintf(text, sizeof text, "%.1f GB", double(bytes) / double(1 << 30));
  else
    std::snprintf(text, sizeof text, "%.1f MB", double(bytes) / double(1 << 20));
  return text;
}

fs::path defaultFolder(const ModellerState& state) {
  std::error_code ec;
  if (!state.document.path().empty()) return state.document.path().parent_path();
  return fs::current_path(ec);
}

std::string defaultOutput(const ModellerState& state, const char* suffix) {
  const std::string stem = state.document.path().empty() ? "untitled" : state.document.path().stem().string();
  return (defaultFolder(state) / (stem + suffix)).string();
}

}  // namespace

void ExportDialog::drawMenuItems(ModellerState& state) {
  if (ImGui::MenuItem("Export mesh...", nullptr, false, !running())) open(Kind::Mesh, state);
  state.probe.item("menu.export_mesh");
  if (ImGui::MenuItem("Export points...", nullptr, false, !running())) open(Kind::Points, state);
  state.probe.item("menu.export_points");
}

void ExportDialog::open(Kind kind, const ModellerState& state) {
  if (running()) return;
  kind_ = kind;
  open_ = true;
  justOpened_ = true;
  phase_ = TaskPhase::Options;
  message_.clear();
  if (meshOutput_.empty()) meshOutput_ = defaultOutput(state, "-mesh.ply");
  if (pointsOutput_.empty()) pointsOutput_ = defaultOutput(state, "-points.ply");
  plan_.valid = false;
}

void ExportDialog::updatePlan(const ModellerState& state) {
  if (plan_.valid && plan_.revision == state.document.revisions().geometry && plan_.depth == depth_ &&
      plan_.subdivide == subdivide_ && plan_.base == base_ && plan_.baseFile == baseFile_ && plan_.smooth == smooth_ &&
      plan_.fit == fit_ && plan_.output == meshOutput_)
    return;
  plan_.valid = true;
  plan_.revision = state.document.revisions().geometry;  // the plan depends on the functions only
  plan_.depth = depth_;
  plan_.subdivide = subdivide_;
  plan_.base = base_;
  plan_.baseFile = baseFile_;
  plan_.smooth = smooth_;
  plan_.fit = fit_;
  plan_.output = meshOutput_;
  plan_.error.clear();
  try {
    const BaseMeshSpec spec = meshSpec(meshFormatFromPath(meshOutput_));
    DeterministicOptions options;
    options.depth = depth_;
    if (spec.shape == BaseShape::File && baseFile_.empty()) throw ModelError("", "choose a base mesh file");
    plan_.plan = planDeterministic(deterministicSnapshot(state), spec, options);
  } catch (const std::exception& e) {
    plan_.error = e.what();
  }
}

BaseMeshSpec ExportDialog::meshSpec(std::optional<MeshFormat> outputFormat) const {
  const BaseShape shape = base_ == 0 ? BaseShape::Cube : base_ == 1 ? BaseShape::Sphere : BaseShape::File;
  return baseMeshSpec(shape, baseFile_, subdivide_, smooth_, fit_, outputFormat);
}

void ExportDialog::drawMeshOptions(ModellerState& state) {
  const float em = ImGui::GetFontSize();
  ImGui::PushItemWidth(em * 16.0f);
  ImGui::SliderInt("Depth n", &depth_, 0, 12, "%d", ImGuiSliderFlags_AlwaysClamp);
  state.probe.frame("export.depth");
  ImGui::SameLine();
  helpMarker("n in F^n(A): the mesh is N^n transformed copies of the base (Gröller & Wegenkittl 1994, §3.2)");
  static const char* bases[] = {"Cube", "Sphere", "Mesh file"};
  ImGui::Combo("Base A", &base_, bases, 3);
  state.probe.frame("export.base");
  if (base_ == 2) {
    ImGui::InputText("Base file", &baseFile_);
    ImGui::SameLine();
    if (ImGui::Button("Browse...##base")) {
      browsing_ = Browsing::Base;
      browser_.open(FileBrowser::Mode::Open, defaultFolder(state));
    }
    ImGui::Checkbox("Fit into X = [-1, 1]^3", &fit_);
  }
  ImGui::SliderInt("Subdivide", &subdivide_, 0, kMaxSubdivision, "%d", ImGuiSliderFlags_AlwaysClamp);
  state.probe.frame("export.subdivide");
  ImGui::SameLine();
  helpMarker("Subdivision levels of the base (about 4x faces each), so nonlinear functions bend its edges smoothly");
  ImGui::Checkbox("Smooth subdivision", &smooth_);
  ImGui::SameLine();
  ImGui::Checkbox("ASCII", &ascii_);
  ImGui::PopItemWidth();

  updatePlan(state);
  ImGui::Spacing();
  ImGui::PushTextWrapPos(0.0f);
  if (!plan_.error.empty()) {
    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "%s", plan_.error.c_str());
  } else {
    const DeterministicPlan& p = plan_.plan;
    ImGui::Text("%zu^%d = %s copies x %s faces = %s faces, %s vertices", p.functionCount, p.depth,
                withThousands(p.copies).c_str(), withThousands(p.base.faces).c_str(),
                withThousands(p.total.faces).c_str(), withThousands(p.total.vertices).c_str());
    ImGui::TextDisabled("about %s in memory while building", megabytes(p.estimatedBytes).c_str());
    if (p.overLimit)
      ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "Refused: %s", p.message.c_str());
    else if (p.overBudget)
      ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "Warning: %s", p.message.c_str());
  }
  if (const auto format = meshFormatFromPath(meshOutput_); format && !formatHasVertexColors(*format))
    ImGui::TextDisabled("%s files carry no vertex colors; write .ply for colors.", meshFormatName(*format));
  ImGui::PopTextWrapPos();
}

void ExportDialog::drawPointsOptions(ModellerState& state) {
  const float em = ImGui::GetFontSize();
  ImGui::PushItemWidth(em * 16.0f);
  const std::int64_t step = 100'000, fast = 1'000'000;
  ImGui::InputScalar("Samples", ImGuiDataType_S64, &samples_, &step, &fast, "%lld");
  samples_ = std::clamp<std::int64_t>(samples_, 1, kMaxGuiPointSamples);
  state.probe.frame("export.samples");
  ImGui::SameLine();
  helpMarker(
      "Chaos-game iterations written as points with their colors (the project's seed; the same points as "
      "`gridifs export-points FILE --samples N`)");
  ImGui::PopItemWidth();
  ImGui::TextDisabled("about %s of binary PLY", megabytes(std::uint64_t(samples_) * 15).c_str());
}

void ExportDialog::start(ModellerState& state) {
  const bool mesh = kind_ == Kind::Mesh;
  const fs::path output = mesh ? meshOutput_ : pointsOutput_;
  message_.clear();
  stage_ = 0;
  // Everything that can fail fast fails here, inline, before the thread starts.
  try {
    if (mesh) {
      checkMeshOutputPath(output);
      updatePlan(state);
      if (!plan_.error.empty()) throw ModelError("", plan_.error);
      if (plan_.plan.overLimit) throw ModelError("", plan_.plan.message);
      const BaseMeshSpec spec = meshSpec(meshFormatFromPath(output));
      DeterministicOptions options;
      options.depth = depth_;
      const MeshWriteOptions writeOptions{!ascii_, true};
      auto ifs = std::make_shared<DeterministicIfs>(deterministicSnapshot(state));
      task_.start([this, ifs, spec, options, writeOptions, output](JobContext& context) -> TaskOutcome {
        try {
          // Built where it lives: OpenMesh meshes copy on move (deterministic_ifs.h).
          auto result = std::make_unique<DeterministicMesh>();
          runDeterministic(
              *ifs, spec, options, *result,
              [&context](double f) {
                context.progress(f);
                return !context.stopRequested();
              },
              context.stopFlag());
          stage_ = 1;
          writeMeshFile(result->mesh, output, writeOptions);  // temporary + rename (mesh_io.h)
          return {TaskPhase::Done, "Wrote " + output.string() + ": " + withThousands(result->plan.total.faces) +
                                       " faces, " + withThousands(result->plan.total.vertices) + " vertices."};
        } catch (const DeterministicCancelled&) {
          return {TaskPhase::Cancelled, "Cancelled; " + output.filename().string() + " was not written."};
        } catch (const std::exception& e) {
          return {TaskPhase::Failed, e.what()};
        }
      });
    } else {
      std::error_code ec;
      if (output.extension() != ".ply" && output.extension() != ".PLY")
        throw ModelError("", "the point file must be a .ply file: " + output.string());
      if (!fs::is_directory(output.parent_path().empty() ? fs::path(".") : output.parent_path(), ec))
        throw ModelError("", "the folder of " + output.string() + " does not exist");
      // The points of `gridifs export-points`: the same job, condensation sets read from files
      // beside the project, and for median functions the points of the density volume
      // (job/prepared_render.h).
      RenderJobOptions options;
      options.threads = 0;  // all cores, as the CLI
      options.samples = samples_;
      options.folder = state.projectFolder();
      const Project& project = state.document.project();
      const std::string source = state.document.path().filename().string();
      // Median functions need their density volume (seconds): it is computed on the task's
      // thread, from a copy of the project, once the settings are checked here; other projects
      // are prepared here, from the document's evaluated grids, and fail inline.
      std::optional<PreparedRender> prepared;
      if (usesSetIteration(project)) {
        checkRenderOutput(project, options);
      } else {
        options.evaluation = &state.document.evaluation();
        prepared = preparePoints(project, options);
        options.evaluation = nullptr;
      }
      task_.start([prepared, project, options, output, source](JobContext& context) -> TaskOutcome {
        try {
          const PreparedRender points = prepared ? *prepared : preparePoints(project, options);
          const std::string description = pointCloudDescription(source, points.output);
          const PointCloudResult written =
              writePointCloud(*points.ifs, points.output, output, description, [&](const RenderStats& s) {
                context.progress(s.progress());
                return !context.stopRequested();
              });
          if (written.cancelled) throw DeterministicCancelled();
          const std::uint64_t n = written.written;
          return {TaskPhase::Done, "Wrote " + output.string() + ": " + withThousands(n) + " points."};
        } catch (const DeterministicCancelled&) {
          return {TaskPhase::Cancelled, "Cancelled; " + output.filename().string() + " was not written."};
        } catch (const std::exception& e) {
          return {TaskPhase::Failed, e.what()};
        }
      });
    }
    phase_ = TaskPhase::Running;
    startedAt_ = state.now;
  } catch (const std::exception& e) {
    phase_ = TaskPhase::Failed;
    message_ = e.what();
  }
}

void ExportDialog::draw(ModellerState& state) {
  if (task_.poll(phase_, message_) && phase_ == TaskPhase::Done) state.info(message_);
  if (!open_) return;
  const char* title = kind_ == Kind::Mesh ? "Export mesh F^n(A)###export" : "Export points###export";
  bool keepOpen = true;
  if (!beginTaskModal(title, 38.0f, running(), open_, justOpened_, keepOpen)) return;
  const float em = ImGui::GetFontSize();
  const bool busy = running();
  std::string& output = kind_ == Kind::Mesh ? meshOutput_ : pointsOutput_;
  ImGui::BeginDisabled(busy);
  ImGui::SetNextItemWidth(-em * 9.0f);
  ImGui::InputText("##output", &output);
  state.probe.item("export.output");
  ImGui::SameLine();
  if (ImGui::Button("Browse...##output")) {
    browsing_ = Browsing::Output;
    const fs::path current(output);
    browser_.open(FileBrowser::Mode::Save, current.has_parent_path() ? current.parent_path() : defaultFolder(state),
                  current.filename().string());
  }
  ImGui::SameLine();
  ImGui::TextUnformatted("Output");
  ImGui::TextDisabled(kind_ == Kind::Mesh ? ".ply (binary, vertex colors, per-face address), .off, .obj or .stl"
                                          : ".ply (binary little-endian, x y z and colors)");
  ImGui::Separator();
  if (kind_ == Kind::Mesh)
    drawMeshOptions(state);
  else
    drawPointsOptions(state);
  ImGui::EndDisabled();

  ImGui::Separator();
  if (busy) {
    char overlay[64];
    const double seconds = state.now - startedAt_;
    if (stage_.load() == 1)
      std::snprintf(overlay, sizeof overlay, "writing the file...  (%.1f s)", seconds);
    else
      std::snprintf(overlay, sizeof overlay, "%s %.0f%%  (%.1f s)", kind_ == Kind::Mesh ? "building" : "walking",
                    100.0 * task_.progress(), seconds);
    ImGui::ProgressBar(float(task_.progress()), ImVec2(-em * 7.0f, 0), overlay);
    state.probe.item("export.progress");
    ImGui::SameLine();
    // The mesh file itself is written in one OpenMesh call, which cannot be interrupted.
    ImGui::BeginDisabled(stage_.load() == 1 || task_.cancelled());
    if (ImGui::Button("Cancel", ImVec2(-1, 0))) task_.cancel();
    ImGui::EndDisabled();
    state.probe.item("export.cancel");
  } else {
    const bool refused = kind_ == Kind::Mesh && plan_.valid && (!plan_.error.empty() || plan_.plan.overLimit);
    ImGui::BeginDisabled(refused);
    if (ImGui::Button("Export", ImVec2(em * 7.0f, 0))) start(state);
    state.probe.item("export.run");
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Close", ImVec2(em * 7.0f, 0))) {
      open_ = false;
      ImGui::CloseCurrentPopup();
    }
    state.probe.item("export.close");
  }
  if (!message_.empty()) {
    const ImVec4 color = phase_ == TaskPhase::Failed ? ImVec4(1.0f, 0.45f, 0.35f, 1.0f)
                         : phase_ == TaskPhase::Done ? ImVec4(0.55f, 0.85f, 0.55f, 1.0f)
                                                     : ImVec4(0.8f, 0.8f, 0.8f, 1.0f);
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(color, "%s", message_.c_str());
    ImGui::PopTextWrapPos();
  }

  if (auto chosen = browser_.draw(state.probe)) {
    if (browsing_ == Browsing::Output)
      output = chosen->string();
    else if (browsing_ == Browsing::Base)
      baseFile_ = chosen->string();
    browsing_ = Browsing::None;
  }
  endTaskModal(keepOpen, open_);
}

nlohmann::json ExportDialog::probeJson() const {
  return {{"open", open_},
          {"kind", kind_ == Kind::Mesh ? "mesh" : "points"},
          {"phase", taskPhaseName(phase_)},
          {"running", running()},
          {"progress", task_.progress()},
          {"output", kind_ == Kind::Mesh ? meshOutput_ : pointsOutput_},
          {"message", message_}};
}

}  // namespace gridifs::ui
