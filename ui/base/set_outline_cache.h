#pragma once
// The line drawings of the project's condensation sets (volume/set_outline.h), kept between
// frames: a mesh or VDB set is read and voxelized once per change of the set, not once per frame
// or per view. Each drawing remembers why it could not be made (the voxelizer's sentence), which
// the set editor shows inline.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "volume/set_outline.h"

namespace gridifs::ui {

class SetOutlineCache {
 public:
  struct Drawing {
    CondensationSet set;
    std::filesystem::path folder;
    LineSegments lines;  // empty when the set cannot be drawn
    std::string error;   // why not, or empty
  };

  /// The drawing of `set` (file paths relative to `folder`); `jsonPath` names the set in messages.
  const Drawing& get(const CondensationSet& set, const std::filesystem::path& folder, const std::string& jsonPath);

 private:
  std::vector<Drawing> drawings_;  // most recently used last
};

}  // namespace gridifs::ui
