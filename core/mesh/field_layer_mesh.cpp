#include "mesh/field_layer_mesh.h"

#include <algorithm>
#include <limits>

#include "schema/field_layer.h"

namespace gridifs {
namespace {

void addSheet(IfsMesh& mesh, const VolumeDensityField& layer, double t, std::size_t n) {
  const double h = fieldLayerPlaneHeight(layer);
  std::vector<Vec3> points(n * n);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i)
      points[j * n + i] = {-1.0 + 2.0 * double(i) / double(n - 1), -1.0 + 2.0 * double(j) / double(n - 1), h};
  const std::vector<double> g = fieldLayerValues(layer, points, t);
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (std::size_t v = 0; v < points.size(); ++v) {
    points[v].z = h + layer.strength * g[v];
    low = std::min(low, points[v].z);
    high = std::max(high, points[v].z);
  }
  std::vector<IfsMesh::VertexHandle> vertices(points.size());
  for (std::size_t v = 0; v < points.size(); ++v) {
    const Vec3& p = points[v];
    vertices[v] = mesh.add_vertex(IfsMesh::Point(float(p.x), float(p.y), float(p.z)));
    const float s = high > low ? float((p.z - low) / (high - low)) : 0.5f;
    const IfsMesh::Color color = layer.role == FieldRole::Cloud
                                     ? IfsMesh::Color(0.85f + 0.15f * s, 0.87f + 0.13f * s, 0.9f + 0.1f * s, 1.0f)
                                     : IfsMesh::Color(0.25f + 0.7f * s, 0.22f + 0.7f * s, 0.18f + 0.75f * s, 1.0f);
    mesh.set_color(vertices[v], color);
  }
  for (std::size_t j = 0; j + 1 < n; ++j)
    for (std::size_t i = 0; i + 1 < n; ++i)
      mesh.add_face(
          {vertices[j * n + i], vertices[j * n + i + 1], vertices[(j + 1) * n + i + 1], vertices[(j + 1) * n + i]});
}

}  // namespace

IfsMesh fieldLayerSheets(const std::vector<const VolumeDensityField*>& layers, double t, int size) {
  IfsMesh mesh;
  mesh.request_vertex_colors();
  for (const VolumeDensityField* layer : layers) addSheet(mesh, *layer, t, std::size_t(size));
  return mesh;
}

}  // namespace gridifs
