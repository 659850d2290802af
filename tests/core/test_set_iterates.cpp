// The deterministic algorithm over sets and the book of drawings (Sokolov & Gentil, §3.3), drawings
// as condensation sets, and the rotated median about any axis (§4.1).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "io/project_io.h"
#include "render/image_file.h"
#include "volume/set_function.h"
#include "volume/set_iterates.h"
#include "volume/set_voxelizer.h"
#include "volume/volume_points.h"

using namespace gridifs;
namespace fs = std::filesystem;

namespace {

VoxelSet ball(const VoxelLattice& lattice, Vec3 centre, double radius) {
  CondensationSet s;
  s.shape = SetShape::Sphere;
  s.center = centre;
  s.radius = radius;
  return voxelizeSet(s, lattice, ".", "set");
}

VoxelSet cube(const VoxelLattice& lattice, Vec3 centre, double size) {
  CondensationSet s;
  s.shape = SetShape::Box;
  s.center = centre;
  s.size = Vec3{size};
  return voxelizeSet(s, lattice, ".", "set");
}

VoxelSet apply(const SetFunction& f, const VoxelSet& in) {
  VoxelSet out;
  SetScratch scratch;
  f.apply(in, out, scratch, 1);
  return out;
}

SetSystem twoMedians(const VoxelLattice& lattice) {
  SetSystem system;
  system.lattice = lattice;
  system.functions.push_back(SetFunction::median(ball(lattice, {-0.5, 0.0, 0.0}, 0.3), 0.0));
  system.functions.push_back(SetFunction::median(cube(lattice, {0.5, 0.2, 0.0}, 0.4), 0.0));
  system.sources = {0, 1};
  system.weights = {1.0, 1.0};
  return system;
}

struct SetIterateFolder {
  fs::path path;
  explicit SetIterateFolder(const std::string& name) {
    path = fs::temp_directory_path() / ("gridifs-setiter-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~SetIterateFolder() { fs::remove_all(path); }
};

}  // namespace

TEST(SetIterates, DeterministicAlgorithmEqualsTheUnionOfImagesStepByStep) {
  const VoxelLattice lattice{16};
  const SetSystem system = twoMedians(lattice);
  const VoxelSet start = ball(lattice, {0.0, -0.4, 0.3}, 0.35);
  // A_1 = f_A(S) ∪ f_B(S), A_2 = f_A(A_1) ∪ f_B(A_1), computed here one map at a time.
  const VoxelSet a1 = unite(apply(system.functions[0], start), apply(system.functions[1], start));
  const VoxelSet a2 = unite(apply(system.functions[0], a1), apply(system.functions[1], a1));
  EXPECT_EQ(iterateSets(system, start, 0, 1), start);
  EXPECT_EQ(iterateSets(system, start, 1, 1), a1);
  EXPECT_EQ(iterateSets(system, start, 2, 2), a2);
  EXPECT_NE(a1, a2);
  // A median of a union is not the union of medians, so the condensation sets need not stay in
  // every iterate (only M(C, C) = C is sure); the iterates stay non-empty.
  EXPECT_FALSE(iterateSets(system, start, 6, 2).empty());
}

TEST(SetIterates, ConstantMapsMakeTheCondensationSetFromTheFirstStep) {
  const VoxelLattice lattice{16};
  SetSystem system;
  system.lattice = lattice;
  const VoxelSet c1 = ball(lattice, {-0.5, 0.0, 0.0}, 0.3), c2 = cube(lattice, {0.5, 0.0, 0.0}, 0.3);
  system.functions.push_back(SetFunction::constant(c1));
  system.functions.push_back(SetFunction::constant(c2));
  const VoxelSet all = startSet(Project{}, lattice, ".");
  EXPECT_EQ(all.size(), lattice.voxelCount());
  EXPECT_EQ(iterateSets(system, all, 3, 1), unite(c1, c2));
}

TEST(SetIterates, PagesAreNumberedByTheirAddressWithTheOutermostMapFirst) {
  const VoxelLattice lattice{16};
  SetSystem system;
  system.lattice = lattice;
  const VoxelSet a = ball(lattice, {-0.5, 0.0, 0.0}, 0.3), c = cube(lattice, {0.5, 0.3, 0.0}, 0.4);
  system.functions.push_back(SetFunction::median(a, 0.0));  // σ = 0
  system.functions.push_back(SetFunction::constant(c));     // σ = 1
  const VoxelSet start = ball(lattice, {0.0, -0.5, 0.0}, 0.3);
  std::map<std::int64_t, VoxelSet> pages;
  forEachBookPage(system, start, 2, 1,
                  [&](std::int64_t n, const VoxelSet& s) { EXPECT_TRUE(pages.emplace(n, s).second); });
  ASSERT_EQ(pages.size(), 4u);
  const SetFunction& fA = system.functions[0];
  // Page σ1σ2 is f_σ1(f_σ2(S)), numbered σ1·2 + σ2.
  EXPECT_EQ(pages[0], apply(fA, apply(fA, start)));
  EXPECT_EQ(pages[1], apply(fA, c));
  EXPECT_EQ(pages[2], c);
  EXPECT_EQ(pages[3], c);
  EXPECT_NE(pages[0], pages[1]);
  EXPECT_EQ(bookPageCount(2, 6, 4096), 64);
  EXPECT_EQ(bookPageCount(3, 8, 4096), -1);
  EXPECT_EQ(bookPageCount(2, 12, 4096), 4096);
  EXPECT_EQ(bookPageCount(2, 13, 4096), -1);
}

TEST(SetIterates, TwoMediansBookMorphsOneSetIntoTheOther) {
  // Sokolov & Gentil, figure 8: sorted by address, the pages go from A to B.
  const VoxelLattice lattice{32};
  const SetSystem system = twoMedians(lattice);
  std::map<std::int64_t, double> centreX;
  forEachBookPage(system, startSet(Project{}, lattice, "."), 4, 2,
                  [&](std::int64_t n, const VoxelSet& s) { centreX[n] = latticeCentroid(s).x; });
  ASSERT_EQ(centreX.size(), 16u);
  EXPECT_LT(centreX[0], centreX[15]);
  EXPECT_LT(centreX[0], centreX[8]);
  EXPECT_LT(centreX[7], centreX[15]);
  // Page 0 is f_A applied four times: next to A's centre (x = -0.5 is lattice 8).
  EXPECT_NEAR(centreX[0], 7.5, 2.0);
}

TEST(SetIterates, DensityVolumeAndItsPoints) {
  const VoxelLattice lattice{16};
  const VoxelSet set = ball(lattice, {0.2, 0.0, 0.0}, 0.4);
  const DensityVolume volume = setDensityVolume(set);
  double mass = 0.0;
  for (float d : volume.density) mass += d;
  EXPECT_EQ(mass, double(set.size()));
  const std::vector<Vec3> points = sampleDensityVolume(volume, 2000, 7);
  ASSERT_EQ(points.size(), 2000u);
  EXPECT_EQ(points, sampleDensityVolume(volume, 2000, 7));
  for (const Vec3& p : points) {
    const int i = int(std::floor((p.x + 1.0) * 8.0)), j = int(std::floor((p.y + 1.0) * 8.0)),
              k = int(std::floor((p.z + 1.0) * 8.0));
    EXPECT_TRUE(std::binary_search(set.voxels.begin(), set.voxels.end(), lattice.index(i, j, k)));
  }
  EXPECT_TRUE(sampleDensityVolume(setDensityVolume(VoxelSet{lattice, {}}), 10, 1).empty());
  Project project = defaultNewProject();
  project.functions.front().color = Vec3{0.0, 0.5, 1.0};
  const auto ifs = compileVolumePoints(project, volume, 1000);
  ASSERT_EQ(ifs->functions.size(), 1u);
  EXPECT_EQ(ifs->functions[0].points.size(), 4000u);
  EXPECT_FLOAT_EQ(ifs->functions[0].color[2], 1.0f);
}

TEST(SetIterates, RotatedMedianAboutAnAxis) {
  const VoxelLattice lattice{24};
  const VoxelSet c = cube(lattice, {0.4, 0.0, 0.0}, 0.4), b = ball(lattice, {-0.4, 0.0, 0.3}, 0.3);
  const VoxelSet plain = apply(SetFunction::median(c, 0.0), b);
  const VoxelSet aboutZ = apply(SetFunction::median(c, 60.0), b);
  EXPECT_EQ(aboutZ, apply(SetFunction::median(c, 60.0, Vec3{0.0, 0.0, 1.0}), b));
  EXPECT_EQ(aboutZ, apply(SetFunction::median(c, 60.0, Vec3{0.0, 0.0, 3.0}), b));  // any length
  const VoxelSet aboutX = apply(SetFunction::median(c, 60.0, Vec3{1.0, 0.0, 0.0}), b);
  EXPECT_NE(aboutZ, plain);
  EXPECT_NE(aboutX, aboutZ);
  // About z the median's z extent stays; about x it turns in the y-z plane, so its x extent stays.
  auto extent = [&](const VoxelSet& s, int d) {
    int lo = 1 << 30, hi = -1;
    for (std::uint32_t v : s.voxels) {
      lo = std::min(lo, lattice.coordinates(v)[std::size_t(d)]);
      hi = std::max(hi, lattice.coordinates(v)[std::size_t(d)]);
    }
    return hi - lo;
  };
  EXPECT_EQ(extent(aboutZ, 2), extent(plain, 2));
  EXPECT_NEAR(extent(aboutX, 0), extent(plain, 0), 1);
}

TEST(SetIterates, DrawingIsASlabOfItsDarkPixels) {
  SetIterateFolder dir("drawing");
  // 20 × 10: black on the left half, white on the right; fitted into [-1, 1] × [-0.5, 0.5].
  std::vector<std::uint8_t> pixels(20 * 10 * 3, 255);
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 10; ++x)
      for (int c = 0; c < 3; ++c) pixels[std::size_t((y * 20 + x) * 3 + c)] = 0;
  ImageFileLayout layout;
  layout.width = 20;
  layout.height = 10;
  layout.channels = {"R", "G", "B"};
  writeImageFile(dir.path / "half.png", layout, pixels.data());
  const GreyImage grey = readGreyImage(dir.path / "half.png");
  EXPECT_EQ(grey.width, 20);
  EXPECT_EQ(grey.height, 10);

