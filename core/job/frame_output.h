#pragma once
// The frame step every image render shares: a frame's time samples prepared, their accumulations
// merged into one image (motion blur, Draves & Reckase 2003, §9), and the image developed and
// written with every output its display mode has. `gridifs render`, `gridifs merge`, the farm and
// File › Render animation… all go through here, so the same project and options write the same
// bytes whichever of them ran it.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "job/prepared_render.h"
#include "render/accumulation.h"

namespace gridifs {

/// One time sample of a frame: the project at that time, compiled, with the share of the frame's
/// samples and the seed this sample renders.
struct TimeSample {
  PreparedRender render;  // render.job carries this sample's samples and seed
  double time = 0.0;
};

/// The time samples of the frame at options.time (or the project's own time): `blur` times spread
/// evenly over `shutter` seconds centred on it, each prepared with its own camera and tracks, the
/// frame's samples shared among them and seed + i for the i-th. One sample is the frame's own
/// time exactly, so an unblurred frame is a render at that time. Throws RenderJobError.
std::vector<TimeSample> prepareTimeSamples(const Project& project, const RenderJobOptions& options, int blur,
                                           double shutter);

/// The share of `samples` that time sample `i` of `count` renders (the first ones take the rest).
std::int64_t timeSampleShare(std::int64_t samples, std::int64_t i, std::int64_t count);

/// The time samples' buffers developed with `display` and added into one image, the earlier ones
/// dimmer with a motion fade (render/motion_blur.h).
RenderImage mergeTimeSamples(const std::vector<Accumulation>& samples, const DisplaySettings& display,
                             double motionFade);

/// Renders every time sample on the CPU (`progress` gets the fraction of the whole frame; false
/// cancels with RenderCancelled) and merges them.
RenderImage renderTimeSamples(const std::vector<TimeSample>& samples, double motionFade,
                              const std::function<bool(double)>& progress);

/// Where a frame goes and how its flame display is stored.
struct FrameOutput {
  std::filesystem::path file;  // .png, .tif/.tiff or .exr
  /// What the image is a render of (the project's file name), in its description.
  std::string source;
  /// Flame display: bits per channel, 8 or 16 for PNG and TIFF, 16 (half) or 32 (float) for EXR;
  /// 0: 8 or 32.
  int bitDepth = 0;
  /// Flame display: PNG/TIFF with alpha instead of the background (an EXR always has alpha).
  bool transparent = false;
};

/// The bits per channel `out` is written with (FrameOutput::bitDepth's default resolved).
int frameBitDepth(const FrameOutput& out);

/// Writes `image`, rendered from `project` in its display mode, atomically (a temporary file
/// renamed over out.file):
/// - z-buffer: PNG/TIFF 8-bit RGB over the background; EXR float R G B A (linear, premultiplied,
///   A = coverage), Z (view depth), P.x P.y P.z (the world position each pixel's centre sees)
///   and the camera's OpenEXR matrices;
/// - flame (Draves & Reckase 2003, §4–8): tone mapped at output's size; PNG/TIFF RGB (RGBA when
///   transparent), EXR premultiplied RGBA with the camera's matrices;
/// - shaded: the lights developed (render/shaded_image.h); EXR adds N.x N.y N.z, AO, shadow and P.
/// `output` is the output image's job and `rendered` the renderer's (a flame's is supersampled).
/// Throws IoError when the file cannot be written, ModelError (or std::invalid_argument from the
/// flame's develop) when the project cannot develop the image.
void writeFrame(const RenderImage& image, const Project& project, const RenderJob& output, const RenderJob& rendered,
                const FrameOutput& out);

}  // namespace gridifs
