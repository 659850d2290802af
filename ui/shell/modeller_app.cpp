// The modeller's window and its fixed frame order: poll → build
// UI (collect edits) → apply edits → publish renderer snapshot → draw views → ImGui render.
#include "ui/shell/modeller_app.h"

#include <epoxy/gl.h>

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <numeric>
#include <vector>

#include "base/atomic_file.h"
#include "render/camera.h"
#include "render/image_file.h"
#include "ui/dialogs/combine_dialog.h"
#include "ui/dialogs/export_dialog.h"
#include "ui/dialogs/render_animation_dialog.h"
#include "ui/gl/screenshot.h"
#include "ui/gl/view_renderer.h"
#include "ui/panels/condensation_set_panel.h"
#include "ui/panels/construction_tree_panel.h"
#include "ui/panels/live_panel.h"
#include "ui/panels/panels.h"
#include "ui/panels/timeline_panel.h"
#include "ui/shell/app_commands.h"
#include "ui/shell/app_window.h"
#include "ui/shell/modeller_options.h"
#include "ui/shell/panel_layout.h"
#include "ui/shell/project_files.h"
#include "ui/shell/theme.h"
#include "ui/views/explore_window.h"
#include "ui/views/grid_view.h"
#include "ui/views/preview_view.h"

namespace gridifs::ui {
namespace {

namespace fs = std::filesystem;

class ModellerApp {
 public:
  ModellerApp(AppWindow& appWindow, ModellerOptions options, float scale)
      : appWindow_(appWindow),
        window_(appWindow.window()),
        options_(std::move(options)),
        files_(state_, AppFolders::fromEnvironment(), options_.autosaveSeconds),
        views_{GridView(GridView::Content::FunctionGrid, ViewAxis::Top, "##top"),
               GridView(GridView::Content::FunctionGrid, ViewAxis::Side, "##side"),
               GridView(GridView::Content::FunctionGrid, ViewAxis::Front, "##front"),
               GridView(GridView::Content::FunctionGrid, ViewAxis::User, "##user")},
        ifsView_(GridView::Content::Ifs, ViewAxis::User, "##ifs") {
    state_.uiScale = scale;
    state_.probe.enabled = !options_.probe.empty();
    if (options_.renderThreads > 0) state_.renderThreads = options_.renderThreads;
    iniPath_ = (files_.folders().config / "imgui.ini").string();
    // The panels saved in imgui.ini were arranged for the window size saved with the geometry;
    // a window that opens at another size carries them over proportionally.
    std::error_code ec;
    if (fs::exists(iniPath_, ec) && appWindow_.savedLayoutWidth() > 0)
      layoutViewport_ = ImVec2(float(appWindow_.savedLayoutWidth()), float(appWindow_.savedLayoutHeight()));
    ImGui::GetIO().IniFilename = iniPath_.c_str();
    commands_ = std::make_unique<AppCommands>(
        AppCommands{state_, edits_, files_, [this] { frameViews(); }, [this] { resetLayout_ = true; }, &export_});
  }

  ~ModellerApp() {
    // ImGui saves the layout when its context is destroyed, after this object (and the path
    // string) are gone: save now and tell ImGui not to.
    ImGui::SaveIniSettingsToDisk(iniPath_.c_str());
    ImGui::GetIO().IniFilename = nullptr;
  }
  ModellerApp(const ModellerApp&) = delete;
  ModellerApp& operator=(const ModellerApp&) = delete;

  /// The frame loop, in the fixed order poll → build UI (collect edits) → apply edits → publish
  /// the renderer's snapshot → draw views → ImGui render; returns the exit code.
  int run();

 private:
  using Clock = std::chrono::steady_clock;
  /// When each phase of a frame began, for --stats and the probe's slowest frame.
  struct FrameTimes {
    Clock::time_point start, ui, uiDone, applied, views, ifsView, preview, viewsDone, tick, ticked, finished;
  };
  static double milliseconds(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
  }

