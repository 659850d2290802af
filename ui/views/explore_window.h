#pragma once
// View › Explore (E): a grid of live thumbnails of variants of the open project, the way
// Apophysis's mutation window and Chaotica's random worlds let artists find forms. Mutate draws
// children of the document (core/explore: numbers within their ranges scaled by the strength,
// operations, functions, colours, variations), Random draws new worlds of a style, Breed draws
// children of the pinned variants; what the keep boxes name stays as it is. The thumbnails fill
// progressively on background threads while the main preview keeps running; a click adopts one
// as one undo step. Generations are kept, so Back and Forward walk through them.
#include <GLFW/glfw3.h>

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "explore/explore.h"
#include "explore/thumbnail.h"
#include "ui/base/edit_queue.h"
#include "ui/base/modeller_state.h"
#include "ui/gl/gl_resources.h"

namespace gridifs::ui {

class ExploreWindow {
 public:
  static constexpr int kThumbnailWidth = 192, kThumbnailHeight = 144;
  static constexpr std::int64_t kThumbnailSamples = 1'000'000;

  ExploreWindow();
  ~ExploreWindow();
  ExploreWindow(const ExploreWindow&) = delete;
  ExploreWindow& operator=(const ExploreWindow&) = delete;

  /// Opens when state.showExplore is set (View menu, E); call every frame at top level.
  void draw(ModellerState& state, EditQueue& edits);
  /// Whether thumbnails are still being made (the UI keeps animating while they are).
  bool busy() const;
  nlohmann::json probeJson() const;

  /// Starts a generation of random worlds of the chosen style (File › New random world).
  void startRandom(ModellerState& state);

 private:
  enum class Kind { Mutate, Random, Breed };
  /// One variant: drawn and rendered on a worker, shown once ready.
  struct Slot {
    Project project;
    Thumbnail thumbnail;
    bool ready = false;
    std::string error;  // why none could be drawn
    bool pinned = false;
    bool uploaded = false;
    std::unique_ptr<StreamTexture> texture;
  };
  struct Generation {
    Kind kind = Kind::Mutate;
    std::uint64_t seed = 1;
    // The controls as they were when it started (the workers read these, not the controls).
    double strength = 0.5;
    ExploreKeep keep;
    ExploreStyle style = ExploreStyle::Grid;
    bool gpu = false;  // thumbnails on the GPU compute renderer (the preview renders there too)
    std::vector<Project> parents;
    std::vector<std::string> parentNames;  // for the lineage: the file, or a variant of a generation
    std::vector<Slot> slots;
  };
  struct Task {
    std::uint64_t serial;  // the generation it belongs to (stale tasks are skipped)
    std::size_t slot;
  };

  void start(Kind kind, ModellerState& state);
  void work();
  /// Draws and renders slot `index` of the generation with `serial` (runs on a worker, with the
  /// worker's own GPU renderer, opened on first use when the generation asks for the GPU).
  void fill(std::uint64_t serial, std::size_t index, std::unique_ptr<Renderer>& gpuRenderer);
  void adopt(ModellerState& state, EditQueue& edits, std::size_t index);
  void drawControls(ModellerState& state);
  /// Draws the current generation's thumbnails (with mutex_ held); returns the one clicked.
  std::optional<std::size_t> drawGrid(ModellerState& state);
  std::size_t pinnedCount() const;

  bool open_ = false;
  float strength_ = 0.5f;
  ExploreKeep keep_;
  int style_ = 0;
  int count_ = 9;
  std::uint64_t nextSeed_ = 1;

  // Generations, newest last; current_ is the one shown. Guarded by mutex_ (the workers fill
  // slots in place).
  mutable std::mutex mutex_;
  std::vector<std::unique_ptr<Generation>> generations_;
  std::size_t current_ = 0;
  std::uint64_t serial_ = 0;  // of the newest generation
  std::deque<Task> tasks_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::vector<std::thread> workers_;
  std::atomic<int> running_{0};
  std::filesystem::path folder_;      // the document's folder, for relative set and palette files
  std::atomic<bool> usedGpu_{false};  // a thumbnail of the current generation came from the GPU
};

}  // namespace gridifs::ui
