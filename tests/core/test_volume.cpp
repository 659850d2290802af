// Condensation sets, median functions and the measure attractor (Sokolov & Gentil): the file
// format, voxelization, the median's fixed point, the set iteration's mass, the chaos game with a
// constant condensation and point binning (the OpenVDB file: files/).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "io/project_io.h"
#include "model/project.h"
#include "render/chaos_renderer.h"
#include "render/compiled_ifs.h"
#include "tests/core/volume_scenes.h"
#include "volume/measure_attractor.h"
#include "volume/set_function.h"
#include "volume/set_orbit_memo.h"
#include "volume/set_voxelizer.h"
#include "volume/vdb_volume_file.h"

using namespace gridifs;
using test_support::kTwoMedians;
namespace fs = std::filesystem;

namespace {

struct VolumeFolder {
  fs::path path;
  explicit VolumeFolder(const std::string& name) {
    path = fs::temp_directory_path() / ("gridifs-volume-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~VolumeFolder() { fs::remove_all(path); }
};

/// A closed cube [-h, h]³ as an OBJ, optionally without its top face (open).
void writeCubeOfSize(const fs::path& file, double h, bool open = false) {
  std::ofstream out(file);
  for (int v = 0; v < 8; ++v)
    out << "v " << ((v & 1) ? h : -h) << " " << ((v & 2) ? h : -h) << " " << ((v & 4) ? h : -h) << "\n";
  out << "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\n";
  if (!open) out << "f 2 4 8 6\n";
}

double massInside(const DensityVolume& v, const VoxelSet& set) {
  double m = 0.0;
  for (std::uint32_t voxel : set.voxels) m += v.density[voxel];
  return m;
}

double visitedFraction(const DensityVolume& v, const VoxelSet& set) {
  std::size_t visited = 0;
  for (std::uint32_t voxel : set.voxels) visited += v.density[voxel] > 0.0f;
  return double(visited) / double(set.size());
}

/// The Hausdorff distance between two voxel sets in voxels (Chebyshev metric), by scanning.
int hausdorffVoxels(const VoxelSet& a, const VoxelSet& b) {
  auto oneWay = [](const VoxelSet& from, const VoxelSet& to) {
    int worst = 0;
    for (std::uint32_t u : from.voxels) {
      const Index3 p = from.lattice.coordinates(u);
      int best = 1 << 20;
      for (std::uint32_t w : to.voxels) {
        const Index3 q = to.lattice.coordinates(w);
        best = std::min(best, std::max({std::abs(p[0] - q[0]), std::abs(p[1] - q[1]), std::abs(p[2] - q[2])}));
      }
      worst = std::max(worst, best);
    }
    return worst;
  };
  return std::max(oneWay(a, b), oneWay(b, a));
}

}  // namespace

TEST(VolumeIo, SetFunctionsAndVolumeBlockRoundTrip) {
  const Project p = parseProject(kTwoMedians);
  ASSERT_EQ(p.functions.size(), 2u);
  EXPECT_EQ(p.functions[0].kind, FunctionKind::Median);
  EXPECT_EQ(p.functions[0].set.shape, SetShape::Sphere);
  EXPECT_DOUBLE_EQ(p.functions[0].set.radius, 0.3);
  EXPECT_EQ(p.functions[1].set.shape, SetShape::Box);
  ASSERT_TRUE(p.volume);
  EXPECT_EQ(p.volume->resolution, 32);
  EXPECT_EQ(p.volume->iterations, 200);
  const std::string saved = serializeProject(p);
  EXPECT_EQ(parseProject(saved), p);
  EXPECT_EQ(serializeProject(parseProject(saved)), saved);
}

TEST(VolumeIo, EverySetShapeRoundTrips) {
  const Project p = parseProject(R"({"format": "gridifs", "version": 1, "functions": [
    {"kind": "condensation", "set": {"primitive": "torus", "center": [0, 0, 0.1], "major": 0.4, "minor": 0.1, "axis": [0, 1, 0]}},
    {"kind": "condensation", "set": {"mesh": "tree.obj", "fill": "surface",
      "placement": {"translate": [0.6, 0, 0], "rotate": [0, 0, 30], "scale": [0.3, 0.3, 0.3]}}},
    {"kind": "median", "rotate": 45, "set": {"vdb": "cloud.vdb", "grid": "density", "threshold": 0.25}},
    {"name": "g", "resolution": [2, 2, 2]}]})");
  EXPECT_EQ(p.functions[0].set.shape, SetShape::Torus);
  EXPECT_EQ(p.functions[1].set.fill, SetFill::Surface);
  EXPECT_EQ(p.functions[1].set.placement.rotate.z, 30.0);
  EXPECT_EQ(p.functions[2].set.grid, "density");
  EXPECT_EQ(p.functions[2].rotate, 45.0);
  EXPECT_EQ(p.functions[3].kind, FunctionKind::Grid);
  EXPECT_FALSE(p.volume);
  EXPECT_EQ(parseProject(serializeProject(p)), p);
}

