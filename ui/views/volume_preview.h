#pragma once
// The volume preview mode: the measure attractor (Sokolov & Gentil, §3.4) computed at a preview
// resolution on a worker thread and drawn by the same ray march as `gridifs render --mode volume`
// (render/volume_raymarch.h): emission and absorption, one directional light with
// self-shadowing, or the X-ray display, through the project's transfer function. The worker
// publishes the partial volume now and then while the iteration runs, so the picture fills
// progressively; an edit of the functions (or a new time that changes them) cancels it and starts
// again. A second job classifies the newest volume (transfer function, shadow towards the light)
// and a third ray-marches it for the camera and the view size. The UI thread only uploads the
// finished picture and draws it.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/background_job.h"
#include "edit/document.h"
#include "render/camera.h"
#include "render/volume_raymarch.h"
#include "ui/gl/gl_resources.h"

namespace gridifs::ui {

/// The preview resolutions offered (capped at the project's volume resolution).
inline constexpr int kVolumePreviewResolutions[] = {32, 48, 64, 96, 128, 192, 256};

/// What the volume mode shows, besides the project: view settings of the modeller, not saved.
struct VolumeView {
  int resolution = 64;  // N of the preview's N³ volume
};

class VolumePreview {
 public:
  VolumePreview();
  ~VolumePreview();  // cancels and joins the workers
  VolumePreview(const VolumePreview&) = delete;
  VolumePreview& operator=(const VolumePreview&) = delete;

  VolumeView view;

  /// UI thread, every frame in volume mode: restarts the worker when the geometry revision, the
  /// volume settings or the resolution changed, and reclassifies when the look changed. Never waits.
  void update(const Document& document, int threads);
  /// UI thread, when the preview leaves the volume mode: stops a computation under way (the chaos
  /// game gets the cores back); the next update() starts it again. A finished volume is kept.
  void suspend();
  /// UI thread: takes the newest results of the workers; true when a new picture is in texture().
  bool upload();
  /// UI thread: asks for the picture of the current volume at width × height through the
  /// project's camera (a no-op when that picture is already shown or under way).
  void requestImage(const Project& project, int width, int height);

  GLuint texture() const { return texture_.id(); }
  int imageWidth() const { return texture_.width(); }
  int imageHeight() const { return texture_.height(); }

  /// The light the volume is lit by (towards the light): the key light of the shading settings.
  static Vec3 lightDirection(const Project& project);
  /// The resolution the preview computes at: the artist's choice within the project's volume resolution.
  static int effectiveResolution(const Project& project, int requested);

  bool computing() const { return compute_.busy(); }
  /// Whether any worker is busy (the window keeps polling).
  bool busy() const { return compute_.busy() || classify_.busy() || image_.busy(); }
  /// Work done and to do in the current computation: set iterations, or chaos-game points.
  std::int64_t done() const { return compute_.progress().done; }
  std::int64_t total() const { return compute_.progress().total; }
  bool setIteration() const { return setIteration_; }
  int resolution() const { return shownResolution_; }
  std::uint64_t restarts() const { return restarts_; }
  std::uint64_t uploads() const { return uploads_; }
  std::uint64_t images() const { return images_; }
  /// Whether the volume on screen is the finished one of the current request.
  bool finished() const { return shownFinal_ && !computing(); }
  /// Whether the picture on screen is the ray march of the finished volume with the current look,
  /// camera and size (what `gridifs render --mode volume` makes from the same settings).
  bool pictureFinal() const;
  /// Why nothing can be shown ("" when all is well): a set that fails to voxelize, too little memory.
  const std::string& error() const { return error_; }

 private:
  struct Request {
    Project project;
    std::filesystem::path folder;
    int resolution = 64;
    int threads = 1;
  };
  struct Frame {
    VolumeSource volume;
    bool final = false;
    std::string error;
  };
  using FramePtr = std::shared_ptr<const Frame>;
  struct ClassifyInput {
    FramePtr source;
    VolumeLook look;
    int threads = 1;
  };
  struct Classified {
    FramePtr source;
    VolumeLook look;
    std::shared_ptr<const ClassifiedVolume> volume;
  };
  struct ImageInput {
    Classified classified;
    VolumeLook look;
    Camera camera;
    int width = 1, height = 1, threads = 1;
    bool operator==(const ImageInput& o) const {
      return classified.volume == o.classified.volume && look == o.look && camera == o.camera && width == o.width &&
             height == o.height;
    }
  };
  struct Picture {
    ImageInput input;
    std::vector<std::uint8_t> rgba;
  };
  using ComputeJob = BackgroundJob<Request, FramePtr>;
  using ClassifyJob = BackgroundJob<ClassifyInput, Classified>;
  using ImageJob = BackgroundJob<ImageInput, Picture>;
  /// Worker threads.
  static void compute(const Request& request, ComputeJob::Context& context);
  /// Normalises `counts` (and colour sums) and publishes them.
  static void publish(const Request& request, ComputeJob::Context& context, const std::vector<float>& counts,
                      const std::vector<float>& colorSums, bool final);
  static void classify(const ClassifyInput& input, ClassifyJob::Context& context);
  static void march(const ImageInput& input, ImageJob::Context& context);
  /// UI thread: classifies the newest computed frame for look_.
  void classifySource();
  /// The project's look with its palette (resolved again only when the reference changes).
  VolumeLook lookOf(const Project& project);

  // UI-thread state.
  std::uint64_t geometryRevision_ = 0;
  std::optional<VolumeSettings> volumeSettings_;
  int requestedResolution_ = 0;
  bool haveRequest_ = false;
  VolumeLook look_;
  bool haveLook_ = false;
  std::string error_;
  std::uint64_t restarts_ = 0, uploads_ = 0, images_ = 0;
  int shownResolution_ = 0;
  bool shownFinal_ = false;
  bool setIteration_ = true;
  std::string paletteRef_;
  std::vector<float> palette_;
  std::filesystem::path paletteFolder_;
  FramePtr source_;                         // the newest computed frame taken (what a classification starts from)
  std::optional<Classified> classified_;    // the newest classification of source_
  std::optional<ImageInput> imageRequest_;  // the picture last asked for
  bool imageCurrent_ = false;               // texture_ holds the picture of imageRequest_
  int threads_ = 1;                         // the threads of the last request
  StreamTexture texture_;

  // Last: destroyed first, they stop and join their workers before the rest goes.
  ComputeJob compute_{&VolumePreview::compute};
  ClassifyJob classify_{&VolumePreview::classify};
  ImageJob image_{&VolumePreview::march};
};

}  // namespace gridifs::ui