  /// The preview's device, the view renderer, crash recovery and the file to open; false when the
  /// device cannot be had.
  bool startSession();
  /// Waits for input when nothing moves (redraw on demand), else polls.
  void pollEvents(bool capture);
  /// A new ImGui frame: the panels and views collect edits.
  void buildFrame(FrameTimes& t);
  /// Hands the frame's edits to the Document.
  void applyEdits();
  /// Draws the grid views, the IFS view and the preview into their textures.
  void renderViews(FrameTimes& t);
  /// The views' textures and ImGui into the window's framebuffer.
  void present(int fbw, int fbh);
  /// The title, the autosave tick and the frame's timing; returns the frame's milliseconds.
  double finishFrame(FrameTimes& t);
  /// Whether a --screenshot capture has waited enough frames and points.
  bool captureReady() const;
  /// The last probe, the window's geometry, the files' shutdown and the --stats summary.
  void endSession(bool capture);
  void buildUi();
  void drawGridViews(float framebufferScale);
  void drawIfsView(float framebufferScale);
  void frameViews();
  void writeProbe(double frameMs);
  float framebufferScale() const;
  void followContentScale();
  void beginPanel(Panel panel, const PanelRects& layout, ImGuiCond cond);
  void endPanel(Panel panel);

  AppWindow& appWindow_;
  GLFWwindow* window_;
  ModellerOptions options_;
  ModellerState state_;
  ProjectFiles files_;
  EditQueue edits_;
  std::unique_ptr<ViewRenderer> renderer_;
  std::array<GridView, 4> views_;
  GridView ifsView_;
  PreviewView preview_;
  ExportDialog export_;              // File > Export
  RenderAnimationDialog animation_;  // File > Render animation
  CombineDialog combine_;            // File > Combine
  ExploreWindow explore_;            // View > Explore, File > New random world
  CondensationSetPanel setPanel_;    // in the Operations panel's place while a set function is active
  FunctionsPanelState functionsPanel_;
  OperationPanelState operationPanel_;
  SelectionPanelState selectionPanel_;
  MatricesWindowState matricesWindow_;      // Function > Matrices
  ConstructionTreePanel constructionTree_;  // Function > Construction tree
  LivePanel live_;                          // View > Live, and the OSC input
  std::unique_ptr<AppCommands> commands_;
  std::string iniPath_, title_;
  bool resetLayout_ = false;
  PanelRects panels_;      // where each panel was drawn in the last frame
  int panelsSeen_ = 0;     // how many of them were drawn in the last frame
  ImVec2 layoutViewport_;  // the window size the panels are arranged for (0: the current one)
  int frame_ = 0;
  int quietFrames_ = 0;  // frames since the last input or edit: a few more are drawn before waiting
  std::vector<double> frameMs_;
  double slowestFrameMs_ = 0.0;          // past the first frames
  double phaseMs_[5] = {0, 0, 0, 0, 0};  // UI+edits+publish, grid views, IFS view, preview, ImGui
  // Where the slowest frame's time went (written to the probe, so a soak can name the phase).
  nlohmann::json slowestFramePhases_ = nlohmann::json::object();
};

float ModellerApp::framebufferScale() const {
  const ImGuiIO& io = ImGui::GetIO();
  return io.DisplayFramebufferScale.x > 0.0f ? io.DisplayFramebufferScale.x : 1.0f;
}

void ModellerApp::frameViews() {
  for (GridView& v : views_)
    if (v.hovered()) return v.frame(state_, edits_);
  if (ifsView_.hovered()) return ifsView_.frame(state_, edits_);
  for (GridView& v : views_) v.frame(state_, edits_);
  if (ifsView_.axis() != ViewAxis::User) ifsView_.frame(state_, edits_);
}

void ModellerApp::drawGridViews(float fbScale) {
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const float gap = std::round(3.0f * state_.uiScale);
  if (state_.maximizedGridView >= 0) {
    views_[std::size_t(state_.maximizedGridView)].build(state_, edits_, {avail.x, avail.y}, fbScale);
    return;
  }
  const float w = std::floor((avail.x - gap) * 0.5f), h = std::floor((avail.y - gap) * 0.5f);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  for (int v = 0; v < 4; ++v) {
    ImGui::SetCursorScreenPos(ImVec2(origin.x + float(v % 2) * (w + gap), origin.y + float(v / 2) * (h + gap)));
    views_[std::size_t(v)].build(state_, edits_, {w, h}, fbScale);
    state_.probe.item(std::string("view.") + viewAxisName(views_[std::size_t(v)].axis()));
  }
}

void ModellerApp::drawIfsView(float fbScale) {
  static const char* names[] = {"User (preview camera)", "Top", "Side", "Front"};
  static const ViewAxis axes[] = {ViewAxis::User, ViewAxis::Top, ViewAxis::Side, ViewAxis::Front};
  int current = 0;
  for (int i = 0; i < 4; ++i)
    if (axes[i] == ifsView_.axis()) current = i;
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 12);
  if (ImGui::Combo("##ifsaxis", &current, names, 4)) ifsView_.setAxis(axes[current]);
  if (ImGui::IsItemHovered())
    state_.contextHelp = "Which way the IFS view looks; the user view is the preview's camera";
  ImGui::SameLine();
  const Project& project = state_.document.project();
  ImGui::TextDisabled("%zu function%s in the common initial grid%s", project.functions.size(),
                      project.functions.size() == 1 ? "" : "s",
                      project.final_function ? "; the final lattice in violet" : "");
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  ifsView_.build(state_, edits_, {avail.x, avail.y}, fbScale);
  state_.probe.item("view.ifs");
}

void ModellerApp::followContentScale() {
  if (options_.uiScale > 0.0f) return;  // --ui-scale overrides the monitor
  const float scale = std::clamp(appWindow_.contentScale(), 1.0f, 4.0f);
  if (std::abs(scale - state_.uiScale) < 0.01f) return;
  rescaleTheme(scale);
  state_.uiScale = scale;
  resetLayout_ = true;  // the panels' minimum sizes are in font units
}

void ModellerApp::beginPanel(Panel panel, const PanelRects& layout, ImGuiCond cond) {
  ImGui::SetNextWindowPos(layout.pos[std::size_t(panel)], cond);
  ImGui::SetNextWindowSize(layout.size[std::size_t(panel)], cond);
}

void ModellerApp::endPanel(Panel panel) {
  // Called between Begin and End: records where the panel is for a later resize of the window.
  panels_.pos[std::size_t(panel)] = ImGui::GetWindowPos();
  panels_.size[std::size_t(panel)] = ImGui::GetWindowSize();
  ++panelsSeen_;
  static const char* names[] = {"panel.functions", "panel.operations", "panel.parameters", "panel.grids",
                                "panel.selection", "panel.preview",    "panel.ifs"};
  state_.probe.window(names[std::size_t(panel)]);
}

void ModellerApp::buildUi() {
  handleShortcuts(*commands_);
  const float menuHeight = drawMenuBar(*commands_);
  const float statusHeight = std::round(ImGui::GetFontSize() + 12.0f * state_.uiScale);
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  const ImVec2 origin(vp->Pos.x, vp->Pos.y + menuHeight);
  const ImVec2 area(vp->Size.x, vp->Size.y - menuHeight - statusHeight);
  if (layoutViewport_.x <= 0.0f) layoutViewport_ = vp->Size;
  PanelRects layout;
  ImGuiCond cond = ImGuiCond_FirstUseEver;
  const bool resized = layoutViewport_.x != vp->Size.x || layoutViewport_.y != vp->Size.y;
  if (resetLayout_) {
    layout = defaultPanelLayout(origin, area, operationStackPanelMinHeight(std::round(area.x * 0.215f)));
    cond = ImGuiCond_Always;
  } else if (resized && panelsSeen_ >= kPanelCount) {
    // The window changed size: the artist's arrangement follows, proportionally.
    const ImVec2 fromArea(layoutViewport_.x, layoutViewport_.y - menuHeight - statusHeight);
    layout = rescalePanelLayout(panels_, origin, fromArea, origin, area);
    cond = ImGuiCond_Always;
  } else {
    layout = defaultPanelLayout(origin, area, operationStackPanelMinHeight(std::round(area.x * 0.215f)));
  }
  if (cond == ImGuiCond_Always) layoutViewport_ = vp->Size;
  resetLayout_ = false;
  panelsSeen_ = 0;
  const float fbScale = framebufferScale();
  const ImGuiWindowFlags panel = ImGuiWindowFlags_NoCollapse;

  beginPanel(Panel::Functions, layout, cond);
  if (ImGui::Begin("Functions", nullptr, panel)) drawFunctionsPanel(state_, edits_, functionsPanel_);
  endPanel(Panel::Functions);
  ImGui::End();
  beginPanel(Panel::Operations, layout, cond);
  if (ImGui::Begin("Operations", nullptr, panel)) {
    // A condensation or median function has no operation stack: its set is edited here instead.
    state_.clampIndices();
    if (isSetKind(state_.function().kind)) {
      setPanel_.draw(state_, edits_);
    } else {
      setPanel_.clearMessage();
      drawOperationStackPanel(state_, edits_);
    }
  }
  endPanel(Panel::Operations);
  ImGui::End();
  beginPanel(Panel::Parameters, layout, cond);
  if (ImGui::Begin("Parameters", nullptr, panel)) drawOperationPanel(state_, edits_, operationPanel_);
  endPanel(Panel::Parameters);
  ImGui::End();
  beginPanel(Panel::Grids, layout, cond);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(4 * state_.uiScale, 4 * state_.uiScale));
  const std::string gridsTitle = "Grid views: " + state_.function().name + "###Grid views";
  // View windows skip their background: the view image covers it (fill rate matters on llvmpipe).
  const ImGuiWindowFlags viewWindow =
      panel | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse | ImGuiWindowFlags_NoBackground;
  if (ImGui::Begin(gridsTitle.c_str(), nullptr, viewWindow)) drawGridViews(fbScale);
  endPanel(Panel::Grids);
  ImGui::End();
  ImGui::PopStyleVar();
  beginPanel(Panel::Selection, layout, cond);
  if (ImGui::Begin("Selection", nullptr, panel)) drawSelectionPanel(state_, edits_, selectionPanel_);
  endPanel(Panel::Selection);
  ImGui::End();
  beginPanel(Panel::Preview, layout, cond);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(6 * state_.uiScale, 6 * state_.uiScale));
  if (ImGui::Begin("Preview", nullptr, viewWindow)) {
    preview_.build(state_, edits_, fbScale);
    drawTimelinePanel(state_, edits_);
  }
  endPanel(Panel::Preview);
  ImGui::End();
  beginPanel(Panel::Ifs, layout, cond);
  if (ImGui::Begin("IFS view", nullptr, viewWindow)) drawIfsView(fbScale);
  endPanel(Panel::Ifs);
  ImGui::End();
  ImGui::PopStyleVar();

  if (state_.previewMode == PreviewMode::Shaded) {
    // Over the IFS view while the preview shows the shaded display, so that the picture and its
    // light dial stay free (placed once; the artist may move it).
    const ImVec2 ifsPos = panels_.pos[std::size_t(Panel::Ifs)], ifsSize = panels_.size[std::size_t(Panel::Ifs)];
    const float em = ImGui::GetFontSize();
    ImGui::SetNextWindowPos(ImVec2(ifsPos.x + ifsSize.x - em * 18.0f, ifsPos.y), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(em * 18.0f, std::max(em * 20.0f, ifsSize.y)), ImGuiCond_FirstUseEver);
    if (ImGui::Begin("Shading")) drawShadingPanel(state_, edits_);
    state_.probe.window("panel.shading");
    ImGui::End();
  }
  if (state_.previewMode == PreviewMode::Volume) {
    // The volume's field layers beside the cloud they shape (placed once; the artist may move it).
    const ImVec2 ifsPos = panels_.pos[std::size_t(Panel::Ifs)];
    const float em = ImGui::GetFontSize();
    ImGui::SetNextWindowPos(ImVec2(ifsPos.x, ifsPos.y), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(em * 20.0f, em * 30.0f), ImGuiCond_FirstUseEver);
    if (ImGui::Begin("Field layers")) drawFieldLayersPanel(state_, edits_);
    state_.probe.window("panel.fieldlayers");
    ImGui::End();
  }
  if (state_.showCamera) {
    // Over the IFS view, beside the preview it changes (placed once; the artist may move it).
    const ImVec2 previewPos = panels_.pos[std::size_t(Panel::Ifs)];
    const float em = ImGui::GetFontSize();
    ImGui::SetNextWindowPos(ImVec2(previewPos.x, previewPos.y), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(em * 19.0f, em * 25.0f), ImGuiCond_FirstUseEver);
    if (ImGui::Begin("Camera", &state_.showCamera)) drawCameraPanel(state_, edits_);
    state_.probe.window("panel.camera");
    ImGui::End();
  }
  if (state_.showLive) {
    const float em = ImGui::GetFontSize();
    ImGui::SetNextWindowSize(ImVec2(em * 30.0f, em * 16.0f), ImGuiCond_FirstUseEver);
    if (ImGui::Begin("Live", &state_.showLive)) live_.draw(state_);
    state_.probe.window("panel.live");
    ImGui::End();
  }
  drawHelpWindow(state_);
  drawMatricesWindow(state_, edits_, matricesWindow_);
  constructionTree_.draw(state_, edits_);
  files_.draw(edits_);
  export_.draw(state_);
  animation_.draw(state_);
  combine_.draw(state_, edits_);
  explore_.draw(state_, edits_);
  if (!state_.gridError.empty() && state_.statusText != state_.gridError) state_.error(state_.gridError);
  drawStatusBar(state_, statusHeight);
}

