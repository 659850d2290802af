#pragma once
// Ready-made free-form IFSs (Thollot, Zair, Tosan & Vandorpe 1997, §5): Bézier curves and
// patches of degree 1–7 as attractors of their de Casteljau subdivision matrices, uniform B-spline
// curves and patches as attractors of their uniform subdivision matrices, the Sierpinski gasket with
// control points, and "roughness", which blends the subdivision matrices towards random Markov
// rows (rows still summing to 1, the joints between the pieces kept) so that the smooth shapes become fractal ones
// (§5.3.2).
//
// Thread-safety: pure functions of their arguments.
#include <cstdint>
#include <string>
#include <vector>

#include "freeform/free_form.h"

namespace gridifs {

enum class FreeFormPreset {
  BezierCurve,      // Bézier curve of `degree`: the two de Casteljau halves at `split` (§5.3.1)
  BezierPatch,      // Bézier patch of `degree`²: the four tensor products of the halves (§5.4.2)
  Sierpinski,       // the gasket on 3 control points: λ ← (λ + e_k)/2, the affine Sierpinski
  SierpinskiPatch,  // three of the four quarters of a bicubic patch: a gasket bent by its net (§5.5)
  BSplineCurve,     // one uniform B-spline segment of `degree`, halved (`split` does not apply)
  BSplinePatch,     // one uniform B-spline patch of `degree`², quartered
};

/// The degrees the Bézier and B-spline presets offer.
inline constexpr int kMinPresetDegree = 1, kMaxPresetDegree = 7;

struct FreeFormPresetOptions {
  int degree = 3;          // of the Bézier and B-spline presets, kMinPresetDegree..kMaxPresetDegree
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
/// camera and render settings stay). Throws ModelError ("degree", "split", "roughness") for
/// options out of range. Roughness applies to the Bézier and Sierpinski presets; the B-spline
/// ones stay smooth (blending their rows would break the joint between the halves).
void applyFreeFormPreset(Project& project, FreeFormPreset preset, const FreeFormPresetOptions& options = {});

/// The control points the presets start from: a curve's degree + 1 points, a patch's
/// (degree + 1)² net (index (degree + 1)·i + k), a triangle's 3 corners.
std::vector<Vec3> defaultCurveControlPoints(int degree = 3);
std::vector<Vec3> defaultPatchControlPoints(int degree = 3);
std::vector<Vec3> defaultTriangleControlPoints();

}  // namespace gridifs
