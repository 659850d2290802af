#include "volume/density_field.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "schema/field_layer.h"

namespace gridifs {
namespace {

double weightOf(double strength, double g) { return std::max(0.0, 1.0 + strength * g); }

// What a cloud or terrain layer adds at height z over a column whose plane value is g.
double columnDensity(const VolumeDensityField& layer, double g, double z) {
  switch (layer.role) {
    case FieldRole::Terrain:
      return z <= layer.height + layer.strength * g ? 1.0 : 0.0;
    case FieldRole::Cloud: {
      // The cloud is as thick as it is dense: c·thickness about its plane, density c.
      const double c = std::clamp(layer.strength * g, 0.0, 1.0);
      return c > 0.0 && std::abs(z - layer.height) <= 0.5 * c * layer.thickness ? c : 0.0;
    }
    case FieldRole::Density:
      break;
  }
  return 0.0;
}

void addLayer(DensityVolume& volume, const VolumeDensityField& layer, double t, int threads) {
  const VoxelLattice& lattice = volume.lattice;
  const int n = lattice.n;
  const std::vector<double> plane = fieldLayerPlane(layer, n, layer.height, t, threads);
  // Clouds white, rock a light grey: the colour volume holds mean colours in [0, 1].
  const float shade = layer.role == FieldRole::Cloud ? 1.0f : 0.62f;
  for (int k = 0; k < n; ++k) {
    const double z = lattice.centre(0, 0, k).z;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const float d = float(columnDensity(layer, plane[std::size_t(j) * std::size_t(n) + std::size_t(i)], z));
        const std::uint32_t v = lattice.index(i, j, k);
        if (!(d > volume.density[v])) continue;
        volume.density[v] = d;
        if (!volume.color.empty())
          for (int c = 0; c < 3; ++c) volume.color[3 * std::size_t(v) + std::size_t(c)] = shade;
      }
  }
}

}  // namespace

double densityFieldWeight(const VolumeDensityField& field, const Vec3& p, double t) {
  return weightOf(field.strength, fieldLayerValue(field, p, t));
}

double fieldLayerDensity(const VolumeDensityField& layer, const Vec3& p, double t) {
  if (layer.role == FieldRole::Density) return 0.0;
  return columnDensity(layer, fieldLayerValue(layer, {p.x, p.y, layer.height}, t), p.z);
}

void modulateDensity(DensityVolume& volume, const VolumeDensityField& field, double t, int threads) {
  std::vector<std::uint32_t> visited;
  for (std::uint32_t v = 0; v < std::uint32_t(volume.density.size()); ++v)
    if (volume.density[v] > 0.0f) visited.push_back(v);
  if (visited.empty()) return;
  std::vector<Vec3> centres(visited.size());
  for (std::size_t n = 0; n < visited.size(); ++n) centres[n] = volume.lattice.centre(visited[n]);
  const std::vector<double> g = fieldLayerValues(field, centres, t, threads);
  float largest = 0.0f;
  for (std::size_t n = 0; n < visited.size(); ++n) {
    float& d = volume.density[visited[n]];
    d = float(d * weightOf(field.strength, g[n]));
    largest = std::max(largest, d);
  }
  if (largest > 0.0f)
    for (float& d : volume.density) d /= largest;
}

void applyFieldLayers(DensityVolume& volume, const VolumeSettings& settings, double t, int threads) {
  for (const VolumeDensityField* layer : fieldLayers(settings)) {
    if (layer->role == FieldRole::Density)
      modulateDensity(volume, *layer, t, threads);
    else
      addLayer(volume, *layer, t, threads);
  }
}

}  // namespace gridifs
