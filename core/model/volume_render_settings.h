#pragma once
// "render.volume": how `gridifs render --mode volume` and the modeller's Volume preview draw the
// measure attractor's density volume (Sokolov & Gentil, §3.4) — one ray march for both — and
// "view": how the modeller last showed the project.
#include <optional>
#include <vector>

#include "base/types.h"

namespace gridifs {

/// "display": "lit" (emission and absorption, one light with self-shadowing) or "xray" (grey
/// summed density, the look of Sokolov & Gentil's figures 9–12).
enum class VolumeDisplay { Lit, Xray };

/// One stop of the transfer function: at `density` (in [0, 1]) the voxel has this colour and
/// this opacity (extinction weight in [0, 1]); between stops both are interpolated linearly.
struct TransferStop {
  double density = 0.0;
  Vec3 color{1.0};
  double opacity = 1.0;
  bool operator==(const TransferStop&) const = default;
};

inline constexpr int kMaxTransferStops = 64;
inline constexpr double kMinVolumeDensityScale = 0.01;
inline constexpr double kMaxVolumeDensityScale = 10000.0;

struct VolumeRenderSettings {
  int resolution = 128;         // N of the N³ volume the ray march reads
  double density_scale = 24.0;  // σ: extinction per world unit at opacity 1
  VolumeDisplay display = VolumeDisplay::Lit;
  /// Density → colour and opacity, stops sorted by density. Empty: opacity = density, and the
  /// colour is the functions' structural colour (or the flame palette by density).
  std::vector<TransferStop> transfer;
  bool operator==(const VolumeRenderSettings&) const = default;
};

/// "view.preview_mode": the preview mode the modeller showed when the project was saved.
enum class StoredPreviewMode { ZBuffer, Flame, Shaded, Mesh, Volume };

}  // namespace gridifs
