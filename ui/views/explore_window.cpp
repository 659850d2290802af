#include "ui/views/explore_window.h"

#include <imgui.h>

#include <algorithm>

#include "base/errors.h"
#if GRIDIFS_HAVE_GPU
#include "gpu/render_device.h"
#endif

namespace gridifs::ui {
namespace {

constexpr const char* kStyleNames[] = {"Grid", "Flame", "Free-form", "Volume"};
constexpr ExploreStyle kStyles[] = {ExploreStyle::Grid, ExploreStyle::Flame, ExploreStyle::FreeForm,
                                    ExploreStyle::Volume};
constexpr std::size_t kMaxGenerations = 32;  // Back reaches this far; older ones are dropped

}  // namespace

ExploreWindow::ExploreWindow() : nextSeed_(clockSeed()) {}

ExploreWindow::~ExploreWindow() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
    tasks_.clear();
  }
  wake_.notify_all();
  for (std::thread& t : workers_) t.join();
}

bool ExploreWindow::busy() const {
  const std::lock_guard lock(mutex_);
  if (!tasks_.empty() || running_.load() > 0) return true;
  if (generations_.empty()) return false;
  // Ready thumbnails still to be uploaded keep the window drawing.
  for (const Slot& s : generations_[current_]->slots)
    if (s.ready && !s.uploaded && !s.thumbnail.rgba.empty()) return true;
  return false;
}

std::size_t ExploreWindow::pinnedCount() const {
  const std::lock_guard lock(mutex_);
  if (generations_.empty()) return 0;
  std::size_t n = 0;
  for (const Slot& s : generations_[current_]->slots) n += s.pinned && s.ready && s.error.empty() ? 1 : 0;
  return n;
}

void ExploreWindow::startRandom(ModellerState& state) {
  open_ = true;
  start(Kind::Random, state);
}

void ExploreWindow::start(Kind kind, ModellerState& state) {
  auto generation = std::make_unique<Generation>();
  generation->kind = kind;
  generation->seed = nextSeed_;
  generation->strength = double(strength_);
  generation->keep = keep_;
  generation->style = kStyles[style_];
  // Where the preview renders on the GPU, so do the thumbnails.
  generation->gpu = state.previewDevice.rfind("gpu", 0) == 0;
  usedGpu_ = false;
  nextSeed_ += std::uint64_t(count_);
  folder_ = state.document.path().empty() ? std::filesystem::path() : state.document.path().parent_path();
  const std::string file =
      state.document.path().empty() ? "untitled.gridifs" : state.document.path().filename().string();
  const std::lock_guard lock(mutex_);
  if (kind == Kind::Mutate) {
    generation->parents = {state.document.project()};
    generation->parentNames = {file};
  }
  if (kind == Kind::Breed && !generations_.empty()) {
    const std::vector<Slot>& slots = generations_[current_]->slots;
    for (std::size_t i = 0; i < slots.size(); ++i)
      if (slots[i].pinned && slots[i].ready && slots[i].error.empty()) {
        generation->parents.push_back(slots[i].project);
        generation->parentNames.push_back(file + ": variant " + std::to_string(i + 1) + " of generation " +
                                          std::to_string(current_ + 1));
      }
  }
  generation->slots.resize(std::size_t(count_));
  // A new generation replaces whatever lies ahead of the one shown (as an edit after undo does).
  if (!generations_.empty()) generations_.resize(current_ + 1);
  generations_.push_back(std::move(generation));
  if (generations_.size() > kMaxGenerations) generations_.erase(generations_.begin());
  current_ = generations_.size() - 1;
  ++serial_;
  tasks_.clear();  // the work for an older generation is no longer wanted
  for (std::size_t i = 0; i < std::size_t(count_); ++i) tasks_.push_back({serial_, i});
  if (workers_.empty()) {
    const unsigned n = std::max(1u, std::thread::hardware_concurrency());
    for (unsigned i = 0; i < n; ++i) workers_.emplace_back([this] { work(); });
  }
  wake_.notify_all();
}

void ExploreWindow::work() {
  std::unique_ptr<Renderer> gpuRenderer;  // this worker's, opened when a generation asks for it
  for (;;) {
    Task task;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [this] { return stopping_ || !tasks_.empty(); });
      if (stopping_) return;
      task = tasks_.front();
      tasks_.pop_front();
      ++running_;
    }
    fill(task.serial, task.slot, gpuRenderer);
    --running_;
  }
}