TEST(VolumeIo, BadSetsAreRejectedWithTheirPath) {
  auto error = [](const std::string& functions, const std::string& extra = "") {
    try {
      parseProject(R"({"format": "gridifs", "version": 1, "functions": [)" + functions + "]" + extra + "}");
    } catch (const ModelError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error(R"({"kind": "median"})").find("functions[0].set"), std::string::npos);
  EXPECT_NE(error(R"({"kind": "median", "set": {"primitive": "cone"}})").find("functions[0].set.primitive"),
            std::string::npos);
  EXPECT_NE(error(R"({"kind": "median", "set": {"primitive": "sphere", "radius": -1}})").find("radius"),
            std::string::npos);
  EXPECT_NE(error(R"({"set": {"primitive": "sphere"}})").find("functions[0].set"), std::string::npos);
  EXPECT_NE(error(R"({"kind": "median", "resolution": [2, 2, 2], "set": {"primitive": "sphere"}})").find("resolution"),
            std::string::npos);
  EXPECT_NE(error(R"({"kind": "condensation", "rotate": 3, "set": {"primitive": "sphere"}})").find("rotate"),
            std::string::npos);
  EXPECT_NE(error(R"({"kind": "median", "set": {"mesh": "a.obj", "fill": "hollow"}})").find("fill"), std::string::npos);
  EXPECT_NE(error(R"({"name": "g"})", R"(, "volume": {"resolution": 1024})").find("volume.resolution"),
            std::string::npos);
}

TEST(VolumeSets, PrimitivesKeepTheVoxelsWhoseCentresLieInside) {
  const VoxelLattice lattice{32};
  CondensationSet box;
  box.shape = SetShape::Box;
  box.center = Vec3{0.0};
  box.size = Vec3{0.5};  // centres at ±(1/32 + 2k/32) inside |x| ≤ 0.25: 4 per side of 0 per axis
  const VoxelSet b = voxelizeSet(box, lattice, ".", "set");
  EXPECT_EQ(b.size(), 8u * 8u * 8u);
  CondensationSet sphere;
  sphere.radius = 0.5;
  const VoxelSet s = voxelizeSet(sphere, lattice, ".", "set");
  const double expected = 4.0 / 3.0 * M_PI * std::pow(0.5 * 16, 3);
  EXPECT_NEAR(double(s.size()), expected, 0.05 * expected);
  for (std::uint32_t v : s.voxels) EXPECT_LE(glm::length(lattice.centre(v)), 0.5 + 1e-12);
  CondensationSet outside = sphere;
  outside.center = Vec3{5.0, 0.0, 0.0};
  EXPECT_THROW(voxelizeSet(outside, lattice, ".", "set"), ModelError);
}

TEST(VolumeSets, MeshesAreVoxelizedSolidOrSurface) {
  VolumeFolder folder("mesh");
  writeCubeOfSize(folder.path / "cube.obj", 0.5);
  writeCubeOfSize(folder.path / "open.obj", 0.5, true);
  const VoxelLattice lattice{32};
  CondensationSet set;
  set.shape = SetShape::Mesh;
  set.path = "cube.obj";
  const VoxelSet solid = voxelizeSet(set, lattice, folder.path, "set");
  EXPECT_NEAR(double(solid.size()), 16.0 * 16 * 16, 0.1 * 16 * 16 * 16);
  set.placement.scale = Vec3{0.5};
  set.placement.translate = Vec3{0.5, 0.0, 0.0};
  const VoxelSet small = voxelizeSet(set, lattice, folder.path, "set");
  EXPECT_NEAR(double(small.size()), 8.0 * 8 * 8, 0.15 * 8 * 8 * 8);
  for (std::uint32_t v : small.voxels) EXPECT_GT(lattice.centre(v).x, 0.2);
  set.placement = {};
  set.fill = SetFill::Surface;
  const VoxelSet shell = voxelizeSet(set, lattice, folder.path, "set");
  EXPECT_GT(shell.size(), 6u * 14u * 14u);
  EXPECT_LT(shell.size(), solid.size());
  // An open mesh has no inside: solid is refused, naming the file, surface works.
  set.path = "open.obj";
  EXPECT_NO_THROW(voxelizeSet(set, lattice, folder.path, "set"));
  set.fill = SetFill::Solid;
  try {
    voxelizeSet(set, lattice, folder.path, "functions[0].set");
    FAIL() << "an open mesh was filled";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("open.obj"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("not closed"), std::string::npos);
  }
  set.path = "missing.obj";
  try {
    voxelizeSet(set, lattice, folder.path, "functions[0].set");
    FAIL() << "a missing mesh was read";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.obj"), std::string::npos);
  }
}

TEST(VolumeSets, VdbGridsAreThresholded) {
  VolumeFolder folder("vdbset");
  DensityVolume v{VoxelLattice{16}, std::vector<float>(16 * 16 * 16, 0.0f), {}, 0.0};
  for (int k = 4; k < 8; ++k)
    for (int j = 4; j < 8; ++j)
      for (int i = 4; i < 8; ++i) v.density[v.lattice.index(i, j, k)] = 1.0f;
  writeVdbVolume(v, folder.path / "cube.vdb");
  CondensationSet set;
  set.shape = SetShape::Vdb;
  set.path = "cube.vdb";
  set.threshold = 0.99;
  const VoxelSet same = voxelizeSet(set, v.lattice, folder.path, "set");
  EXPECT_EQ(same.size(), 64u);
  set.threshold = 0.5;  // trilinear samples between the grid's voxels: half-way is the edge
  const VoxelSet finer = voxelizeSet(set, VoxelLattice{32}, folder.path, "set");
  EXPECT_NEAR(double(finer.size()), 512.0, 200.0);
  set.grid = "nothing";
  try {
    voxelizeSet(set, v.lattice, folder.path, "functions[1].set");
    FAIL() << "a missing grid was read";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("nothing"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("functions[1].set.grid"), std::string::npos);
  }
}

// Sokolov & Gentil, §3.2: f_C(C) = M(C, C) = C, voxel for voxel — also for the rotated median.
TEST(MedianFunction, ItsSetIsItsFixedPoint) {
  const VoxelLattice lattice{48};
  for (SetShape shape : {SetShape::Sphere, SetShape::Box, SetShape::Torus}) {
    CondensationSet set;
    set.shape = shape;
    set.center = Vec3{0.2, -0.1, 0.05};
    set.radius = 0.4;
    set.size = Vec3{0.5, 0.3, 0.7};
    const VoxelSet c = voxelizeSet(set, lattice, ".", "set");
    for (double rotate : {0.0, 90.0}) {
      const SetFunction f = SetFunction::median(c, rotate);
      VoxelSet image;
      SetScratch scratch;
      f.apply(c, image, scratch, 2);
      normalizeVoxels(image.voxels);
      EXPECT_EQ(image.voxels, c.voxels) << setShapeName(shape) << " rotate " << rotate;
    }
  }
}

// Iterating f_C from another set converges to C (the contraction of §3.2).
TEST(MedianFunction, IterationMorphsAnySetIntoItsSet) {
  const VoxelLattice lattice{32};
  CondensationSet a, b;
  a.center = Vec3{-0.5, 0.0, 0.0};
  a.radius = 0.3;
  b.shape = SetShape::Box;
  b.center = Vec3{0.5, 0.2, 0.0};
  b.size = Vec3{0.4};
  const VoxelSet target = voxelizeSet(b, lattice, ".", "set");
  VoxelSet current = voxelizeSet(a, lattice, ".", "set"), next;
  const SetFunction f = SetFunction::median(target, 0.0);
  SetScratch scratch;
  for (int k = 0; k < 12; ++k) {
    f.apply(current, next, scratch, 1);
    std::swap(current, next);
  }
  // Within one voxel of C (the discrete midpoints round), from a set two units of X away.
  EXPECT_LE(hausdorffVoxels(current, target), 1);
  const std::size_t before = current.size();
  EXPECT_NEAR(double(before), double(target.size()), 0.2 * double(target.size()));
}

// Two median functions A (weight 2) and B (weight 1): density inside both, more mass at A.
TEST(MeasureAttractor, TwoMediansPutMoreMassAtTheHeavierSet) {
  const Project p = parseProject(kTwoMedians);
  VolumeJob job;
  job.settings = *p.volume;
  job.settings.iterations = 1000;
  job.threads = 2;
  const DensityVolume v = computeDensityVolume(p, job);
  ASSERT_EQ(v.density.size(), 32u * 32u * 32u);
  const VoxelSet a = voxelizeSet(p.functions[0].set, v.lattice, ".", "a");
  const VoxelSet b = voxelizeSet(p.functions[1].set, v.lattice, ".", "b");
  // The iteration visits (nearly) every voxel of both sets: the discrete median converges to its
  // set up to boundary voxels that rounding may leave out of a short run.
  EXPECT_GT(visitedFraction(v, a), 0.97);
  EXPECT_GT(visitedFraction(v, b), 0.9);
  EXPECT_GT(massInside(v, a), 1.3 * massInside(v, b));
  float largest = 0.0f;
  for (float d : v.density) largest = std::max(largest, d);
  EXPECT_FLOAT_EQ(largest, 1.0f);
  // The functions have different colours: a colour volume, blue-ish inside B.
  ASSERT_EQ(v.color.size(), v.density.size() * 3);
  const std::uint32_t inB = b.voxels[b.size() / 2];
  EXPECT_GT(v.color[3 * inB + 2], v.color[3 * inB + 0]);
  // The same seed gives the same volume.
  EXPECT_EQ(computeDensityVolume(p, job).density, v.density);
}

// Nearest-voxel ties are broken the same way however the queries are shared among threads, so
// the set iteration gives the same volume on one thread and on four.
TEST(MeasureAttractor, SetIterationIsTheSameOnAnyNumberOfThreads) {
  const Project p = parseProject(kTwoMedians);
  VolumeJob job;
  job.settings = *p.volume;
  job.settings.resolution = 96;
  job.settings.iterations = 60;
  job.threads = 1;
  const DensityVolume one = computeDensityVolume(p, job);
  job.threads = 4;
  EXPECT_EQ(computeDensityVolume(p, job).density, one.density);
}

// A median function and a constant condensation: every time the constant map is picked the
// orbit returns to C and repeats sets it has seen (looked up, not recomputed); the volume holds
// all of C and most of A, the same on every run.
TEST(MeasureAttractor, MedianAndConstantCondensationCoverBothSets) {
  Project p = parseProject(R"({"format": "gridifs", "version": 1, "functions": [
    {"name": "A", "kind": "median", "weight": 1, "set": {"primitive": "sphere", "center": [0.5, 0, 0], "radius": 0.3}},
    {"name": "C", "kind": "condensation", "weight": 1, "set": {"primitive": "box", "center": [-0.5, 0, 0], "size": [0.4, 0.4, 0.4]}}]})");
  VolumeJob job;
  job.settings.resolution = 32;
  job.settings.iterations = 400;
  job.settings.skip = 0;
  job.threads = 2;
  const DensityVolume v = computeDensityVolume(p, job);
  const VoxelSet a = voxelizeSet(p.functions[0].set, v.lattice, ".", "a");
  const VoxelSet c = voxelizeSet(p.functions[1].set, v.lattice, ".", "c");
  EXPECT_EQ(visitedFraction(v, c), 1.0);
  EXPECT_GT(visitedFraction(v, a), 0.9);
  EXPECT_EQ(computeDensityVolume(p, job).density, v.density);
}

