#pragma once
// Ready-made free-form IFSs (Thollot, Zair, Tosan & Vandorpe 1997, §5): Bézier curves and
// patches as attractors of their de Casteljau subdivision matrices, the Sierpinski gasket with
// control points, and "roughness", which blends the subdivision matrices towards random Markov
// rows (rows still summing to 1, the joints between the pieces kept) so that the smooth shapes become fractal ones
// (§5.3.2).
//
// Thread-safety: pure functions of their arguments.
#include <cstdint>
#include <string>
#include <vector>

#include "model/free_form.h"

namespace gridifs {

enum class FreeFormPreset {
  BezierCurve,      // cubic Bézier curve: the two de Casteljau halves at `split` (§5.3.1)
  BezierPatch,      // bicubic Bézier patch: the four tensor products of the halves (§5.4.2)
  Sierpinski,       // the gasket on 3 control points: λ ← (λ + e_k)/2, the affine Sierpinski
  SierpinskiPatch,  // three of the four quarters of a bicubic patch: a gasket bent by its net (§5.5)
};

struct FreeFormPresetOptions {
  double split = 0.5;      // r of the de Casteljau subdivision, in (0, 1)
  double roughness = 0.0;  // 0..1; 0: smooth; ~0.1–0.4: a fractal curve or surface
  std::uint64_t seed = 1;  // of the roughness perturbation
};

/// Preset names as the modeller shows them and parseFreeFormPreset reads them.
const char* freeFormPresetName(FreeFormPreset preset);
bool parseFreeFormPreset(const std::string& name, FreeFormPreset& out);

/// Bernstein polynomials B_i^n(t), i = 0..n.
std::vector<double> bernstein(int degree, double t);

/// The de Casteljau subdivision matrices of a degree-n Bézier curve at r: B(t)·left = B(r·t) and
/// B(t)·right = B(r + (1 − r)·t) for the row vector B(t) of Bernstein polynomials.
BarycentricMatrix deCasteljauLeft(int degree, double r);
BarycentricMatrix deCasteljauRight(int degree, double r);

/// Replaces the space, the functions and the transitions of `project` by the preset's (the
/// camera and render settings stay). Throws ModelError for options out of range.
void applyFreeFormPreset(Project& project, FreeFormPreset preset, const FreeFormPresetOptions& options = {});

/// The control points the presets start from: a cubic's 4 points, a bicubic's 4×4 net (index
/// 4·i + k), a triangle's 3 corners.
std::vector<Vec3> defaultCurveControlPoints();
std::vector<Vec3> defaultPatchControlPoints();
std::vector<Vec3> defaultTriangleControlPoints();

}  // namespace gridifs
