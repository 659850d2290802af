#pragma once
// What a function of the IFS is made of, and how the final function's lattice interpolates.
namespace gridifs {

/// "kind": a distorted grid (Gröller & Wegenkittl 1994) or, in a project with a free-form space,
/// an m×m matrix acting on barycentric coordinates (Thollot, Zair, Tosan & Vandorpe 1997, §3.1).
enum class FunctionKind { Grid, Matrix };

/// "interpolation" of the final function's lattice: trilinear cells (the default) or
/// Sederberg & Parry's free-form deformation (1986), the whole lattice as tensor-product Bézier
/// control points over X.
enum class LatticeInterpolation { Trilinear, Bezier };

const char* functionKindName(FunctionKind kind);
const char* latticeInterpolationName(LatticeInterpolation interpolation);

}  // namespace gridifs
