#pragma once
// Small shared vocabulary of the model: vectors, axes, profiles, limits.
#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <string>

#include "base/errors.h"

namespace gridifs {

using Vec3 = glm::dvec3;
using Index3 = std::array<int, 3>;

enum class Axis { X = 0, Y = 1, Z = 2 };
enum class Profile { Linear, Sine, PingPong };

const char* axisName(Axis axis);
const char* profileName(Profile profile);
bool parseAxis(const std::string& text, Axis& out);
bool parseProfile(const std::string& text, Profile& out);

/// The two axes perpendicular to `axis`, in cyclic order:
/// z → (x, y), x → (y, z), y → (z, x).
inline std::array<int, 2> perpendicularAxes(Axis axis) {
  const int a = static_cast<int>(axis);
  return {(a + 1) % 3, (a + 2) % 3};
}

/// Hard limits that keep hostile project files from exhausting memory or time.
namespace limits {
inline constexpr int kMinResolution = 2;
inline constexpr int kMaxResolution = 128;
inline constexpr int kMaxFunctions = 64;
inline constexpr int kMaxOpsPerFunction = 256;
inline constexpr int kMaxSelectionBoxes = 256;
inline constexpr int kMaxMorphPairs = 64;
inline constexpr int kMaxNodeMoves = 1 << 20;
inline constexpr std::int64_t kMaxTotalNodes = std::int64_t(1) << 22;  // summed over all functions
inline constexpr std::size_t kMaxNameLength = 256;
inline constexpr std::size_t kMaxExpressionLength = 4096;
inline constexpr std::size_t kMaxFileBytes = 64u << 20;
inline constexpr int kMaxJsonDepth = 32;
inline constexpr double kMaxCoordinate = 1e6;  // any coordinate or parameter magnitude
}  // namespace limits

}  // namespace gridifs
