#include "volume/set_orbit_memo.h"

#include "base/hash.h"

namespace gridifs {

std::uint64_t hashVoxelSet(const VoxelSet& set) {
  std::uint64_t h = splitmix64(std::uint64_t(set.lattice.n) ^ (std::uint64_t(set.voxels.size()) << 32));
  for (std::uint32_t v : set.voxels) h = splitmix64(h ^ v);
  return h;
}

SetOrbitMemo::SetOrbitMemo(std::size_t functionCount, std::size_t byteBudget)
    : functionCount_(functionCount), byteBudget_(byteBudget) {}

int SetOrbitMemo::intern(const VoxelSet& set) {
  const std::uint64_t hash = hashVoxelSet(set);
  const auto [first, last] = byHash_.equal_range(hash);
  for (auto it = first; it != last; ++it)
    if (sets_[std::size_t(it->second)] == set) return it->second;  // equal, not merely equal hashes
  const std::size_t bytes = set.voxels.size() * sizeof(std::uint32_t);
  if (bytes_ + bytes > byteBudget_) return kNone;
  bytes_ += bytes;
  const int id = int(sets_.size());
  sets_.push_back(set);
  images_.resize(images_.size() + functionCount_, kNone);
  byHash_.emplace(hash, id);
  return id;
}

void SetOrbitMemo::rememberImage(int id, std::size_t function, int imageId) {
  images_[std::size_t(id) * functionCount_ + function] = imageId;
}

}  // namespace gridifs