void ExploreWindow::fill(std::uint64_t serial, std::size_t index, std::unique_ptr<Renderer>& gpuRenderer) {
  Generation work;  // a copy of what the slot needs, so the draw runs without the lock
  {
    const std::lock_guard lock(mutex_);
    if (serial != serial_ || generations_.empty()) return;  // a newer generation took over
    const Generation& g = *generations_.back();
    work.kind = g.kind;
    work.seed = g.seed;
    work.strength = g.strength;
    work.keep = g.keep;
    work.style = g.style;
    work.parents = g.parents;
    work.parentNames = g.parentNames;
    work.gpu = g.gpu;
  }
  const Kind kind = work.kind;
  const std::uint64_t seed = work.seed + index;
  const std::vector<Project>& parents = work.parents;
  Slot result;
  try {
    if (kind == Kind::Random) {
      result.project = randomWorld({work.style, 0, seed}).project;
    } else {
      MutationOptions options;
      options.strength = work.strength;
      options.keep = work.keep;
      options.seed = seed;
      options.folder = folder_;
      std::vector<std::string> names{work.parentNames.front()};
      const Project* parent = &parents.front();
      if (kind == Kind::Breed && parents.size() >= 2) {
        const std::size_t a = index % parents.size(), b = (index + 1) % parents.size();
        parent = &parents[a];
        options.mate = &parents[b];
        names = {work.parentNames[a], work.parentNames[b]};
      }
      result.project = mutateProject(*parent, options, names).project;
    }
    Renderer* renderer = nullptr;
#if GRIDIFS_HAVE_GPU
    if (work.gpu && !gpuRenderer) {
      try {
        gpuRenderer = gpu::openRenderer(gpu::RenderDevice::Gpu).renderer;
      } catch (const std::exception&) {
        // no GPU after all: the CPU renders the thumbnails
      }
    }
    if (work.gpu) renderer = gpuRenderer.get();
#endif
    result.thumbnail = renderThumbnail(result.project, folder_, kThumbnailWidth, kThumbnailHeight, kThumbnailSamples, 1,
                                       nullptr, renderer);
    if (renderer) usedGpu_ = true;
  } catch (const std::exception& e) {
    result.error = e.what();
  }
  const std::lock_guard lock(mutex_);
  for (auto& g : generations_)
    if (g->seed == work.seed && index < g->slots.size() && !g->slots[index].ready) {
      Slot& slot = g->slots[index];
      slot.project = std::move(result.project);
      slot.thumbnail = std::move(result.thumbnail);
      slot.error = std::move(result.error);
      slot.ready = true;
      break;
    }
}

void ExploreWindow::adopt(ModellerState& state, EditQueue& edits, std::size_t index) {
  Project project;
  {
    const std::lock_guard lock(mutex_);
    const Slot& slot = generations_[current_]->slots[index];
    if (!slot.ready || !slot.error.empty()) return;
    project = slot.project;
  }
  const std::size_t functions = project.functions.size();
  edits.commit("Adopt variant", ReplaceProject{std::move(project)});
  state.activeFunction = FunctionRef(0);
  state.activeOp = -1;
  state.info("Adopted variant " + std::to_string(index + 1) + " (" + std::to_string(functions) +
             " functions); Ctrl+Z brings the project back");
}

void ExploreWindow::drawControls(ModellerState& state) {
  if (ImGui::Button("Mutate")) start(Kind::Mutate, state);
  state.probe.item("explore.mutate");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Draw variants of the open project");
  ImGui::SameLine();
  if (ImGui::Button("Random")) start(Kind::Random, state);
  state.probe.item("explore.random");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Draw new worlds of the style on the right");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(110.0f);
  ImGui::Combo("##style", &style_, kStyleNames, int(std::size(kStyleNames)));
  state.probe.item("explore.style");
  ImGui::SameLine();
  const bool canBreed = pinnedCount() >= 2;
  ImGui::BeginDisabled(!canBreed);
  if (ImGui::Button("Breed")) start(Kind::Breed, state);
  ImGui::EndDisabled();
  state.probe.item("explore.breed");
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip(canBreed ? "Draw children of the pinned variants" : "Pin two or more variants to breed them");
  ImGui::SameLine();
  ImGui::BeginDisabled(current_ == 0 || generations_.empty());
  if (ImGui::ArrowButton("##back", ImGuiDir_Left)) --current_;
  ImGui::EndDisabled();
  state.probe.item("explore.back");
  ImGui::SameLine();
  ImGui::BeginDisabled(generations_.empty() || current_ + 1 >= generations_.size());
  if (ImGui::ArrowButton("##forward", ImGuiDir_Right)) ++current_;
  ImGui::EndDisabled();
  state.probe.item("explore.forward");
  ImGui::SameLine();
  if (!generations_.empty()) ImGui::TextDisabled("generation %zu of %zu", current_ + 1, generations_.size());
  ImGui::SetNextItemWidth(200.0f);
  ImGui::SliderFloat("Strength", &strength_, 0.05f, 1.0f, "%.2f");
  state.probe.frame("explore.strength");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("How far a variant may move from its parent");
  ImGui::TextUnformatted("Keep:");
  ImGui::SameLine();
  const struct {
    const char* label;
    bool* value;
  } boxes[] = {{"operations", &keep_.ops},        {"placement", &keep_.placement}, {"colours", &keep_.colors},
               {"variations", &keep_.variations}, {"palette", &keep_.palette},     {"camera", &keep_.camera},
               {"tracks", &keep_.tracks}};
  for (const auto& box : boxes) {
    ImGui::Checkbox(box.label, box.value);
    ImGui::SameLine();
  }
  ImGui::NewLine();
}

