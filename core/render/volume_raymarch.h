#pragma once
// The volume ray march behind `gridifs render --mode volume` and the modeller's Volume preview —
// one code path, so the two make the same picture from the same settings. A density volume
// (Sokolov & Gentil, §3.4: the measure attractor, P / max P) is drawn with emission and
// absorption (Beer–Lambert) lit by one directional light with self-shadowing, or as an X-ray
// (grey summed density, the look of Sokolov & Gentil's figures 9–12).
//
// Three stages, so that an interactive view redoes only what changed:
//  1. classifyVolume: the transfer function maps density to albedo and opacity, and the optical
//     depth towards the light is precomputed per voxel (changes with the volume, the transfer
//     function, the palette or the light direction);
//  2. shadeVolume: per voxel emission (albedo lit through its shadow) and extinction for a density
//     scale, light colour and display;
//  3. marchVolume: one ray per pixel through the camera, front to back, skipping empty blocks.
// renderVolumeImage runs all three. Pure functions: thread-safe; they throw ModelError only for
// a camera that cannot be used (see OrbitCamera).
#include <cstdint>
#include <vector>

#include "model/project.h"

namespace gridifs {

/// A density volume to draw: n³ values in [0, 1] (x fastest), voxel (i, j, k) centred at
/// (−1 + (2i+1)/n, …) over X = [-1, 1]³, and optionally 3 colour values per voxel.
struct VolumeSource {
  int n = 0;
  std::vector<float> density;
  std::vector<float> color;  // empty, or 3 per voxel: the mean structural colour of the visits
};

/// Everything that decides the look besides the volume and the camera.
struct VolumeLook {
  VolumeRenderSettings settings;
  /// Albedo by density where there is neither a colour volume nor a transfer function
  /// (the flame palette, 256 entries of r g b); empty: white.
  std::vector<float> palette;
  Vec3 towardLight{0.0, 0.0, 1.0};  // direction towards the light (need not be unit length)
  Vec3 lightColor{1.0};             // colour × intensity
  double ambient = 0.2;
  Vec3 background{0.0};  // what the preview composites over (the image keeps alpha)
  bool operator==(const VolumeLook&) const = default;
  /// Whether two looks classify a volume alike (stage 1: transfer function, palette, light direction).
  bool classifiesLike(const VolumeLook& other) const {
    return settings.transfer == other.settings.transfer && palette == other.palette && towardLight == other.towardLight;
  }
};

/// The look of a project: render.volume (defaults when absent), the key light of the shading
/// settings (or the default key light), the ambient term and the background. The palette is left
/// empty: the caller resolves the project's flame palette (files are relative to the project).
VolumeLook volumeLookOf(const Project& project);

/// Stage 1: albedo (3 per voxel), opacity (1 per voxel) and the optical depth towards the light
/// of the opacity field.
struct ClassifiedVolume {
  int n = 0;
  std::vector<float> albedo, opacity, lightDepth;
};
ClassifiedVolume classifyVolume(const VolumeSource& source, const VolumeLook& look, int threads);

/// Stage 2: per voxel r g b emission (weighted by the extinction, so that interpolation towards an
/// empty neighbour keeps the colour) and extinction per world unit, and the occupied blocks.
struct ShadedVolume {
  int n = 0;
  std::vector<float> voxels;                    // 4 per voxel
  int blocks = 0;                               // blocks per axis (kVolumeBlock voxels each)
  std::vector<std::uint8_t> occupied;           // blocks³: whether a sample in the block can see extinction
  int lo[3] = {0, 0, 0}, hi[3] = {-1, -1, -1};  // voxel index bounds of the extinction (inclusive)
};
inline constexpr int kVolumeBlock = 8;
ShadedVolume shadeVolume(const ClassifiedVolume& classified, const VolumeLook& look, int threads);

/// Stage 3's result: premultiplied r g b a (display values in [0, 1]) and the depth (distance
/// along the viewing direction, world units) where the opacity weight lies on average;
/// kEmptyVolumeDepth where nothing was hit. Rows top to bottom.
struct VolumeImage {
  int width = 0, height = 0;
  std::vector<float> rgba;
  std::vector<float> depth;
  /// The premultiplied colour over `background`, 8-bit r g b a (a = 255), as the preview shows it.
  std::vector<std::uint8_t> composited(const Vec3& background) const;
};
inline constexpr float kEmptyVolumeDepth = 1e10f;

/// Stage 3: the ray march at width × height through `camera`. `threads` ≤ 0: every hardware
/// thread; the image does not depend on the count. Throws ModelError for a bad camera or size.
VolumeImage marchVolume(const ShadedVolume& shaded, const VolumeLook& look, const Camera& camera, int width, int height,
                        int threads);

/// All three stages.
VolumeImage renderVolumeImage(const VolumeSource& source, const VolumeLook& look, const Camera& camera, int width,
                              int height, int threads);

}  // namespace gridifs
