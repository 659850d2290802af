#pragma once
// "Worth looking at": one test of a project's attractor, used by `gridifs random`, `gridifs
// mutate`, the Python module and the modeller's Explore window alike. A small, fast render
// measures what a glance at the preview would: how much of the frame the attractor covers, how its
// points spread through X, and whether the system contracts on average (Barnsley's condition for
// the chaos game to settle on an attractor: the expected log of the maps' local stretch is below
// zero). A speck, a flood, a line or a system that runs off is not worth looking at.
//
// Thread-safety: judgeAttractor touches only its arguments; call it from any thread.
#include <cstdint>
#include <filesystem>
#include <string>

#include "model/project.h"

namespace gridifs {

struct AttractorVerdict {
  double covered = 0.0;      // fraction of a 64×48 frame with at least one point
  double spread = 0.0;       // fraction of a 16³ voxel grid over X holding points
  double thickness = 0.0;    // second-largest over largest principal extent (0: a line)
  double contraction = 0.0;  // exp(E[log local stretch]) of the maps at attractor points
  double escaped = 0.0;      // fraction of the chaos game's points that turned non-finite or escaped
  /// Where the points lie: per axis, the 1st and 99th percentile (stray points left out).
  Vec3 low{0.0}, high{0.0};
  bool worth = false;
  std::string why;  // when not worth it: "a speck", "a flood", "a line", "runs off"
};

/// Renders `project` small (`folder`: where relative set files are found) and judges it.
/// Throws ModelError when the project cannot be rendered at all.
AttractorVerdict judgeAttractor(const Project& project, const std::filesystem::path& folder = {});

/// judgeAttractor for a new world, judged as it will be shown: the camera is turned on the
/// attractor (target at its centre, near enough that it fills about two thirds of the frame, as
/// the modeller's F frames a view) and the coverage measured for that camera. `project` keeps
/// the framed camera unless the world runs off or is a speck whatever the camera.
AttractorVerdict judgeFramed(Project& project, const std::filesystem::path& folder = {});

}  // namespace gridifs
