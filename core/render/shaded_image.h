#pragma once
// The shaded display: develops a renderer snapshot (the camera's z-buffer with the structural
// colour of the nearest point, plus one light-depth buffer per shadowed light) into a lit image.
// Everything here runs after the chaos game, so changing a light's colour or intensity, the
// ambient or specular term, the occlusion or the fog needs no re-render.
//
// Per pixel: the view-space position from the depth after an edge-aware smoothing (neighbours
// across a depth discontinuity are left out, so single-point speckle does not become noise), the
// normal from the cross product of screen-space position differences (the side with the smaller
// depth step, so edges keep their silhouettes), Lambert diffuse plus a Blinn-Phong specular term
// for each directional light (Blinn 1977), the structural colour as albedo, horizon-based
// ambient occlusion (Bavoil, Sainz & Dimitrov 2008), a percentage-closer filtered shadow lookup
// (Reeves, Salesin & Cook 1987) and exponential distance fog.
//
// Thread-safety: pure function of its arguments; runs on up to `threads` oneTBB threads.
#include <array>
#include <cstdint>
#include <vector>

#include "model/project.h"
#include "render/chaos_renderer.h"

namespace gridifs {

struct ShadedImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // display (sRGB) colour over the background; alpha 255 where a point was plotted
  std::vector<float> linear;       // 4 per pixel: linear-light RGB premultiplied by A, A = coverage (EXR)
  std::vector<float> normals;      // 3 per pixel: world-space unit normal; 0 where empty
  std::vector<float> occlusion;    // ambient light that reaches the pixel: 1 open, 0 fully occluded; 1 where empty
  std::vector<float> shadow;  // light visibility over the shadowed lights, weighted by intensity: 1 lit, 0 in shadow

  /// developShaded's working buffers, kept between calls so that re-developing the same size
  /// (a light or occlusion slider) allocates and clears nothing.
  struct Workspace {
    std::vector<float> horizontal, smooth;          // depth after each smoothing pass
    std::vector<std::array<float, 3>> viewNormals;  // per pixel, view space
    std::vector<float> blockAo, blockDepth;         // occlusion per 2×2 block
  } workspace;
};

/// What developShaded writes: the display colour only (rgba; the preview, where each light or
/// occlusion slider step re-develops), or also the compositing channels (linear, normals,
/// occlusion, shadow: EXR output).
enum class ShadedChannels { Display, All };

/// Develops `snapshot` (taken with depth cue 0, so that rgba holds the structural colour; see
/// shadedDisplaySettings) for `camera` into `out`. Light depth buffers in the snapshot are used for
/// the lights with shadows, in order; a shadowed light without a buffer is unshadowed. Throws
/// ModelError when the camera is unusable. With ShadedChannels::Display the compositing channels
/// are left empty.
void developShaded(const RenderImage& snapshot, const ShadingSettings& settings, const Camera& camera,
                   const Vec3& background, int threads, ShadedImage& out,
                   ShadedChannels channels = ShadedChannels::All);

/// The display settings a shaded snapshot must be taken with: the background, no depth cueing.
DisplaySettings shadedDisplaySettings(const Project& project);

/// The shadow map size for an image: half its longer side, between 256 and 2048 texels.
int shadowMapSize(int width, int height);

/// Adds the shaded display's chaos-game inputs to `job`: one light view per light with shadows
/// (over attractorBounds(ifs)) and the depth-of-field lens. Throws ModelError for a zero light
/// direction.
RenderJob shadedRenderJob(const RenderJob& job, const ShadingSettings& settings, const CompiledIfs& ifs);

}  // namespace gridifs
