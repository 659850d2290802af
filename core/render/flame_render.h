#pragma once
// The flame display over the chaos game (Draves & Reckase 2003, §4–8): how a renderer snapshot
// (per-pixel color sums and hit counts, at supersample× the output size) becomes a flame image,
// and how that image is written. Used by `gridifs render --mode flame` and by the GUI preview.
//
// Thread-safety: pure functions of their arguments. Throws as documented per function.
#include <filesystem>

#include "base/errors.h"
#include "render/chaos_renderer.h"
#include "tone/flame_tonemap.h"
#include "tone/palette.h"

namespace gridifs {

/// Output pixels per unit of the image plane at the camera target (OrbitCamera: the view's half
/// height there is distance·tan(fov/2), for perspective and orthographic cameras alike). This
/// is flam3's pixels_per_unit, which fixes the exposure (LogDensityScale::k2).
double flamePixelsPerUnit(const Camera& camera, int outputHeight);

/// The gutter of a flame render in output pixels: the density estimator and the spatial filter
/// reach this far, so the renderer also fills a band this wide around the frame (as flam3 does)
/// and the frame's edges get their neighbours' contributions instead of darkening.
int flameGutter(const FlameSettings& settings);

/// Turns the job of an output image (camera, width × height, samples, ...) into the renderer job
/// of a flame render: (width + 2·gutter) × (height + 2·gutter), supersample× larger, the field of
/// view widened to cover the gutter at the same pixels per unit, color accumulation on and the
/// palette looked up per sample (RenderJob::palette). The gutter is dropped when the widened
/// field of view would exceed 170°, or when `gutter` is false (the GUI preview, whose z-buffer
/// image must stay the frame so that switching modes needs no restart).
RenderJob flameRenderJob(const RenderJob& outputJob, const FlameSettings& settings,
                         std::shared_ptr<const Palette> palette, bool gutter = true);
/// The same from the project's render settings.
RenderJob flameRenderJob(const Project& project, std::shared_ptr<const Palette> palette, int threads);

/// The flame histogram held by a renderer snapshot made with accumulateColor. Channels 0..2 of
/// colorSums are summed palette colors when the job had a palette; when `meanCPalette` is given
/// instead, each pixel gets hits × palette(mean c), an approximation for snapshots without
/// per-sample palette colors. Throws std::invalid_argument when the snapshot has no color sums.
FlameHistogram flameHistogramFromSnapshot(const RenderImage& snapshot, const Palette* meanCPalette = nullptr);

/// Develops a snapshot of flameRenderJob(...) into the flame image of `outputWidth` ×
/// `outputHeight` (`camera` is the output's camera, not the widened one): develops the whole
/// supersampled histogram with its gutter (whatever the job had: told from the snapshot's size) and
/// keeps the centre. The exposure uses snapshot.stats.samples. Throws std::invalid_argument when
/// the snapshot's size matches neither.
FlameImage developFlameSnapshot(const RenderImage& snapshot, const FlameSettings& settings, const Camera& camera,
                                int outputWidth, int outputHeight, const Vec3& background, bool transparent,
                                int threads = 1, const Palette* meanCPalette = nullptr);

/// 8-bit RGBA for a texture upload (GUI preview): channels × 255, rounded; the rgb of a transparent
/// image stays premultiplied. `out` is resized to width·height·4.
void flameImageToRgba8(const FlameImage& image, std::vector<std::uint8_t>& out);

/// Writes a flame image through OpenImageIO: PNG/TIFF with 8 or 16 bits per channel, EXR as
/// half or float (bitDepth 16 or 32), converted from the display (sRGB) values to linear light as
/// EXR expects. RGBA (premultiplied in memory; OIIO stores PNG unassociated) when `withAlpha`,
/// else RGB. Atomic: a temporary file in the same folder is
/// renamed over `file`. Throws IoError when the format is unknown or the file cannot be written.
/// An EXR carries `camera`'s matrices (render/camera.h: exrCameraMatrices) when one is given.
void writeFlameImage(const FlameImage& image, const std::filesystem::path& file, int bitDepth, bool withAlpha,
                     const Camera* camera = nullptr);

}  // namespace gridifs
