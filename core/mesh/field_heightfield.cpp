#include "mesh/field_heightfield.h"

#include <algorithm>
#include <limits>

namespace gridifs {

IfsMesh fieldHeightfield(const FractalField& field, double t, int size) {
  const auto n = std::size_t(size);
  std::vector<Vec3> points(n * n);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i)
      points[j * n + i] = {-1.0 + 2.0 * double(i) / double(n - 1), -1.0 + 2.0 * double(j) / double(n - 1), 0.0};
  field.displaceNodes(points, std::vector<unsigned char>(points.size(), 1), t);
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (const Vec3& p : points) {
    low = std::min(low, p.z);
    high = std::max(high, p.z);
  }
  IfsMesh mesh;
  mesh.request_vertex_colors();
  std::vector<IfsMesh::VertexHandle> vertices(points.size());
  for (std::size_t v = 0; v < points.size(); ++v) {
    const Vec3& p = points[v];
    vertices[v] = mesh.add_vertex(IfsMesh::Point(float(p.x), float(p.y), float(p.z)));
    // Valleys dark, peaks light: the relief reads without lighting.
    const float h = high > low ? float((p.z - low) / (high - low)) : 0.5f;
    mesh.set_color(vertices[v], IfsMesh::Color(0.25f + 0.7f * h, 0.22f + 0.7f * h, 0.18f + 0.75f * h, 1.0f));
  }
  for (std::size_t j = 0; j + 1 < n; ++j)
    for (std::size_t i = 0; i + 1 < n; ++i)
      mesh.add_face(
          {vertices[j * n + i], vertices[j * n + i + 1], vertices[(j + 1) * n + i + 1], vertices[(j + 1) * n + i]});
  return mesh;
}

}  // namespace gridifs
