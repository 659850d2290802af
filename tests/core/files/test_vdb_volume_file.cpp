// A density volume written as OpenVDB, read back with OpenVDB itself: its grids, their class and
// background, the lattice's transform and every voxel.
#include <gtest/gtest.h>
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Count.h>

#include <filesystem>

#include "io/project_io.h"
#include "tests/core/deterministic_samples.h"
#include "tests/core/volume_scenes.h"
#include "volume/measure_attractor.h"
#include "volume/vdb_volume_file.h"

using namespace gridifs;
namespace fs = std::filesystem;

TEST(VdbVolumeFile, HasTheDensityAndColourGridsAndTheLatticeTransform) {
  const test_support::TempFolder folder("vdbfile");
  const Project p = parseProject(test_support::kTwoMedians);
  VolumeJob job;
  job.settings = *p.volume;
  job.settings.iterations = 60;
  const DensityVolume v = computeDensityVolume(p, job);
  const fs::path file = folder.path / "out.vdb";
  writeVdbVolume(v, file);
  openvdb::initialize();
  openvdb::io::File vdb(file.string());
  vdb.open();
  ASSERT_TRUE(vdb.hasGrid("density"));
  ASSERT_TRUE(vdb.hasGrid("color"));
  auto density = openvdb::gridPtrCast<openvdb::FloatGrid>(vdb.readGrid("density"));
  auto color = openvdb::gridPtrCast<openvdb::Vec3SGrid>(vdb.readGrid("color"));
  vdb.close();
  ASSERT_TRUE(density);
  ASSERT_TRUE(color);
  EXPECT_EQ(density->getGridClass(), openvdb::GRID_FOG_VOLUME);
  EXPECT_EQ(density->background(), 0.0f);
  EXPECT_TRUE(density->transform().isLinear());
  EXPECT_NEAR(density->voxelSize().x(), 2.0 / 32, 1e-12);
  const openvdb::Vec3d origin = density->transform().indexToWorld(openvdb::Vec3d(0, 0, 0));
  EXPECT_NEAR(origin.x(), -1.0 + 1.0 / 32, 1e-12);
  EXPECT_NEAR(origin.z(), -1.0 + 1.0 / 32, 1e-12);
  const auto range = openvdb::tools::minMax(density->tree());
  EXPECT_FLOAT_EQ(range.max(), 1.0f);
  EXPECT_GE(range.min(), 0.0f);
  const auto accessor = density->getConstAccessor();
  for (int k = 0; k < 32; ++k)
    for (int j = 0; j < 32; ++j)
      for (int i = 0; i < 32; ++i) ASSERT_FLOAT_EQ(accessor.getValue(openvdb::Coord(i, j, k)), v.at(i, j, k));
}
