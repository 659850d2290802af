#include "volume/vdb_volume_file.h"

#include <openvdb/io/File.h>

#include "base/atomic_file.h"
#include "volume/vdb_support.h"

namespace gridifs {

void writeVdbVolume(const DensityVolume& volume, const std::filesystem::path& file) {
  initializeOpenVdb();
  const VoxelLattice& lattice = volume.lattice;
  const auto xform = latticeTransform(lattice);
  openvdb::FloatGrid::Ptr density = openvdb::FloatGrid::create(0.0f);
  density->setName("density");
  density->setGridClass(openvdb::GRID_FOG_VOLUME);
  density->setTransform(xform);
  openvdb::Vec3SGrid::Ptr color;
  if (!volume.color.empty()) {
    color = openvdb::Vec3SGrid::create(openvdb::Vec3s(0.0f));
    color->setName("color");
    color->setTransform(xform->copy());
  }
  {
    auto densityAccess = density->getAccessor();
    for (int k = 0; k < lattice.n; ++k)
      for (int j = 0; j < lattice.n; ++j)
        for (int i = 0; i < lattice.n; ++i) {
          const std::uint32_t v = lattice.index(i, j, k);
          const float d = volume.density[v];
          if (d <= 0.0f) continue;
          densityAccess.setValue(openvdb::Coord(i, j, k), d);
          if (color)
            color->tree().setValue(openvdb::Coord(i, j, k), openvdb::Vec3s(volume.color[3 * v], volume.color[3 * v + 1],
                                                                           volume.color[3 * v + 2]));
        }
  }
  openvdb::GridPtrVec grids{density};
  if (color) grids.push_back(color);
  AtomicFile out(file);
  try {
    openvdb::io::File vdb(out.temporaryPath().string());
    vdb.write(grids);
    vdb.close();
  } catch (const openvdb::Exception& e) {
    throw IoError("cannot write " + file.string() + ": " + e.what());
  }
  out.commit();
}

}  // namespace gridifs
