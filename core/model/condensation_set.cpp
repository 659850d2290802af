#include "model/condensation_set.h"

#include <cmath>
#include <glm/geometric.hpp>

#include "base/hash.h"

namespace gridifs {

const char* setShapeName(SetShape shape) {
  switch (shape) {
    case SetShape::Sphere:
      return "sphere";
    case SetShape::Box:
      return "box";
    case SetShape::Torus:
      return "torus";
    case SetShape::Mesh:
      return "mesh";
    case SetShape::Vdb:
      return "vdb";
    case SetShape::Image:
      return "image";
  }
  return "sphere";
}

const char* setFillName(SetFill fill) { return fill == SetFill::Surface ? "surface" : "solid"; }

bool primitiveContains(const CondensationSet& set, const Vec3& p) {
  const Vec3 d = p - set.center;
  switch (set.shape) {
    case SetShape::Sphere:
      return glm::dot(d, d) <= set.radius * set.radius;
    case SetShape::Box:
      return std::abs(d.x) <= 0.5 * set.size.x && std::abs(d.y) <= 0.5 * set.size.y &&
             std::abs(d.z) <= 0.5 * set.size.z;
    case SetShape::Torus: {
      const Vec3 a = glm::normalize(set.axis);
      const double h = glm::dot(d, a);
      const double r = glm::length(d - h * a) - set.major;
      return r * r + h * h <= set.minor * set.minor;
    }
    case SetShape::Mesh:
    case SetShape::Vdb:
    case SetShape::Image:
      break;
  }
  return false;
}

Vec3 primitiveHalfExtent(const CondensationSet& set) {
  switch (set.shape) {
    case SetShape::Sphere:
      return Vec3{set.radius};
    case SetShape::Box:
      return 0.5 * set.size;
    case SetShape::Torus:
      return Vec3{set.major + set.minor};
    case SetShape::Mesh:
    case SetShape::Vdb:
    case SetShape::Image:
      break;
  }
  return Vec3{0.0};
}

std::vector<Vec3> samplePrimitive(const CondensationSet& set, std::size_t count, std::uint64_t seed) {
  std::vector<Vec3> out;
  if (set.shape == SetShape::Mesh || set.shape == SetShape::Vdb || set.shape == SetShape::Image) return out;
  const Vec3 half = primitiveHalfExtent(set);
  out.reserve(count);
  std::uint64_t state = seed;
  auto unit = [&] { return double(splitmix64(state++) >> 11) * (2.0 / 9007199254740992.0) - 1.0; };
  // Rejection keeps at least 1 in 40 candidates for any torus that fits its checks; the cap
  // only guards against a degenerate set.
  for (std::size_t tries = 0; out.size() < count && tries < count * 1000; ++tries) {
    const Vec3 p = set.center + half * Vec3{unit(), unit(), unit()};
    if (primitiveContains(set, p)) out.push_back(p);
  }
  return out;
}

}  // namespace gridifs