  CondensationSet set;
  set.shape = SetShape::Image;
  set.path = "half.png";
  set.thickness = 0.25;
  const VoxelLattice lattice{32};
  const VoxelSet dark = voxelizeSet(set, lattice, dir.path, "set");
  ASSERT_FALSE(dark.empty());
  for (std::uint32_t v : dark.voxels) {
    const Vec3 p = lattice.centre(v);
    EXPECT_LT(p.x, 0.0);
    EXPECT_LE(std::abs(p.y), 0.5);
    EXPECT_LE(std::abs(p.z), 0.125);
  }
  // 16 columns × 16 rows × 4 layers (z = ±1/32, ±3/32; ±5/32 is outside the slab).
  EXPECT_EQ(dark.size(), 16u * 16u * 4u);
  set.invert = true;
  const VoxelSet light = voxelizeSet(set, lattice, dir.path, "set");
  EXPECT_EQ(light.size(), dark.size());
  for (std::uint32_t v : light.voxels) EXPECT_GT(lattice.centre(v).x, 0.0);
  // Thinner than a voxel: still the two middle layers (z = ±1/32), not nothing.
  set.thickness = 0.001;
  EXPECT_EQ(voxelizeSet(set, lattice, dir.path, "set").size(), 16u * 16u * 2u);
  set.thickness = 0.25;
  // Placed like a mesh: moved up by 0.25.
  set.invert = false;
  set.placement.translate = Vec3{0.0, 0.25, 0.0};
  for (std::uint32_t v : voxelizeSet(set, lattice, dir.path, "set").voxels) EXPECT_GE(lattice.centre(v).y, -0.25);

