#pragma once
// A flame genome as the .flame / .flam3 XML files of flam3, Apophysis, JWildfire and Fractorium
// store it (Draves & Reckase, "The Fractal Flame Algorithm"), parsed with pugixml into plain
// values. Nothing here knows GridIFS's model: see flame_import.h for the conversion.
// Pure functions: thread-safe.
#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "tone/palette.h"
#include "variations/flame_variations.h"

namespace gridifs {

/// Thrown for a file that is not a usable flame: the message is one sentence (no file name).
class FlameError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct FlameXform {
  double weight = 0.0;
  double color = 0.0;        // palette index in [0, 1]
  double color_speed = 0.5;  // weight of the xform's color in the running mix (legacy: (1 − symmetry)/2)
  FlameAffine coefs;         // the pre-affine map
  FlameAffine post;          // identity unless `post` is given
  /// JWildfire's 3D affine parts (`yzCoefs`, `zxCoefs`, `yzPost`, `zxPost`, same "a d b e c f"
  /// order): after the xy part, y and z are mixed by yz, then x and z by zx; the translations add.
  std::optional<FlameAffine> yz, zx, postYz, postZx;
  /// The genome's `preserve_z`: planar variations carry w·z instead of dropping z.
  bool preserveZ = false;
  std::vector<std::pair<std::string, double>> variations;  // deterministic ones, in file order
  std::map<std::string, double> params;                    // variation parameters
  std::vector<double> chaos;  // "xaos" row: weights of the next xform (missing entries are 1)
  std::string name;

  /// The whole map: post(Σ_v w_v · V_v(pre(p))) (Draves & Reckase §3, §3.1).
  FlamePoint apply(FlamePoint p) const;
  /// The pre-affine map with its 3D parts (identity in z without them), and the post map likewise.
  FlamePoint preAffine(FlamePoint p) const;
  FlamePoint postAffine(FlamePoint p) const;
  /// Whether the map is affine (only linear and the affine z variations, or no variation).
  bool isAffine() const;
  /// Whether any variation receives a point whose x or y depends on the input z (the 3D
  /// pre-affine parts mix z in). When not, the map is affine in z for fixed x and y, so two
  /// grid layers in z sample it exactly.
  bool xyDependsOnZ() const;
  /// Whether the xform has 3D parts (z variations or 3D affine parts).
  bool isThreeD() const;
};

/// Whether a genome's variation `name` writes z in the 3D extension's semantics (Apophysis 7X,
/// JWildfire): linear, linear3D and the z variations. The others see the plane and carry z only
/// under preserve_z.
bool isGenomeZVariation(const std::string& name);
/// Whether variation `name`'s z output does not scale with the point's z (ztranslate: a constant;
/// zcone: a function of x and y), so that seen in X = (x, y, −z) its weight changes sign.
bool flipsSignWithZ(const std::string& name);

struct FlameGenome {
  std::string name;
  int width = 0, height = 0;
  double centerX = 0.0, centerY = 0.0;
  double scale = 1.0;   // pixels per unit at zoom 0
  double zoom = 0.0;    // pixels per unit = scale · 2^zoom
  double rotate = 0.0;  // degrees
  double quality = 50.0;
  int supersample = 1;
  double filter = 0.5;
  double brightness = 4.0, gamma = 4.0, gamma_threshold = 0.01, vibrancy = 1.0, highlight_power = -1.0;
  std::array<double, 3> background{0.0, 0.0, 0.0};
  double estimator_radius = 9.0, estimator_minimum = 0.0, estimator_curve = 0.4;
  int paletteNumber = -1;          // `palette` attribute: flam3's collection (−1: none)
  std::optional<Palette> palette;  // inline `<palette>` hex or `<color>` entries
  double hue = 0.0;                // flam3's hue rotation in turns, applied to a `palette` number's colors
  /// The 3D camera of Apophysis 7X, JWildfire and Fractorium: pitch and yaw in radians as the
  /// files store them, perspective (1 / the eye's distance from the z = 0 plane), zpos (subtracted
  /// from z before the camera turns), and JWildfire's extra zoom factor.
  double camPitch = 0.0, camYaw = 0.0, camPerspective = 0.0, camZpos = 0.0, camZoom = 1.0;
  /// cam_dof: each sample moves, at a random angle, by a random distance up to 0.1 · |camDof|
  /// times its distance from the plane c_z = 0, before the perspective divide.
  double camDof = 0.0;
  /// Whether the genome is 3D: a 3D camera, z variations or 3D affine parts.
  bool threeD = false;
  /// `gridifs_frame` ("centerX centerY scale"), written by GridIFS's exporter so that importing
  /// the file again restores the project's frame exactly.
  std::optional<std::array<double, 3>> frameHint;
  std::vector<FlameXform> xforms;
  std::optional<FlameXform> finalXform;
  /// Sentences about what was left out (random variations, unknown attributes, 3D attributes).
  std::vector<std::string> warnings;

  /// scale · 2^zoom · cam_zoom.
  double pixelsPerUnit() const;
};

/// Limits that keep a hostile file from exhausting memory or time.
namespace flame_limits {
inline constexpr std::size_t kMaxFileBytes = 64u << 20;
inline constexpr int kMaxDepth = 16;
inline constexpr int kMaxXforms = 64;
inline constexpr int kMaxImageSize = 16384;
inline constexpr double kMaxQuality = 1e5;
}  // namespace flame_limits

/// Parses every `<flame>` element of a .flame file's text (a root `<flame>` or any container
/// such as `<flames>`/`<Flames>`). Throws FlameError for malformed XML, a file without genomes,
/// a genome without xforms, non-finite or missing coefficients, and absurd sizes or qualities.
std::vector<FlameGenome> parseFlameFile(const std::string& xmlText);

/// Reads and parses a .flame file. Throws FlameError (bad content) or std::runtime_error
/// subclasses from the file system as IoError (project_io.h) when it cannot be read.
std::vector<FlameGenome> loadFlameFile(const std::filesystem::path& file);

/// Picks a genome by index ("0", "1", …) or by name; throws FlameError when none matches.
const FlameGenome& selectGenome(const std::vector<FlameGenome>& genomes, const std::string& indexOrName);

}  // namespace gridifs
