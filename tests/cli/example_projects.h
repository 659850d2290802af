#pragma once
// The example projects of assets/ that several command-line test files render, by one name each.
#include <string>

namespace gridifs::test_support {

/// A project of assets/ by its path there.
inline std::string asset(const std::string& name) { return std::string(GRIDIFS_ASSETS) + "/" + name; }

inline const std::string kSierpinski = asset("sierpinski_tetrahedron.gridifs");
inline const std::string kTwisted = asset("twisted_functions.gridifs");           // z-buffer, three twisted grids
inline const std::string kAnimated = asset("animation/breathing_twist.gridifs");  // tracks: camera.yaw, a twist
inline const std::string kPineTrees = asset("volumes/pine_trees.gridifs");        // condensation, no median

}  // namespace gridifs::test_support
