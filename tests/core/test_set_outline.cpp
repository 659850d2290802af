// The line drawings of condensation sets that the modeller shows: a box's 12 edges at its
// corners, circles on the sphere and the torus, a mesh's placed edges (capped), the outline of a
// voxel set, and the voxelizer's error for a set that cannot be drawn.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <set>

#include "mesh/mesh_io.h"
#include "volume/set_outline.h"

using namespace gridifs;
namespace fs = std::filesystem;

namespace {

struct Folder {
  fs::path path = fs::temp_directory_path() / ("gridifs-outline-" + std::to_string(::getpid()));
  Folder() { fs::create_directories(path); }
  ~Folder() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

/// A unit cube [-1, 1]³ as six quads: 8 vertices, 12 edges.
void writeCube(const fs::path& file) {
  std::ofstream out(file);
  for (int k = 0; k < 8; ++k)
    out << "v " << (k & 1 ? 1 : -1) << ' ' << (k & 2 ? 1 : -1) << ' ' << (k & 4 ? 1 : -1) << "\n";
  out << "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
}

std::size_t segments(const LineSegments& s) { return s.size() / 2; }

}  // namespace

TEST(SetOutline, ABoxIsTwelveEdgesBetweenItsCorners) {
  CondensationSet box;
  box.shape = SetShape::Box;
  box.center = Vec3{0.1, -0.2, 0.3};
  box.size = Vec3{0.4, 0.6, 0.8};
  const LineSegments lines = primitiveOutline(box);
  ASSERT_EQ(segments(lines), 12u);
  std::set<std::tuple<long, long, long>> corners;
  for (std::size_t s = 0; s < segments(lines); ++s) {
    const Vec3 a = lines[2 * s], b = lines[2 * s + 1];
    // Each edge runs along one axis, its full edge length.
    const Vec3 d = glm::abs(b - a);
    const int along = d.x > 1e-12 ? 0 : d.y > 1e-12 ? 1 : 2;
    EXPECT_NEAR(d[along], box.size[along], 1e-12);
    EXPECT_NEAR(d.x + d.y + d.z, box.size[along], 1e-12) << "edge " << s << " is not parallel to an axis";
    for (const Vec3& p : {a, b}) {
      for (int axis = 0; axis < 3; ++axis)
        EXPECT_NEAR(std::abs(p[axis] - box.center[axis]), 0.5 * box.size[axis], 1e-12);
      corners.insert({std::lround(p.x * 1e6), std::lround(p.y * 1e6), std::lround(p.z * 1e6)});
    }
  }
  EXPECT_EQ(corners.size(), 8u);  // every corner, each the end of three edges
}

TEST(SetOutline, SphereAndTorusLinesLieOnTheirSurfaces) {
  CondensationSet sphere;
  sphere.center = Vec3{0.2, 0.0, -0.1};
  sphere.radius = 0.3;
  const LineSegments s = primitiveOutline(sphere, 40);
  EXPECT_EQ(segments(s), 3u * 40u);
  for (const Vec3& p : s) EXPECT_NEAR(glm::length(p - sphere.center), 0.3, 1e-12);

  CondensationSet torus;
  torus.shape = SetShape::Torus;
  torus.center = Vec3{0.0, 0.1, 0.0};
  torus.major = 0.5;
  torus.minor = 0.1;
  torus.axis = Vec3{1.0, 1.0, 0.0};
  const LineSegments t = primitiveOutline(torus, 40);
  EXPECT_EQ(segments(t), 4u * 40u + 8u * 20u);
  const Vec3 a = glm::normalize(torus.axis);
  for (const Vec3& p : t) {
    const Vec3 d = p - torus.center;
    const double h = glm::dot(d, a);
    const double r = glm::length(d - h * a) - torus.major;
    EXPECT_NEAR(std::sqrt(r * r + h * h), torus.minor, 1e-9) << "a torus line leaves its surface";
  }
  CondensationSet mesh;
  mesh.shape = SetShape::Mesh;
  EXPECT_TRUE(primitiveOutline(mesh).empty());
}

TEST(SetOutline, AMeshIsItsPlacedEdgesCappedForHugeMeshes) {
  Folder folder;
  writeCube(folder.path / "cube.obj");
  CondensationSet set;
  set.shape = SetShape::Mesh;
  set.path = "cube.obj";
  set.placement.scale = Vec3{0.25};
  set.placement.translate = Vec3{0.5, 0.0, 0.0};
  const LineSegments lines = setOutline(set, folder.path, "functions[0].set");
  ASSERT_EQ(segments(lines), 12u);
  for (const Vec3& p : lines) {
    EXPECT_NEAR(std::abs(p.x - 0.5), 0.25, 1e-6);
    EXPECT_NEAR(std::abs(p.y), 0.25, 1e-6);
    EXPECT_NEAR(std::abs(p.z), 0.25, 1e-6);
  }
  const IfsMesh cube = readMeshFile(folder.path / "cube.obj");
  EXPECT_EQ(segments(meshOutline(cube, {}, 5)), 4u);  // every third edge of 12

  // What the voxelizer refuses is refused here, with its sentence naming the file.
  set.path = "missing.obj";
  try {
    setOutline(set, folder.path, "functions[0].set");
    FAIL() << "a missing mesh was drawn";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.obj"), std::string::npos) << e.what();
  }
  set.path = "cube.obj";
  set.placement.translate = Vec3{5.0, 0.0, 0.0};
  EXPECT_THROW(setOutline(set, folder.path, "functions[0].set"), ModelError) << "a set outside X was drawn";
}

TEST(SetOutline, VoxelOutlinesAreTheEdgesOfTheBoundaryFaces) {
  const VoxelLattice lattice{8};
  VoxelSet one{lattice, {lattice.index(3, 4, 5)}};
  const LineSegments cube = voxelOutline(one, 0);
  ASSERT_EQ(segments(cube), 12u);
  for (const Vec3& p : cube) {
    EXPECT_TRUE(std::abs(p.x - (-1.0 + 0.25 * 3)) < 1e-12 || std::abs(p.x - (-1.0 + 0.25 * 4)) < 1e-12);
    EXPECT_TRUE(std::abs(p.z - (-1.0 + 0.25 * 5)) < 1e-12 || std::abs(p.z - (-1.0 + 0.25 * 6)) < 1e-12);
  }
  // Two voxels side by side: a 2×1×1 box whose surface has 20 unit edges (8 along its length).
  VoxelSet two{lattice, {lattice.index(3, 4, 5), lattice.index(4, 4, 5)}};
  EXPECT_EQ(segments(voxelOutline(two, 0)), 20u);
  // A solid 4³ block: only its surface is outlined, none of the edges inside it.
  VoxelSet block{lattice, {}};
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) block.voxels.push_back(lattice.index(i, j, k));
  // Per axis, the 4a lines along it on the surface, each a unit edges long: 3 · 4a · a.
  EXPECT_EQ(segments(voxelOutline(block, 0)), 3u * 4u * 16u);
  EXPECT_LE(segments(voxelOutline(block, 50)), 50u);
}
