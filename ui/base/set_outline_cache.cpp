#include "ui/base/set_outline_cache.h"

#include <algorithm>

namespace gridifs::ui {
namespace {

// Enough for every set function of a project and the states a slider drag passes through.
constexpr std::size_t kMaxDrawings = 24;

}  // namespace

const SetOutlineCache::Drawing& SetOutlineCache::get(const CondensationSet& set, const std::filesystem::path& folder,
                                                     const std::string& jsonPath) {
  auto it = std::find_if(drawings_.begin(), drawings_.end(),
                         [&](const Drawing& d) { return d.set == set && d.folder == folder; });
  if (it != drawings_.end()) {
    std::rotate(it, it + 1, drawings_.end());  // most recently used last
    return drawings_.back();
  }
  if (drawings_.size() >= kMaxDrawings) drawings_.erase(drawings_.begin());
  Drawing d{set, folder, {}, {}};
  try {
    d.lines = setOutline(set, folder, jsonPath);
  } catch (const ModelError& e) {
    d.error = e.what();
  } catch (const std::exception& e) {  // OpenVDB and OpenMesh throw their own on broken files
    d.error = std::string(jsonPath) + ": " + e.what();
  }
  drawings_.push_back(std::move(d));
  return drawings_.back();
}

}  // namespace gridifs::ui
