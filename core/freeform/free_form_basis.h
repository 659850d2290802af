#pragma once
// Bases of free-form IFSs and the linear algebra that turns a map of the parameter space into a
// matrix of barycentric coordinates (Thollot, Zair, Tosan & Vandorpe 1997, §5.2–5.3): when the
// basis B spans a space of polynomials that a map T keeps (B∘T = B·M for one matrix M), M can be
// found by collocation, B(x_k)·M = B(T x_k) at as many points x_k as there are basis functions
// (solveLinear; freeform/free_form_deformation.cpp does so). Rows of M sum to 1 whenever the basis
// sums to 1 (a partition of unity).
//
// Thread-safety: pure functions of their arguments. solveLinear throws ModelError("", …) for a
// singular system.
#include <vector>

#include "freeform/free_form.h"

namespace gridifs {

/// X with A·X = B (A n×n, B n×k), by Gaussian elimination with partial pivoting.
BarycentricMatrix solveLinear(BarycentricMatrix a, BarycentricMatrix b);

/// The uniform B-spline blending functions of one segment of degree n at t in [0, 1]: n + 1
/// values N_j(t) = M_n(t + n − j), M_n the cardinal B-spline on [0, n + 1].
std::vector<double> uniformBSpline(int degree, double t);

/// The standard uniform subdivision matrices of a degree-n B-spline segment (the Lane–Riesenfeld
/// refinement restricted to one segment, exact binomial weights over 2^n): N(t/2) = N(t)·left,
/// N((1 + t)/2) = N(t)·right.
BarycentricMatrix bsplineSubdivisionLeft(int degree);
BarycentricMatrix bsplineSubdivisionRight(int degree);

/// The multi-indices α (|α| = degree, dim + 1 entries) of the Bernstein basis of total degree
/// `degree` on a simplex of dimension `dim` (2: triangle, 3: tetrahedron), in a fixed order;
/// their count is C(degree + dim, dim).
std::vector<std::vector<int>> simplexIndices(int dim, int degree);

/// B_α(β) = degree!/∏α_i! · ∏β_i^{α_i} for every α of simplexIndices, at barycentric β.
std::vector<double> simplexBernstein(int degree, const std::vector<std::vector<int>>& indices,
                                     const std::vector<double>& beta);

}  // namespace gridifs
