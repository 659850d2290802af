#include "volume/voxel_set.h"

#include <algorithm>

namespace gridifs {

void normalizeVoxels(std::vector<std::uint32_t>& voxels) {
  std::sort(voxels.begin(), voxels.end());
  voxels.erase(std::unique(voxels.begin(), voxels.end()), voxels.end());
}

Vec3 latticeCentroid(const VoxelSet& set) {
  Vec3 sum{0.0};
  for (std::uint32_t v : set.voxels) {
    const Index3 c = set.lattice.coordinates(v);
    sum += Vec3{double(c[0]), double(c[1]), double(c[2])};
  }
  return set.voxels.empty() ? sum : sum / double(set.voxels.size());
}

}  // namespace gridifs
