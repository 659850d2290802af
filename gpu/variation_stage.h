#pragma once
// The flame variations' part of the GPU renderer's upload (shaders/flame_variations.comp.glsl):
// the shader's numbering, every function's variation stage packed for the Stages buffer, and the
// depth range of a render whose functions have variations. Internal to ChaosCompute; pure
// functions of their arguments (thread-safe).
//
// Stages buffer (uvec4 words, binding 9): word i < n (n = functions + the final function, in the
// Functions buffer's order) is (offset of function i's stage, its term count, 0, 0), offset
// ~0 when f = g. A stage at word h: h, h+1, h+2 the post map's rows (x y z t, floats); h+3 the
// grid map's affine coefficients a b c d and h+4 e f 0 0 (the dependent variations read them);
// then three words per term: (variation index, weight, flags, 0) and its parameters in table
// order, 8 floats (flags: 1 writes z, 2 pre-variation, 4 flatten, 8 random).
#include <cstdint>
#include <string>
#include <vector>

#include "render/camera.h"
#include "render/compiled_ifs.h"

namespace gridifs::gpu {

/// Which variations of flameVariations() the functions of `ifs` (and its final function) use: one
/// character per variation, '1' used, '0' not. The key of the specialised program.
std::string usedVariations(const CompiledIfs& ifs);

/// For every variation of flameVariations(), "#define V_<name> <index>u" and "#define USE_<name>
/// 1" or "0" as `used` (usedVariations) says, one a line.
std::string variationDefines(const std::string& used);

/// The Stages buffer for `ifs`. Throws GpuUnavailable for a variation the shader's layout cannot
/// hold (more than 8 parameters, a pre-variation other than pre_blur).
std::vector<std::uint32_t> packVariationStages(const CompiledIfs& ifs);

/// The camera depths the plotted points of an IFS with variations mostly have, for the 32-bit
/// keys' linear depth step (the nodes' range says nothing once variations move points beyond
/// them): [lo, hi] over a short CPU chaos game with a fixed seed (so it depends on the IFS and the
/// camera only, never on the render's seed or part), its 0.1 % tails cut and 5 % margins added.
/// False when too few pilot points land in the image.
bool variationDepthRange(const CompiledIfs& ifs, const OrbitCamera& camera, int skip, float& lo, float& hi);

}  // namespace gridifs::gpu
