#include "volume/vdb_support.h"

#include <openvdb/io/File.h>

#include <mutex>

namespace gridifs {

void initializeOpenVdb() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

openvdb::math::Transform::Ptr latticeTransform(const VoxelLattice& lattice) {
  auto xform = openvdb::math::Transform::createLinearTransform(lattice.voxelSize());
  const double origin = -1.0 + 1.0 / lattice.n;
  xform->postTranslate(openvdb::Vec3d(origin, origin, origin));
  return xform;
}

openvdb::FloatGrid::Ptr readFloatGrid(const std::filesystem::path& file, const std::string& name,
                                      const std::string& jsonPath) {
  initializeOpenVdb();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    throw ModelError(jsonPath + ".vdb", "the VDB file " + file.string() + " does not exist");
  openvdb::GridBase::Ptr base;
  try {
    openvdb::io::File vdb(file.string());
    vdb.open(false);
    if (!vdb.hasGrid(name)) {
      vdb.close();
      throw ModelError(jsonPath + ".grid",
                       "the VDB file " + file.string() + " has no grid named \"" + name.substr(0, 64) + "\"");
    }
    base = vdb.readGrid(name);
    vdb.close();
  } catch (const openvdb::Exception& e) {
    throw ModelError(jsonPath + ".vdb", "cannot read the VDB file " + file.string() + ": " + e.what());
  }
  auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(base);
  if (!grid)
    throw ModelError(jsonPath + ".grid",
                     "the grid \"" + name.substr(0, 64) + "\" of " + file.string() + " is not a float grid");
  return grid;
}

}  // namespace gridifs