TEST(SetOrbitMemo, InternsEqualSetsOnceAndRemembersImages) {
  const VoxelLattice lattice{16};
  SetOrbitMemo memo(2, 1 << 20);
  const VoxelSet x{lattice, {1, 5, 9}}, y{lattice, {1, 5, 10}};
  const int ix = memo.intern(x), iy = memo.intern(y);
  EXPECT_NE(ix, iy);
  EXPECT_EQ(memo.intern(VoxelSet{lattice, {1, 5, 9}}), ix);
  EXPECT_EQ(memo.set(iy), y);
  EXPECT_EQ(memo.image(ix, 1), SetOrbitMemo::kNone);
  memo.rememberImage(ix, 1, iy);
  EXPECT_EQ(memo.image(ix, 1), iy);
  EXPECT_EQ(memo.image(ix, 0), SetOrbitMemo::kNone);
  EXPECT_EQ(memo.setCount(), 2u);
  // Past the byte budget new sets are not kept; known ones are still found.
  SetOrbitMemo small(1, 3 * sizeof(std::uint32_t));
  EXPECT_EQ(small.intern(x), 0);
  EXPECT_EQ(small.intern(y), SetOrbitMemo::kNone);
  EXPECT_EQ(small.intern(x), 0);
}

// Barnsley's condensation (Sokolov & Gentil, §3.1, fig. 4): f(p) = p/2 and a ball C; every
// chaos-game point lies in one of the balls 2^-n·C.
TEST(MeasureAttractor, ConstantCondensationGivesAGeometricSeriesOfBalls) {
  Project p = defaultNewProject();  // one grid scaled by one half about the origin
  Function c;
  c.name = "ball";
  c.kind = FunctionKind::Condensation;
  c.set.center = Vec3{0.6, 0.2, 0.0};
  c.set.radius = 0.25;
  p.functions.push_back(c);
  p.functions[0].placement.translate = Vec3{0.0};
  // Point test through the chaos kernel itself.
  const auto ifs = compileIfs(p);
  ASSERT_EQ(ifs->functions.size(), 2u);
  ASSERT_FALSE(ifs->functions[1].points.empty());
  VolumeJob job;
  job.settings.resolution = 64;
  job.settings.samples = 400'000;
  job.threads = 2;
  const DensityVolume v = computeDensityVolume(p, job);
  const double slack = std::sqrt(3.0) / 64.0;  // half a voxel diagonal
  int occupied = 0;
  for (std::uint32_t voxel = 0; voxel < v.density.size(); ++voxel) {
    if (v.density[voxel] == 0.0f) continue;
    ++occupied;
    const Vec3 q = v.lattice.centre(voxel);
    bool inBall = false;
    for (int n = 0; n < 30 && !inBall; ++n) {
      const double s = std::ldexp(1.0, -n);
      inBall = glm::length(q - s * c.set.center) <= s * c.set.radius + slack;
    }
    EXPECT_TRUE(inBall) << "voxel at " << q.x << " " << q.y << " " << q.z;
  }
  EXPECT_GT(occupied, 1000);
  // The largest ball (C itself) is reached: a voxel at its centre is occupied.
  EXPECT_GT(v.density[v.lattice.index(int(std::floor((0.6 + 1) * 32)), int(std::floor((0.2 + 1) * 32)), 32)], 0.0f);
}

