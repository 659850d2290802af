#pragma once
// The sRGB transfer function (IEC 61966-2-1): display-encoded values (PNG, the screen) become
// scene-linear light (EXR) here and nowhere else.
//
// Thread-safety: pure functions.
#include <cmath>

namespace gridifs {

/// sRGB-encoded value in [0, 1] → linear light.
inline float srgbToLinear(float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); }

}  // namespace gridifs