void ModellerApp::writeProbe(double frameMs) {
  if (options_.probe.empty()) return;
  nlohmann::json j;
  int x = 0, y = 0, w = 0, h = 0;
  glfwGetWindowPos(window_, &x, &y);
  glfwGetWindowSize(window_, &w, &h);
  j["window"] = {{"x", x},
                 {"y", y},
                 {"width", w},
                 {"height", h},
                 {"maximized", glfwGetWindowAttrib(window_, GLFW_MAXIMIZED) != 0}};
  const ScreenRect work = appWindow_.workArea();
  j["work_area"] = {{"x", work.x}, {"y", work.y}, {"width", work.width}, {"height", work.height}};
  j["ui_scale"] = state_.uiScale;
  j["content_scale"] = appWindow_.contentScale();
  j["font_size"] = ImGui::GetFontSize();
  j["title"] = title_;
  j["frame"] = frame_;
  j["frame_ms"] = frameMs;
  j["slowest_frame_ms"] = slowestFrameMs_;  // since the first frames (fonts, shaders) were made
  j["slowest_frame_phases"] = slowestFramePhases_;
  j["revision"] = state_.document.revision();
  j["dirty"] = state_.document.dirty();
  j["path"] = state_.document.path().string();
  j["undo"] = state_.document.undoLabel();
  j["functions"] = state_.document.project().functions.size();
  if (state_.activeFunction.isFinal())
    j["active_function"] = "final";
  else
    j["active_function"] = state_.activeFunction.index();
  j["final_message"] = state_.finalFunctionMessage;
  j["set_message"] = setPanel_.message();
  j["active_op"] = state_.activeOp;
  j["ops"] = state_.function().ops.size();
  j["status"] = state_.statusText;
  j["status_error"] = state_.statusIsError;
  j["modal"] = files_.modalOpen();
  const RenderStats& s = state_.previewStats;
  j["preview"] = {{"samples", s.samples},
                  {"generation", s.generation},
                  {"done", s.done},
                  {"paused", s.paused},
                  {"kept_camera", s.keptCamera},
                  {"restarts", preview_.restarts()},
                  {"hit_pixels", preview_.image().hitPixels},
                  {"image_generation", preview_.image().generation},
                  {"device", state_.previewDevice}};
  nlohmann::json rects = nlohmann::json::object();
  for (const auto& [name, r] : state_.probe.rects) rects[name] = {r.x, r.y, r.z, r.w};
  j["rects"] = rects;
  j["preview_modes"] = preview_.modes().probeJson();
  j["export"] = export_.probeJson();
  j["render_animation"] = animation_.probeJson();
  j["combine"] = combine_.probeJson();
  j["explore"] = explore_.probeJson();
  j["construction"] = constructionTree_.probeJson(state_);
  const Project& project = state_.document.project();
  j["live"] = live_.probeJson();
  j["live"]["learning"] = state_.learnPath;
  j["live"]["sound_output"] = state_.soundOutput ? state_.soundOutput->driver() : state_.soundOutputProblem;
  j["live"]["bindings"] = nlohmann::json::array();
  for (const Binding& b : state_.document.project().bindings)
    j["live"]["bindings"].push_back({{"path", b.path}, {"source", b.source}, {"min", b.min}, {"max", b.max}});
  j["camera"] = {{"projection", projectionName(project.camera.projection)},
                 {"fov", project.camera.fov},
                 {"yaw", project.camera.yaw},
                 {"lens_blur", project.camera.lens_blur},
                 {"stereo", project.camera.stereo.has_value()}};
  nlohmann::json tracks = nlohmann::json::object();
  for (const auto& [path, track] : project.tracks) {
    nlohmann::json keys = nlohmann::json::array();
    for (const Keyframe& k : track.keys) keys.push_back({k.t, k.v});
    tracks[path] = keys;
  }
  const AnimationSettings timeline = timelineOf(project);
  j["timeline"] = {{"time", project.time},
                   {"playing", state_.playback.playing},
                   {"fps", timeline.fps},
                   {"start", timeline.start},
                   {"end", timeline.end},
                   {"loop", timeline.loop},
                   {"has_animation", project.animation.has_value()},
                   {"tracks", tracks}};
  // Node positions in the Top view (window coordinates), so a test can press on a real node.
  nlohmann::json nodes = nlohmann::json::array();
  for (const glm::dvec2& p : views_[0].screenNodes(state_)) nodes.push_back({p.x, p.y});
  j["nodes_top"] = nodes;
  nlohmann::json ifsNodes = nlohmann::json::array();
  for (const glm::dvec2& p : ifsView_.screenNodes(state_)) ifsNodes.push_back({p.x, p.y});
  j["nodes_ifs"] = ifsNodes;
  try {
    writeFileAtomically(options_.probe, j.dump(1));
  } catch (const IoError&) {
    // A probe for tests only: a failed write leaves the last probe, which the test then reads.
  }
}

