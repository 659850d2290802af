#include "volume/density_field.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "anim/fractal_field.h"

namespace gridifs {
namespace {

// The field along x only: the fast whole-step evaluation displaces nodes by
// amplitude ⊙ (F_S, F_S+1, F_S+2), so an amplitude of (1, 0, 0) leaves F_S in the x displacement.
FractalField scalarField(const VolumeDensityField& field) {
  FractalFieldParams params = field.field;
  params.amplitude = {1.0, 0.0, 0.0};
  return FractalField(params);
}

double weightOf(double strength, double f) { return std::max(0.0, 1.0 + strength * f); }

}  // namespace

double densityFieldWeight(const VolumeDensityField& field, const Vec3& p, double t) {
  const Vec3 s = p + field.field.wind * t;
  return weightOf(field.strength, scalarField(field).value(0, {s.x, s.y, s.z, t}));
}

void modulateDensity(DensityVolume& volume, const VolumeDensityField& field, double t, int threads) {
  std::vector<std::uint32_t> visited;
  for (std::uint32_t v = 0; v < std::uint32_t(volume.density.size()); ++v)
    if (volume.density[v] > 0.0f) visited.push_back(v);
  if (visited.empty()) return;
  std::vector<Vec3> nodes(visited.size());
  for (std::size_t n = 0; n < visited.size(); ++n) nodes[n] = volume.lattice.centre(visited[n]);
  std::vector<Vec3> displaced = nodes;
  scalarField(field).displaceNodes(displaced, std::vector<unsigned char>(nodes.size(), 1), t, threads);
  float largest = 0.0f;
  for (std::size_t n = 0; n < visited.size(); ++n) {
    float& d = volume.density[visited[n]];
    d = float(d * weightOf(field.strength, displaced[n].x - nodes[n].x));
    largest = std::max(largest, d);
  }
  if (largest > 0.0f)
    for (float& d : volume.density) d /= largest;
}

}  // namespace gridifs
