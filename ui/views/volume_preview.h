#pragma once
// The volume preview mode: the measure attractor (Sokolov & Gentil, §3.4) computed at a preview
// resolution on a worker thread and ray-marched as a 3D texture with emission and absorption,
// lit by one directional light with self-shadowing. The worker publishes the partial volume now
// and then while the iteration runs, so the picture fills progressively; an edit of the
// functions (or a new time that changes them) cancels it and starts again. A second job
// recomputes the shadow of the newest volume when the light turns. The UI thread only uploads
// and draws.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/background_job.h"
#include "edit/document.h"
#include "flame/palette.h"
#include "render/camera.h"
#include "ui/gl/gl_resources.h"

namespace gridifs::ui {

/// The preview resolutions offered (capped at the project's volume resolution).
inline constexpr int kVolumePreviewResolutions[] = {32, 48, 64, 96, 128, 192, 256};

/// What the volume mode shows, besides the project: view settings of the modeller, not saved.
struct VolumeView {
  int resolution = 64;         // N of the preview's N³ volume
  float densityScale = 24.0f;  // extinction per world unit at density 1
};

class VolumePreview {
 public:
  VolumePreview();
  ~VolumePreview();  // cancels and joins the worker
  VolumePreview(const VolumePreview&) = delete;
  VolumePreview& operator=(const VolumePreview&) = delete;

  VolumeView view;

  /// UI thread, every frame in volume mode: restarts the worker when the geometry revision, the
  /// volume settings or the resolution changed, and hands it the light direction. Never waits.
  void update(const Document& document, int threads);
  /// UI thread, when the preview leaves the volume mode: stops a computation under way (the chaos
  /// game gets the cores back); the next update() starts it again. A finished volume is kept.
  void suspend();
  /// UI thread with the GL context: uploads the newest published volume; true when there was one.
  bool upload();
  /// Ray-marches the current volume into `target` with the project camera over `background`.
  void draw(const RenderTarget& target, const Project& project);

  /// The light the volume is lit by (towards the light): the key light of the shading settings.
  static Vec3 lightDirection(const Project& project);
  /// The resolution the preview computes at: the artist's choice within the project's volume resolution.
  static int effectiveResolution(const Project& project, int requested);

  bool computing() const { return compute_.busy(); }
  /// Work done and to do in the current computation: set iterations, or chaos-game points.
  std::int64_t done() const { return compute_.progress().done; }
  std::int64_t total() const { return compute_.progress().total; }
  bool setIteration() const { return setIteration_; }
  int resolution() const { return shownResolution_; }
  std::uint64_t restarts() const { return restarts_; }
  std::uint64_t uploads() const { return uploads_; }
  /// Whether the volume on screen is the finished one of the current request.
  bool finished() const { return shownFinal_ && !computing(); }
  /// Why nothing can be shown ("" when all is well): a set that fails to voxelize, too little memory.
  const std::string& error() const { return error_; }

 private:
  struct Request {
    Project project;
    std::filesystem::path folder;
    int resolution = 64;
    int threads = 1;
    Vec3 light{0.0};  // what the published frames are shadowed for
  };
  struct Frame {
    int n = 0;
    std::vector<float> density, color, lightDepth;  // color: empty, or 3 per voxel
    Vec3 light{0.0};                                // the light of lightDepth
    bool final = false;
    std::string error;
  };
  using FramePtr = std::shared_ptr<const Frame>;
  struct Relight {
    FramePtr source;  // a computed frame
    Vec3 light{0.0};
    int threads = 1;
  };
  struct Relit {
    FramePtr source, frame;
  };
  using ComputeJob = BackgroundJob<Request, FramePtr>;
  using RelightJob = BackgroundJob<Relight, Relit>;
  /// Worker threads.
  static void compute(const Request& request, ComputeJob::Context& context);
  /// Normalises `counts` (and colour sums) and publishes them with their shadow.
  static void publish(const Request& request, ComputeJob::Context& context, const std::vector<float>& counts,
                      const std::vector<float>& colorSums, bool final);
  static void relight(const Relight& relight, RelightJob::Context& context);
  /// UI thread: shadows the newest computed frame for light_ (on the relight job).
  void relightSource();
  void uploadFrame(const Frame& frame);

  // UI-thread state.
  std::uint64_t geometryRevision_ = 0;
  std::optional<VolumeSettings> volumeSettings_;
  int requestedResolution_ = 0;
  bool haveRequest_ = false;
  Vec3 light_{0.0};
  std::string error_;
  std::uint64_t restarts_ = 0, uploads_ = 0;
  int shownResolution_ = 0;
  bool shownFinal_ = false;
  bool setIteration_ = true;
  bool hasColor_ = false;
  std::string paletteRef_;
  std::filesystem::path paletteFolder_;
  FramePtr source_;  // the newest computed frame taken (what a relight starts from)
  int threads_ = 1;  // the threads of the last request (a relight uses as many)

  // GL.
  std::optional<ShaderProgram> program_;
  GLuint density_ = 0, color_ = 0, lightDepth_ = 0, palette_ = 0, vao_ = 0;

  // Last: destroyed first, they stop and join their workers before the rest goes.
  ComputeJob compute_{&VolumePreview::compute};
  RelightJob relight_{&VolumePreview::relight};
};

}  // namespace gridifs::ui
