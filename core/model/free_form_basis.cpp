#include "model/free_form_basis.h"

#include <cmath>
#include <utility>

#include "base/errors.h"

namespace gridifs {
namespace {

double factorial(int n) {
  double f = 1.0;
  for (int i = 2; i <= n; ++i) f *= i;
  return f;
}

double binomial(int n, int k) { return factorial(n) / (factorial(k) * factorial(n - k)); }

/// The cardinal B-spline of degree n, supported on [0, n + 1]: the truncated-power formula
/// M_n(x) = 1/n! Σ_k (−1)^k C(n + 1, k) (x − k)_+^n.
double cardinalBSpline(int n, double x) {
  if (x <= 0.0 || x >= n + 1) return 0.0;
  double s = 0.0;
  for (int k = 0; k <= n + 1 && k < x; ++k) s += (k % 2 ? -1.0 : 1.0) * binomial(n + 1, k) * std::pow(x - k, n);
  return s / factorial(n);
}

/// M with N(x_k)·M = N(s(x_k)) at n + 1 points: the matrix of t ↦ s(t) in the basis N.
template <class Basis, class Map>
BarycentricMatrix collocate(int count, const Basis& basis, const Map& map) {
  BarycentricMatrix c, r;
  for (int k = 0; k < count; ++k) {
    const double t = (k + 0.5) / count;
    c.push_back(basis(t));
    r.push_back(basis(map(t)));
  }
  return solveLinear(std::move(c), std::move(r));
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

BarycentricMatrix bsplineSubdivisionLeft(int degree) {
  return collocate(degree + 1, [degree](double t) { return uniformBSpline(degree, t); },
                   [](double t) { return 0.5 * t; });
}

BarycentricMatrix bsplineSubdivisionRight(int degree) {
  return collocate(degree + 1, [degree](double t) { return uniformBSpline(degree, t); },
                   [](double t) { return 0.5 + 0.5 * t; });
}

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
