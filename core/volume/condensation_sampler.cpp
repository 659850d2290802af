#include "volume/condensation_sampler.h"

#include "base/hash.h"
#include "volume/set_voxelizer.h"

namespace gridifs {

CondensationSampler makeCondensationSampler(const Project& project, const std::filesystem::path& projectFolder,
                                            int resolution) {
  return [project, projectFolder, resolution](std::size_t index) {
    const Function& f = project.functions.at(index);
    const VoxelLattice lattice{resolution};
    // Relative to the function: compileIfs puts "functions[i]" in front.
    const VoxelSet set = voxelizeSet(f.set, lattice, projectFolder, "set");
    constexpr std::size_t kSamples = 1 << 16;
    std::vector<Vec3> out;
    out.reserve(kSamples);
    std::uint64_t state = splitmix64(index + 1);
    const double half = 0.5 * lattice.voxelSize();
    auto unit = [&] { return double(splitmix64(state++) >> 11) * (2.0 / 9007199254740992.0) - 1.0; };
    for (std::size_t s = 0; s < kSamples; ++s) {
      const std::uint32_t v = set.voxels[std::size_t((splitmix64(state++) >> 32) * set.size() >> 32)];
      out.push_back(lattice.centre(v) + half * Vec3{unit(), unit(), unit()});
    }
    return out;
  };
}

}  // namespace gridifs
