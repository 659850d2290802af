#include "model/condensation_set.h"

#include <cmath>
#include <glm/geometric.hpp>

#include "base/hash.h"

namespace gridifs {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& message) { throw ModelError(path, message); }

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

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

void checkCondensationSet(const CondensationSet& set, const std::string& path) {
  switch (set.shape) {
    case SetShape::Sphere:
      if (!finite(set.center)) fail(path + ".center", "expected finite coordinates");
      if (!(set.radius > 0.0 && set.radius <= 10.0)) fail(path + ".radius", "expected a radius between 0 and 10");
      break;
    case SetShape::Box:
      if (!finite(set.center)) fail(path + ".center", "expected finite coordinates");
      for (int d = 0; d < 3; ++d)
        if (!(set.size[d] > 0.0 && set.size[d] <= 20.0))
          fail(path + ".size[" + std::to_string(d) + "]", "expected an edge length between 0 and 20");
      break;
    case SetShape::Torus:
      if (!finite(set.center)) fail(path + ".center", "expected finite coordinates");
      if (!(set.major > 0.0 && set.major <= 10.0)) fail(path + ".major", "expected a radius between 0 and 10");
      if (!(set.minor > 0.0 && set.minor <= 10.0)) fail(path + ".minor", "expected a radius between 0 and 10");
      if (!finite(set.axis) || glm::length(set.axis) < 1e-9) fail(path + ".axis", "expected a non-zero axis");
      break;
    case SetShape::Image:
      if (set.path.empty()) fail(path + ".image", "expected a file name");
      if (!(set.threshold >= 0.0 && set.threshold <= 1.0))
        fail(path + ".threshold", "expected a number between 0 and 1");
      if (!(set.thickness > 0.0 && set.thickness <= 2.0))
        fail(path + ".thickness", "expected a thickness between 0 and 2");
      [[fallthrough]];
    case SetShape::Mesh:
    case SetShape::Vdb:
      if (set.path.empty()) fail(path + (set.shape == SetShape::Mesh ? ".mesh" : ".vdb"), "expected a file name");
      if (set.shape == SetShape::Vdb && set.grid.empty()) fail(path + ".grid", "expected a grid name");
      if (set.shape == SetShape::Vdb && !std::isfinite(set.threshold))
        fail(path + ".threshold", "expected a finite number");
      if (set.shape == SetShape::Mesh || set.shape == SetShape::Image) {
        const Placement& p = set.placement;
        if (!finite(p.translate) || !finite(p.rotate) || !finite(p.scale))
          fail(path + ".placement", "expected finite numbers");
        for (int d = 0; d < 3; ++d)
          if (p.scale[d] == 0.0) fail(path + ".placement.scale", "a zero scale flattens the mesh");
      }
      break;
  }
}

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
