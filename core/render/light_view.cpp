#include "render/light_view.h"

#include <glm/geometric.hpp>
#include <limits>

#include "render/compiled_ifs.h"

namespace gridifs {

BoundingSphere attractorBounds(const CompiledIfs& ifs) {
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  auto add = [&](const CompiledFunction& f) {
    for (const NodePair& pair : f.pairs)
      for (const float* node : {pair.a, pair.b})
        for (int d = 0; d < 3; ++d) {
          lo[d] = std::min(lo[d], double(node[d]));
          hi[d] = std::max(hi[d], double(node[d]));
        }
  };
  if (ifs.finalFunction)
    add(*ifs.finalFunction);
  else
    for (const CompiledFunction& f : ifs.functions) add(f);
  BoundingSphere s;
  if (!(lo.x <= hi.x)) return s;  // no nodes: the unit sphere
  s.center = 0.5 * (lo + hi);
  // A little margin so that points on the hull do not fall on the map's edge.
  s.radius = std::max(1e-3, 0.5 * glm::length(hi - lo) * 1.01);
  return s;
}

LightView::LightView(const Vec3& direction, const BoundingSphere& bounds, int size) : bounds_(bounds), size_(size) {
  const double length = glm::length(direction);
  if (!(length > 1e-9) || !std::isfinite(length))
    throw ModelError("direction", "the light direction has zero length, so the light points nowhere");
  if (size < 16 || size > 8192) throw ModelError("", "the shadow map size must be between 16 and 8192");
  direction_ = direction / length;
  // Any up that is not parallel to the light; world +z unless the light is (nearly) overhead.
  const glm::dvec3 reference = std::abs(direction_.z) < 0.99 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
  const glm::dvec3 forward = -direction_;
  right_ = glm::normalize(glm::cross(forward, reference));
  up_ = glm::cross(right_, forward);
}

glm::dvec3 LightView::project(const glm::dvec3& point) const {
  const glm::dvec3 q = point - bounds_.center;
  const double scale = 0.5 * double(size_) / bounds_.radius;
  return {0.5 * size_ + glm::dot(q, right_) * scale, 0.5 * size_ - glm::dot(q, up_) * scale,
          bounds_.radius - glm::dot(q, direction_)};
}

LightView::Rows LightView::rows() const {
  const double scale = 0.5 * double(size_) / bounds_.radius;
  const glm::dvec3 c = bounds_.center;
  Rows r{};
  for (int d = 0; d < 3; ++d) {
    r.rowU[d] = float(right_[d] * scale);
    r.rowV[d] = float(-up_[d] * scale);
    r.rowD[d] = float(-direction_[d]);
  }
  r.rowU[3] = float(0.5 * size_ - glm::dot(c, right_) * scale);
  r.rowV[3] = float(0.5 * size_ + glm::dot(c, up_) * scale);
  r.rowD[3] = float(bounds_.radius + glm::dot(c, direction_));
  return r;
}

}  // namespace gridifs