bool ModellerApp::startSession() {
  if (const std::string error = preview_.useDevice(options_.device); !error.empty()) {
    std::fprintf(stderr, "gridifs: %s\n", error.c_str());
    return false;
  }
  renderer_ = std::make_unique<ViewRenderer>();
  // Installed before ImGui's callbacks are chained to it (see runModeller): record presses.
  glfwSetWindowUserPointer(window_, &state_);
  files_.checkForRecovery();
  // Live input's threads wake the event loop, which waits while nothing moves.
  live_.setWake([] { glfwPostEmptyEvent(); });
  if (options_.oscPort > 0) {
    if (const std::string error = live_.listen(options_.oscPort, [] { glfwPostEmptyEvent(); }); !error.empty())
      state_.error(error);
  }
  if (options_.midi) {
    if (const std::string error = live_.openMidi([] { glfwPostEmptyEvent(); }); !error.empty()) state_.error(error);
  }
  if (!options_.file.empty())
    files_.openAtStartup(options_.file);
  else
    files_.openStartProject();  // something alive, never a one-dot preview
  state_.clampIndices();
  return true;
}

void ModellerApp::pollEvents(bool capture) {
  // Idle windows wait for input (redraw on demand); a filling preview, a drag or a capture keeps
  // the loop animating.
  const bool animate = capture || state_.playback.playing || animation_.running() || preview_.busy() ||
                       explore_.busy() || export_.running() || quietFrames_ < 3 || ImGui::IsAnyMouseDown();
  if (animate) {
    glfwPollEvents();
  } else {
    const double before = glfwGetTime();
    glfwWaitEventsTimeout(0.5);
    if (glfwGetTime() - before < 0.49) quietFrames_ = 0;
  }
  ++quietFrames_;
  if (ImGui::GetIO().MouseDelta.x != 0.0f || ImGui::GetIO().MouseDelta.y != 0.0f) quietFrames_ = 0;
  if (glfwWindowShouldClose(window_)) {
    glfwSetWindowShouldClose(window_, GLFW_FALSE);
    files_.requestQuit();
    quietFrames_ = 0;
  }
}

