#include "freeform/free_form_basis.h"

#include <cmath>

#include "base/errors.h"

namespace gridifs {
namespace {

double factorial(int n) {
  double f = 1.0;
  for (int i = 2; i <= n; ++i) f *= i;
  return f;
}

double binomial(int n, int k) { return factorial(n) / (factorial(k) * factorial(n - k)); }

/// The cardinal B-spline of degree n, supported on [0, n + 1], by the Cox–de Boor recursion
/// M_n(x) = (x·M_{n−1}(x) + (n + 1 − x)·M_{n−1}(x − 1)) / n (stable, unlike the truncated powers).
double cardinalBSpline(int n, double x) {
  if (x < 0.0 || x >= n + 1) return 0.0;
  if (n == 0) return 1.0;
  return (x * cardinalBSpline(n - 1, x) + (n + 1 - x) * cardinalBSpline(n - 1, x - 1.0)) / n;
}

/// The subdivision matrix of one degree-n segment: row j is fine control point `first` + j of
/// the Lane–Riesenfeld refinement P'_m = Σ_i c_{m − 2i} P_i, c_k = C(n + 1, k) / 2^n.
BarycentricMatrix bsplineSubdivision(int n, int first) {
  const std::size_t m = std::size_t(n) + 1;
  BarycentricMatrix t(m, std::vector<double>(m, 0.0));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const int k = first + j - 2 * i;
      if (k >= 0 && k <= n + 1) t[std::size_t(j)][std::size_t(i)] = binomial(n + 1, k) / std::ldexp(1.0, n);
    }
  return t;
}

}  // namespace

BarycentricMatrix solveLinear(BarycentricMatrix a, BarycentricMatrix b) {
  const std::size_t n = a.size(), k = b.empty() ? 0 : b[0].size();
  for (std::size_t col = 0; col < n; ++col) {
    std::size_t pivot = col;
    for (std::size_t i = col + 1; i < n; ++i)
      if (std::abs(a[i][col]) > std::abs(a[pivot][col])) pivot = i;
    if (!(std::abs(a[pivot][col]) > 1e-14)) throw ModelError("", "the collocation system is singular");
    std::swap(a[col], a[pivot]);
    std::swap(b[col], b[pivot]);
    for (std::size_t i = 0; i < n; ++i) {
      if (i == col || a[i][col] == 0.0) continue;
      const double f = a[i][col] / a[col][col];
      for (std::size_t j = col; j < n; ++j) a[i][j] -= f * a[col][j];
      for (std::size_t j = 0; j < k; ++j) b[i][j] -= f * b[col][j];
    }
  }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < k; ++j) b[i][j] /= a[i][i];
  return b;
}

std::vector<double> uniformBSpline(int degree, double t) {
  std::vector<double> n(std::size_t(degree) + 1);
  for (int j = 0; j <= degree; ++j) n[std::size_t(j)] = cardinalBSpline(degree, t + degree - j);
  return n;
}

BarycentricMatrix bsplineSubdivisionLeft(int degree) { return bsplineSubdivision(degree, degree); }

BarycentricMatrix bsplineSubdivisionRight(int degree) { return bsplineSubdivision(degree, degree + 1); }

std::vector<std::vector<int>> simplexIndices(int dim, int degree) {
  std::vector<std::vector<int>> out;
  std::vector<int> alpha(std::size_t(dim) + 1, 0);
  // Every composition of `degree` into dim + 1 parts; the first part is what the others leave.
  auto recurse = [&](auto&& self, int position, int left) -> void {
    if (position == 0) {
      alpha[0] = left;
      out.push_back(alpha);
      return;
    }
    for (int a = 0; a <= left; ++a) {
      alpha[std::size_t(position)] = a;
      self(self, position - 1, left - a);
    }
  };
  recurse(recurse, dim, degree);
  return out;
}

std::vector<double> simplexBernstein(int degree, const std::vector<std::vector<int>>& indices,
                                     const std::vector<double>& beta) {
  std::vector<double> out;
  out.reserve(indices.size());
  for (const auto& alpha : indices) {
    double v = factorial(degree);
    for (std::size_t i = 0; i < alpha.size(); ++i) v *= std::pow(beta[i], alpha[i]) / factorial(alpha[i]);
    out.push_back(v);
  }
  return out;
}

}  // namespace gridifs
