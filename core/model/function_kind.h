#pragma once
// What a function of the IFS is made of, and how the final function's lattice interpolates.
namespace gridifs {

/// "kind": a distorted grid (Gröller & Wegenkittl 1994) or, in a project with a free-form space,
/// an m×m matrix acting on barycentric coordinates (Thollot, Zair, Tosan & Vandorpe 1997, §3.1),
/// Barnsley's constant condensation map onto a set, or Sokolov & Gentil's condensation function
/// f_C = M(·, C) built from left and right median images (§3.2).
enum class FunctionKind { Grid, Matrix, Condensation, Median };

/// Whether the function acts through its condensation set (no grid).
inline bool isSetKind(FunctionKind kind) { return kind == FunctionKind::Condensation || kind == FunctionKind::Median; }

/// "interpolation" of the final function's lattice: trilinear cells (the default) or
/// Sederberg & Parry's free-form deformation (1986), the whole lattice as tensor-product Bézier
/// control points over X.
enum class LatticeInterpolation { Trilinear, Bezier };

const char* functionKindName(FunctionKind kind);
const char* latticeInterpolationName(LatticeInterpolation interpolation);

}  // namespace gridifs
