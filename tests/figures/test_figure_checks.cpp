// The figures tier's own checks must be able to fail: an empty picture has no coverage, one
// changed pixel or voxel makes two outputs differ, and a grid's nodes are read back as listed.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include "cli/run_command.h"
#include "figures/figure_checks.h"

namespace fs = std::filesystem;
namespace fig = gridifs::figures;

namespace {

void writeImage(const fs::path& file, const std::vector<float>& rgb, int w, int h) {
  auto out = OIIO::ImageOutput::create(file.string());
  ASSERT_TRUE(out && out->open(file.string(), OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::UINT8)));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, rgb.data()) && out->close());
}

TEST(FigureChecks, CoverageCountsPixelsOffTheBackground) {
  gridifs::test_support::ScratchDir dir("figure-checks-image");
  std::vector<float> rgb(10 * 10 * 3, 0.1f);
  writeImage(dir.path / "empty.png", rgb, 10, 10);
  EXPECT_EQ(*fig::imageCoverage(dir.path / "empty.png"), 0.0);
  for (int i = 0; i < 5; ++i) rgb[size_t(50 + i) * 3 + 1] = 0.9f;  // five green pixels
  writeImage(dir.path / "five.png", rgb, 10, 10);
  EXPECT_DOUBLE_EQ(*fig::imageCoverage(dir.path / "five.png"), 0.05);
  EXPECT_TRUE(fig::samePixels(dir.path / "five.png", dir.path / "five.png"));
  EXPECT_FALSE(fig::samePixels(dir.path / "empty.png", dir.path / "five.png"));
  EXPECT_FALSE(fig::imageCoverage(dir.path / "missing.png"));
}

TEST(FigureChecks, DensityCoverageAndSameness) {
  openvdb::initialize();
  const auto make = [](float value) {
    auto grid = openvdb::FloatGrid::create(0.f);
    grid->setTransform(openvdb::math::Transform::createLinearTransform(2.0 / 16));  // N = 16
    grid->tree().setValue(openvdb::Coord(1, 2, 3), 1.f);
    grid->tree().setValue(openvdb::Coord(4, 5, 6), value);
    return grid;
  };
  const auto a = make(0.5f), b = make(0.25f);
  EXPECT_EQ(fig::latticeSize(*a), 16);
  EXPECT_DOUBLE_EQ(fig::densityCoverage(*a), 2.0 / 4096.0);
  EXPECT_TRUE(fig::sameDensity(*a, *make(0.5f)));
  EXPECT_FALSE(fig::sameDensity(*a, *b));
  int size = 0;
  const auto img = fig::xray(*a, 'z', size);
  ASSERT_EQ(size, 16);
  EXPECT_FLOAT_EQ(img[size_t(15 - 2) * 16 + 1], 1.f);  // voxel (1, 2, ·) seen along z, rows from the top
  EXPECT_FLOAT_EQ(img[size_t(15 - 5) * 16 + 4], 0.5f);
}

TEST(FigureChecks, NodesReadAsListed) {
  gridifs::test_support::ScratchDir dir("figure-checks-nodes");
  std::ofstream(dir.path / "nodes.txt") << "0 0 0 -1 -1 -1\n1 0 0 0.5 -1 -1\n";
  const auto nodes = fig::readNodes(dir.path / "nodes.txt");
  ASSERT_EQ(nodes.size(), 2u);
  EXPECT_DOUBLE_EQ(nodes[1][3], 0.5);
}

}  // namespace
