#include "volume/vdb_volume_file.h"

#include "base/atomic_file.h"
#include "base/errors.h"
#include "volume/vdb_io.h"

namespace gridifs {

void writeVdbVolume(const DensityVolume& volume, const std::filesystem::path& file) {
  AtomicFile out(file);
  try {
    vdb_io::writeVolume(out.temporaryPath(), volume.lattice, volume.density, volume.color);
  } catch (const IoError& e) {
    throw IoError("cannot write " + file.string() + ": " + e.what());
  }
  out.commit();
}

void requireVdbVolumeWriter() { vdb_io::requirePlugin(); }

}  // namespace gridifs