void ModellerApp::buildFrame(FrameTimes& t) {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  state_.contextHelp.clear();
  state_.probe.rects.clear();
  for (GridView& v : views_) v.hide();
  ifsView_.hide();
  preview_.hide();
  t.ui = Clock::now();
  buildUi();
  ImGui::Render();
  t.uiDone = Clock::now();
}

void ModellerApp::applyEdits() {
  const bool hadEdits = !edits_.empty();
  if (const std::string error = edits_.apply(state_.document); !error.empty()) state_.error(error);
  // Live input after the frame's edits, so that a gesture in progress is not cut by it.
  const bool live = !state_.document.inGesture() && live_.applyInput(state_);
  state_.clampIndices();
  if (hadEdits || live) quietFrames_ = 0;
}

void ModellerApp::renderViews(FrameTimes& t) {
  t.views = Clock::now();
  for (GridView& v : views_) v.render(state_, *renderer_);
  if (options_.stats) glFinish();
  t.ifsView = Clock::now();
  ifsView_.render(state_, *renderer_);
  if (options_.stats) glFinish();
  t.preview = Clock::now();
  preview_.render(state_, *renderer_);
  live_.previewRestarted();  // the preview has taken this frame's project
  if (options_.stats) glFinish();
  t.viewsDone = Clock::now();
  if (options_.stats) {
    phaseMs_[0] += milliseconds(t.start, t.views);
    phaseMs_[1] += milliseconds(t.views, t.ifsView);
    phaseMs_[2] += milliseconds(t.ifsView, t.preview);
    phaseMs_[3] += milliseconds(t.preview, t.viewsDone);
  }
}