// Point binning: the Sierpinski tetrahedron's 64³ density is zero in its central octahedron and
// outside its hull, non-zero at its corners.
TEST(MeasureAttractor, SierpinskiDensityIsZeroAwayFromTheAttractor) {
  const Project p = loadProject(fs::path(GRIDIFS_ASSETS) / "sierpinski_tetrahedron.gridifs");
  VolumeJob job;
  job.settings.resolution = 64;
  job.settings.samples = 2'000'000;
  job.threads = 2;
  const DensityVolume v = computeDensityVolume(p, job);
  int nonZero = 0;
  for (std::uint32_t voxel = 0; voxel < v.density.size(); ++voxel) {
    const Vec3 q = v.lattice.centre(voxel);
    const double l1 = std::abs(q.x) + std::abs(q.y) + std::abs(q.z);
    // Outside the hull: some face plane x+y+z ≥ -1 style inequality is violated.
    const bool outsideHull =
        q.x + q.y + q.z < -1.1 || q.x - q.y - q.z < -1.1 || -q.x + q.y - q.z < -1.1 || -q.x - q.y + q.z < -1.1;
    if (l1 < 0.9 || outsideHull) {
      EXPECT_EQ(v.density[voxel], 0.0f) << q.x << " " << q.y << " " << q.z;
    }
    nonZero += v.density[voxel] > 0.0f;
  }
  EXPECT_GT(nonZero, 500);
  EXPECT_GT(v.at(63, 63, 63), 0.0f);
}