  set.placement = Placement{};
  set.threshold = 0.0;  // no pixel is darker than black
  try {
    voxelizeSet(set, lattice, dir.path, "functions[0].set");
    FAIL() << "an empty drawing set was accepted";
  } catch (const ModelError& e) {
    EXPECT_EQ(e.path(), "functions[0].set.threshold");
  }
  set.threshold = 0.5;
  set.path = "missing.png";
  try {
    voxelizeSet(set, lattice, dir.path, "functions[0].set");
    FAIL() << "a missing drawing was accepted";
  } catch (const ModelError& e) {
    EXPECT_EQ(e.path(), "functions[0].set.image");
    EXPECT_NE(e.message().find("missing.png"), std::string::npos);
  }
}

TEST(SetIterates, FileFieldsRoundTrip) {
  const char* text = R"({"format": "gridifs", "version": 1,
    "functions": [
      {"name": "A", "kind": "median", "rotate": 30, "rotate_axis": [1, 0, 0],
       "set": {"image": "a.png", "threshold": 0.4, "thickness": 0.1, "invert": true,
               "placement": {"translate": [0.1, 0, 0], "rotate": [0, 0, 90], "scale": [0.5, 0.5, 1]}}},
      {"name": "B", "kind": "median", "set": {"primitive": "sphere", "radius": 0.2}}],
    "volume": {"resolution": 64, "start": {"primitive": "box", "center": [0, 0, 0], "size": [1, 1, 0.1]}}})";
  const Project p = parseProject(text);
  const Function& a = p.functions[0];
  EXPECT_EQ(a.set.shape, SetShape::Image);
  EXPECT_EQ(a.set.path, "a.png");
  EXPECT_DOUBLE_EQ(a.set.threshold, 0.4);
  EXPECT_DOUBLE_EQ(a.set.thickness, 0.1);
  EXPECT_TRUE(a.set.invert);
  EXPECT_EQ(a.set.placement.rotate, (Vec3{0.0, 0.0, 90.0}));
  EXPECT_EQ(a.rotate_axis, (Vec3{1.0, 0.0, 0.0}));
  EXPECT_EQ(p.functions[1].rotate_axis, (Vec3{0.0, 0.0, 1.0}));
  ASSERT_TRUE(p.volume && p.volume->start);
  EXPECT_EQ(p.volume->start->shape, SetShape::Box);
  EXPECT_EQ(parseProject(serializeProject(p)), p);
  // The default axis is not written, so older files save as they were.
  EXPECT_EQ(serializeProject(p).find("rotate_axis", serializeProject(p).find("\"B\"")), std::string::npos);

  auto refused = [](const std::string& functionJson) {
    try {
      parseProject(R"({"format": "gridifs", "version": 1, "functions": [)" + functionJson + "]}");
    } catch (const ModelError& e) {
      return e.path();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refused(R"({"kind": "median", "rotate_axis": [0, 0, 0], "set": {"primitive": "sphere"}})"),
            "functions[0].rotate_axis");
  EXPECT_EQ(refused(R"({"kind": "condensation", "rotate_axis": [1, 0, 0], "set": {"primitive": "sphere"}})"),
            "functions[0].rotate_axis");
  EXPECT_EQ(refused(R"({"kind": "median", "set": {"image": "a.png", "threshold": 2}})"), "functions[0].set.threshold");
  EXPECT_EQ(refused(R"({"kind": "median", "set": {"image": "a.png", "thickness": 0}})"), "functions[0].set.thickness");
  EXPECT_EQ(refused(R"({"kind": "median", "set": {"image": "a.png", "invert": 1}})"), "functions[0].set.invert");
  EXPECT_EQ(refused(R"({"kind": "median", "set": {"image": "a.png", "grid": "x"}})"), "functions[0].set.grid");
}