void ModellerApp::present(int fbw, int fbh) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, fbw, fbh);
  glClearColor(0.08f, 0.085f, 0.095f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  const auto t4 = Clock::now();
  for (const GridView& v : views_) v.present(fbh);
  ifsView_.present(fbh);
  preview_.present(fbh);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  if (options_.stats) {
    glFinish();
    phaseMs_[4] += milliseconds(t4, Clock::now());
  }
}

double ModellerApp::finishFrame(FrameTimes& t) {
  const std::string title = files_.windowTitle();
  if (title != title_) {
    title_ = title;
    glfwSetWindowTitle(window_, title_.c_str());
  }
  t.tick = Clock::now();
  files_.tick();
  t.ticked = Clock::now();
  ++frame_;
  glFinish();
  t.finished = Clock::now();
  const double frameMs = milliseconds(t.start, t.finished);
  if (frame_ > 5 && frameMs > slowestFrameMs_) {
    slowestFramePhases_ = {
        {"poll_and_window", milliseconds(t.start, t.ui)},   {"build_ui", milliseconds(t.ui, t.uiDone)},
        {"apply_edits", milliseconds(t.uiDone, t.applied)}, {"publish", milliseconds(t.applied, t.views)},
        {"views", milliseconds(t.views, t.viewsDone)},      {"present", milliseconds(t.viewsDone, t.tick)},
        {"files_tick", milliseconds(t.tick, t.ticked)},     {"gl_finish", milliseconds(t.ticked, t.finished)}};
  }
  if (frame_ > 5) {
    slowestFrameMs_ = std::max(slowestFrameMs_, frameMs);
    if (options_.stats) frameMs_.push_back(frameMs);  // kept only for the --stats summary
  }
  return frameMs;
}

