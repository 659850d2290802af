#include "schema/field_layer.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "base/errors.h"
#include "schema/operation_table.h"
#include "schema/settings_tables.h"
#include "schema/validation.h"

namespace gridifs {

const char* toString(FieldRole role) {
  switch (role) {
    case FieldRole::Density:
      return "density";
    case FieldRole::Cloud:
      return "cloud";
    case FieldRole::Terrain:
      return "terrain";
  }
  return "density";
}

bool parseFieldRole(const std::string& text, FieldRole& out) {
  if (text == "density") {
    out = FieldRole::Density;
  } else if (text == "cloud") {
    out = FieldRole::Cloud;
  } else if (text == "terrain") {
    out = FieldRole::Terrain;
  } else {
    return false;
  }
  return true;
}

double primitiveSignedDistance(const CondensationSet& set, const Vec3& p) {
  const Vec3 d = p - set.center;
  switch (set.shape) {
    case SetShape::Sphere:
      return glm::length(d) - set.radius;
    case SetShape::Box: {
      const Vec3 q = glm::abs(d) - 0.5 * set.size;
      return glm::length(glm::max(q, Vec3{0.0})) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0);
    }
    case SetShape::Torus: {
      const Vec3 a = glm::normalize(set.axis);
      const double h = glm::dot(d, a);
      const double r = glm::length(d - h * a) - set.major;
      return std::sqrt(r * r + h * h) - set.minor;
    }
    case SetShape::Mesh:
    case SetShape::Vdb:
    case SetShape::Image:
      break;
  }
  return 0.0;
}

double fieldShapeValue(const VolumeDensityField& layer, const Vec3& p) {
  if (!layer.shape) return 0.0;
  return std::clamp(-primitiveSignedDistance(*layer.shape, p) / layer.softness, -1.0, 1.0);
}

namespace {

// The field along x only: the whole-step evaluation displaces by amplitude ⊙ (F_S, F_S+1, F_S+2),
// so an amplitude of (1, 0, 0) leaves F_S in the x displacement.
FractalField scalarField(const VolumeDensityField& layer) {
  FractalFieldParams params = layer.field;
  params.amplitude = {1.0, 0.0, 0.0};
  return FractalField(params);
}

double blended(const VolumeDensityField& layer, double f, const Vec3& p) {
  if (!layer.shape) return f;
  return (1.0 - layer.blend) * f + layer.blend * fieldShapeValue(layer, p);
}

}  // namespace

double fieldLayerValue(const VolumeDensityField& layer, const Vec3& p, double t) {
  const Vec3 s = p + layer.field.windShift(t);
  return blended(layer, scalarField(layer).value(0, {s.x, s.y, s.z, t}), p);
}

std::vector<double> fieldLayerValues(const VolumeDensityField& layer, const std::vector<Vec3>& points, double t,
                                     int threads) {
  std::vector<Vec3> displaced = points;
  scalarField(layer).displaceNodes(displaced, std::vector<unsigned char>(points.size(), 1), t, threads);
  std::vector<double> values(points.size());
  for (std::size_t n = 0; n < points.size(); ++n) values[n] = blended(layer, displaced[n].x - points[n].x, points[n]);
  return values;
}

std::vector<double> fieldLayerPlane(const VolumeDensityField& layer, int size, double z, double t, int threads) {
  const auto n = std::size_t(std::max(size, 1));
  std::vector<Vec3> points(n * n);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i)
      points[j * n + i] = {-1.0 + (2.0 * double(i) + 1.0) / double(n), -1.0 + (2.0 * double(j) + 1.0) / double(n), z};
  return fieldLayerValues(layer, points, t, threads);
}

double fieldLayerPlaneHeight(const VolumeDensityField& layer) {
  return layer.role == FieldRole::Density ? 0.0 : layer.height;
}

std::vector<const VolumeDensityField*> fieldLayers(const VolumeSettings& settings) {
  std::vector<const VolumeDensityField*> layers;
  if (settings.field) layers.push_back(&*settings.field);
  for (const VolumeDensityField& layer : settings.more_fields) layers.push_back(&layer);
  return layers;
}

void checkFieldLayer(const VolumeDensityField& layer, const std::string& path) {
  validateSettings(fieldLayerTable(), layer, path);
  try {
    validateOperationParams(OpParams{layer.field});
  } catch (const ModelError& e) {
    throw e.under(path);
  }
  if (layer.shape) {
    if (layer.shape->shape == SetShape::Mesh || layer.shape->shape == SetShape::Vdb ||
        layer.shape->shape == SetShape::Image)
      throw ModelError(path + ".shape", "a field's shape must be a sphere, a box or a torus");
    checkCondensationSet(*layer.shape, path + ".shape");
  }
}

}  // namespace gridifs
