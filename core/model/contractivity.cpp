#include "model/contractivity.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace gridifs {

double spectralNorm(const Vec3& a, const Vec3& b, const Vec3& c) {
  // Largest eigenvalue of the symmetric Gram matrix G = MᵀM (closed form for 3×3).
  auto dot = [](const Vec3& u, const Vec3& v) { return u.x * v.x + u.y * v.y + u.z * v.z; };
  const double g00 = dot(a, a), g11 = dot(b, b), g22 = dot(c, c);
  const double g01 = dot(a, b), g02 = dot(a, c), g12 = dot(b, c);
  const double p1 = g01 * g01 + g02 * g02 + g12 * g12;
  const double trace = g00 + g11 + g22;
  if (p1 <= 1e-300 * (trace * trace + 1e-300)) return std::sqrt(std::max({g00, g11, g22}));
  const double q = trace / 3.0;
  const double d0 = g00 - q, d1 = g11 - q, d2 = g22 - q;
  const double p2 = d0 * d0 + d1 * d1 + d2 * d2 + 2.0 * p1;
  const double p = std::sqrt(p2 / 6.0);
  // det((G − qI)/p) / 2
  const double b00 = d0 / p, b11 = d1 / p, b22 = d2 / p, b01 = g01 / p, b02 = g02 / p, b12 = g12 / p;
  const double det = b00 * (b11 * b22 - b12 * b12) - b01 * (b01 * b22 - b12 * b02) + b02 * (b01 * b12 - b11 * b02);
  const double r = std::clamp(det / 2.0, -1.0, 1.0);
  const double phi = std::acos(r) / 3.0;
  const double largest = q + 2.0 * p * std::cos(phi);
  return std::sqrt(std::max(largest, 0.0));
}

ContractivityEstimate estimateContractivity(const Grid& grid) {
  const Index3& n = grid.resolution();
  const double hx = 2.0 / (n[0] - 1), hy = 2.0 / (n[1] - 1), hz = 2.0 / (n[2] - 1);
  ContractivityEstimate result;
  result.bound = -1.0;
  Vec3 ex[4], ey[4], ez[4];
  for (int k = 0; k + 1 < n[2]; ++k)
    for (int j = 0; j + 1 < n[1]; ++j)
      for (int i = 0; i + 1 < n[0]; ++i) {
        for (int e = 0; e < 4; ++e) {
          const int u = e & 1, v = e >> 1;
          ex[e] = (grid.node(i + 1, j + u, k + v) - grid.node(i, j + u, k + v)) / hx;
          ey[e] = (grid.node(i + u, j + 1, k + v) - grid.node(i + u, j, k + v)) / hy;
          ez[e] = (grid.node(i + u, j + v, k + 1) - grid.node(i + u, j + v, k)) / hz;
        }
        // Cheap Frobenius-style bound first: ‖J‖₂ ≤ sqrt(Σ max‖column‖²). Cells that cannot
        // beat the current maximum skip the 64 exact spectral norms.
        double mx = 0, my = 0, mz = 0;
        for (int e = 0; e < 4; ++e) {
          mx = std::max(mx, glm::dot(ex[e], ex[e]));
          my = std::max(my, glm::dot(ey[e], ey[e]));
          mz = std::max(mz, glm::dot(ez[e], ez[e]));
        }
        if (std::sqrt(mx + my + mz) <= result.bound) continue;
        double cellBound = 0.0;
        for (int a = 0; a < 4; ++a)
          for (int b = 0; b < 4; ++b)
            for (int c = 0; c < 4; ++c) cellBound = std::max(cellBound, spectralNorm(ex[a], ey[b], ez[c]));
        if (cellBound > result.bound) {
          result.bound = cellBound;
          result.worstCell = {i, j, k};
        }
      }
  return result;
}

}  // namespace gridifs