bool ModellerApp::captureReady() const {
  return frame_ >= options_.frames &&
         (state_.previewStats.samples >= options_.waitPoints || state_.previewStats.done || state_.now > 60.0);
}

void ModellerApp::endSession(bool capture) {
  writeProbe(0.0);
  // A capture is not a session: it leaves the artist's window where it was.
  if (!capture) appWindow_.save(int(ImGui::GetMainViewport()->Size.x), int(ImGui::GetMainViewport()->Size.y));
  files_.shutdown();
  if (options_.stats && !frameMs_.empty()) {
    std::vector<double> sorted = frameMs_;
    std::sort(sorted.begin(), sorted.end());
    const double mean = std::accumulate(sorted.begin(), sorted.end(), 0.0) / double(sorted.size());
    std::fprintf(stderr, "gridifs: %zu frames, frame time mean %.2f ms, median %.2f ms, p95 %.2f ms, max %.2f ms\n",
                 sorted.size(), mean, sorted[sorted.size() / 2], sorted[sorted.size() * 95 / 100], sorted.back());
    const double n = double(frame_);
    std::fprintf(
        stderr,
        "gridifs: per frame: UI %.2f ms, grid views %.2f ms, IFS view %.2f ms, preview %.2f ms, ImGui %.2f ms\n",
        phaseMs_[0] / n, phaseMs_[1] / n, phaseMs_[2] / n, phaseMs_[3] / n, phaseMs_[4] / n);
  }
}

