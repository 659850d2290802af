#pragma once
// A condensation set C ⊂ X (Sokolov & Gentil, §3.1–3.2): a built-in primitive, a mesh file placed
// in X, a level set of a VDB grid, or a drawing (the paper's black-ink sketches) as a thin slab. Only the description;
// voxelization lives in volume/.
#include <cstdint>
#include <string>
#include <vector>

#include "model/placement.h"

namespace gridifs {

enum class SetShape { Sphere, Box, Torus, Mesh, Vdb, Image };

/// "fill" of a mesh set: the enclosed volume or the surface alone.
enum class SetFill { Solid, Surface };

struct CondensationSet {
  SetShape shape = SetShape::Sphere;
  Vec3 center{0.0};
  double radius = 0.5;       // sphere
  Vec3 size{1.0};            // box: full edge lengths
  double major = 0.5;        // torus: distance from the centre to the tube's centre line
  double minor = 0.15;       // torus: tube radius
  Vec3 axis{0.0, 0.0, 1.0};  // torus: the axis of revolution
  std::string path;          // mesh or VDB file, relative to the project file
  SetFill fill = SetFill::Solid;
  Placement placement;           // mesh: placement(q) = T + R·(S·q)
  std::string grid = "density";  // VDB: the grid's name
  double threshold = 0.5;        // VDB: voxels whose value is at least this belong to the set;
                                 // image: pixels darker than this (after `invert`) belong to it
  double thickness = 0.05;       // image: the slab's thickness along z (placed like a mesh)
  bool invert = false;           // image: light pixels belong to the set instead of dark ones
  bool operator==(const CondensationSet&) const = default;
};

const char* setShapeName(SetShape shape);
const char* setFillName(SetFill fill);

/// Half the edge lengths of the primitive set's bounding box about its centre (a torus's is a
/// cube: its axis may point anywhere). Zero for file sets.
Vec3 primitiveHalfExtent(const CondensationSet& set);

/// Whether the primitive set (sphere, box, torus) contains `p`, boundary included. False for file sets.
bool primitiveContains(const CondensationSet& set, const Vec3& p);

/// `count` points uniformly distributed in the primitive set's volume (rejection sampling in its
/// bounding box), the same for the same seed. Empty for file sets.
std::vector<Vec3> samplePrimitive(const CondensationSet& set, std::size_t count, std::uint64_t seed);

}  // namespace gridifs