std::optional<std::size_t> ExploreWindow::drawGrid(ModellerState& state) {
  if (generations_.empty()) {
    ImGui::TextWrapped(
        "Mutate draws variants of the open project; Random draws new worlds. Click a picture to adopt "
        "it (one undo step), pin favourites and Breed them.");
    return std::nullopt;
  }
  Generation& g = *generations_[current_];
  const int columns = 3;
  std::optional<std::size_t> clicked;
  for (std::size_t i = 0; i < g.slots.size(); ++i) {
    Slot& slot = g.slots[i];
    if (i % std::size_t(columns) != 0) ImGui::SameLine();
    ImGui::BeginGroup();
    ImGui::PushID(int(i));
    const ImVec2 size{float(kThumbnailWidth), float(kThumbnailHeight)};
    if (slot.ready && !slot.thumbnail.rgba.empty()) {
      if (!slot.uploaded) {
        if (!slot.texture) slot.texture = std::make_unique<StreamTexture>();
        slot.texture->upload(slot.thumbnail.width, slot.thumbnail.height, slot.thumbnail.rgba.data());
        slot.uploaded = true;
      }
      if (ImGui::ImageButton(reinterpret_cast<ImTextureID>(std::intptr_t(slot.texture->id())), size, ImVec2(0, 0),
                             ImVec2(1, 1), -1, ImVec4(0.0f, 0.0f, 0.0f, 1.0f)))
        clicked = i;
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("Click to adopt this variant (Ctrl+Z brings the project back)");
    } else {
      ImGui::BeginDisabled();
      ImGui::Button(slot.ready ? "(none worth looking at)" : "drawing...", ImVec2(size.x + 8.0f, size.y + 8.0f));
      ImGui::EndDisabled();
      if (!slot.error.empty() && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("%s", slot.error.c_str());
    }
    state.probe.item("explore.slot" + std::to_string(i));
    ImGui::BeginDisabled(!slot.ready || !slot.error.empty());
    ImGui::Checkbox("pin", &slot.pinned);
    ImGui::EndDisabled();
    state.probe.item("explore.pin" + std::to_string(i));
    ImGui::PopID();
    ImGui::EndGroup();
  }
  return clicked;
}

void ExploreWindow::draw(ModellerState& state, EditQueue& edits) {
  if (state.showExplore) {
    state.showExplore = false;
    open_ = !open_;
    if (open_ && generations_.empty()) start(Kind::Mutate, state);
  }
  if (state.exploreRandom) {
    state.exploreRandom = false;
    startRandom(state);
  }
  if (!open_) return;
  ImGui::SetNextWindowSize(ImVec2(3.0f * (kThumbnailWidth + 16.0f) + 24.0f, 0.0f), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Explore###explore", &open_, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::End();
    return;
  }
  state.probe.window("explore.window");
  drawControls(state);  // takes the lock itself where it reads the slots
  ImGui::Separator();
  std::optional<std::size_t> clicked;
  {
    // The workers fill slots in place: the lock is held while this frame reads them.
    const std::lock_guard lock(mutex_);
    clicked = drawGrid(state);
  }
  if (clicked) adopt(state, edits, *clicked);
  ImGui::End();
}

nlohmann::json ExploreWindow::probeJson() const {
  const std::lock_guard lock(mutex_);
  nlohmann::json j;
  j["open"] = open_;
  j["generations"] = generations_.size();
  j["current"] = current_;
  j["busy"] = !tasks_.empty() || running_.load() > 0;
  j["device"] = usedGpu_.load() ? "gpu" : "cpu";
  nlohmann::json slots = nlohmann::json::array();
  std::size_t ready = 0;
  if (!generations_.empty())
    for (const Slot& s : generations_[current_]->slots) {
      slots.push_back({{"ready", s.ready}, {"pinned", s.pinned}, {"error", s.error}, {"shown", s.uploaded}});
      ready += s.ready ? 1 : 0;
    }
  j["slots"] = slots;
  j["ready"] = ready;
  return j;
}

}  // namespace gridifs::ui