int ModellerApp::run() {
  if (!startSession()) return 1;
  const bool capture = !options_.screenshot.empty();
  if (capture) startLoadingImageWriter();  // on a helper thread, while the picture fills
  const Clock::time_point start = Clock::now();
  int exitCode = 0;
  for (;;) {
    // 1. Poll.
    pollEvents(capture);
    FrameTimes t;
    t.start = Clock::now();
    state_.now = std::chrono::duration<double>(t.start - start).count();
    appWindow_.track();
    followContentScale();
    advancePlayback(state_);

    // 2. Build the UI; widgets collect edits.
    buildFrame(t);

    // 3. Apply the edits to the one Document.
    applyEdits();
    t.applied = Clock::now();

    // 4. Publish a new renderer snapshot when the document changed.
    preview_.publish(state_);

    // 5. Draw the views into their textures.
    renderViews(t);

    // 6. ImGui on top.
    int fbw = 0, fbh = 0;
    glfwGetFramebufferSize(window_, &fbw, &fbh);
    present(fbw, fbh);
    const double frameMs = finishFrame(t);

    if (capture && captureReady()) {
      if (const std::string error = writeFramebuffer(options_.screenshot, fbw, fbh); !error.empty()) {
        std::cerr << "gridifs: " << error << "\n";
        exitCode = 1;
      }
      writeProbe(frameMs);
      break;
    }
    glfwSwapBuffers(window_);
    // After the swap: a test that reads "done" from the probe then finds that frame on screen.
    writeProbe(frameMs);
    if (files_.quitConfirmed()) break;
  }
  endSession(capture);
  return exitCode;
}

/// The ImGui context and the modeller in an open window; returns the exit code.
int runInWindow(AppWindow& appWindow, const ModellerOptions& options) {
  GLFWwindow* window = appWindow.window();
  glfwMakeContextCurrent(window);
  glfwSwapInterval(options.screenshot.empty() ? 1 : 0);
  // HiDPI: the monitor's content scale sizes the fonts and the style (and follows the window to
  // another monitor, see followContentScale); --ui-scale overrides it.
  const float scale = options.uiScale > 0.0f ? options.uiScale : std::clamp(appWindow.contentScale(), 1.0f, 4.0f);

  // Our key callback first; ImGui_ImplGlfw_InitForOpenGL chains it.
  glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int mods) {
    if (action != GLFW_PRESS) return;
    if (auto* state = static_cast<ModellerState*>(glfwGetWindowUserPointer(w)))
      state->keyPresses.push_back({key, mods});
  });
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  applyTheme(scale);
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
  int code = 0;
  try {
    ModellerApp app(appWindow, options, scale);
    code = app.run();
  } catch (const std::exception& e) {
    std::cerr << "gridifs: the modeller stopped: " << e.what() << "\n";
    code = 1;
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  return code;
}

}  // namespace

int runModeller(const std::string& file, int argc, char** argv) {
  ModellerOptions options;
  options.file = file;
  if (const auto error = parseModellerOptions(argc, argv, options)) {
    std::cerr << "gridifs: " << *error << ".\n";
    return 2;
  }
  glfwSetErrorCallback([](int, const char* description) { std::cerr << "gridifs: GLFW: " << description << "\n"; });
  if (!glfwInit()) {
    std::cerr << "gridifs: cannot open the modeller window (no display?); use a verb such as 'gridifs render'.\n";
    return 1;
  }
  int code = 1;
  {
    AppWindow appWindow(options, AppFolders::fromEnvironment().config / "window.json");
    if (appWindow.window())
      code = runInWindow(appWindow, options);
    else
      std::cerr << "gridifs: cannot create an OpenGL 3.3 window.\n";
  }
  glfwTerminate();
  return code;
}

}  // namespace gridifs::ui
