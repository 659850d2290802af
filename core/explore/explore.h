#pragma once
// Exploring: random worlds by style, mutations of a project and children of two, the way
// Apophysis's mutation window, Chaotica's random worlds and JWildfire's MutaGen let artists find
// forms. Every draw comes from the project's own description: the operation table's parameters
// and ranges, flam3's variation list, the free-form presets, the parameter paths and their spans
// (schema/project_parameter.h), so a new operation or variation joins without new code here. One
// seeded stream (explore/explore_stream.h) makes every result reproducible byte for byte, and
// every result passes the same test the modeller uses (explore/attractor_verdict.h) or is drawn
// again, a bounded number of times.
//
// Thread-safety: the functions touch only their arguments.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "explore/attractor_verdict.h"
#include "model/project.h"

namespace gridifs {

/// "--style": which kind of world randomWorld draws.
enum class ExploreStyle {
  Grid,      // distorted grids: random placements and operation stacks (Gröller & Wegenkittl)
  Flame,     // affine grids with flam3's variations, shown in the flame display (Draves & Reckase)
  FreeForm,  // a free-form IFS from a preset with its control net moved (Thollot et al.)
  Volume,    // condensation and median sets, and a fractal field thinning the density
};
const char* exploreStyleName(ExploreStyle style);
/// Parses "grid", "flame", "free-form" or "volume".
bool parseExploreStyle(std::string_view name, ExploreStyle& style);
/// "grid, flame, free-form or volume", for messages.
const char* exploreStyleList();

/// What a mutation leaves byte-equal in the project file ("--keep ops,placement,...").
struct ExploreKeep {
  bool ops = false;         // every function's operation stack
  bool placement = false;   // every function's placement (and the number of functions)
  bool colors = false;      // every function's colour, palette index and colour speed
  bool variations = false;  // every function's variations, their parameters and post map
  bool palette = false;     // render.flame's palette and its keys
  bool camera = false;      // the camera
  bool tracks = false;      // the keyframe tracks and the animation settings
  bool operator==(const ExploreKeep&) const = default;
};
/// Parses a comma-separated list of the names above. Returns false and sets `unknown` to the
/// first name it does not know.
bool parseExploreKeep(std::string_view list, ExploreKeep& keep, std::string& unknown);
/// "ops, placement, colors, variations, palette, camera or tracks", for messages.
const char* exploreKeepList();

/// One function's attractor is a single point: a world needs two at least.
inline constexpr int kMinExploreFunctions = 2;
inline constexpr int kMaxExploreFunctions = 12;
inline constexpr int kExploreTries = 64;  // draws before giving up on finding one worth looking at

struct RandomWorldOptions {
  ExploreStyle style = ExploreStyle::Grid;
  int functions = 0;  // 0: the style's own choice (3 to 5); else kMinExploreFunctions..kMaxExploreFunctions
  std::uint64_t seed = 1;
};

struct MutationOptions {
  double strength = 0.5;  // (0, 1]: how far a child may move from its parent
  ExploreKeep keep;
  std::uint64_t seed = 1;
  /// Breeding: the second parent, whose functions (with their stacks) the child draws from too.
  const Project* mate = nullptr;
  /// Where the parents' relative set and palette files are found.
  std::filesystem::path folder;
};

/// A result and how it was found.
struct ExploreResult {
  Project project;
  int tries = 0;  // draws until one was worth looking at (1: the first)
  AttractorVerdict verdict;
};

/// A new world of `options.style`, worth looking at, with lineage {[], seed}. Throws ModelError
/// ("") when none of kExploreTries draws is.
ExploreResult randomWorld(const RandomWorldOptions& options);

/// A seed for a draw asked for without one: from the clock, below a billion so that it can be
/// typed back (it is printed, and kept in the lineage).
std::uint64_t clockSeed();

/// One draw of randomWorld, not judged: what the acceptance tests count at the first draw.
Project drawRandomWorld(const RandomWorldOptions& options, std::uint64_t draw);

/// Judges one draw as randomWorld and mutateProject do; with `frame` (new worlds) the camera is
/// first turned on the attractor as the modeller's F frames a view, and the framed project judged.
AttractorVerdict judgeDraw(Project& project, const std::filesystem::path& folder, bool frame);

/// A child of `parent` (and options.mate), worth looking at, with what options.keep names equal
/// to the parent's and lineage {parents, seed, strength} (`parents` names the parents' files).
/// Throws ModelError ("") when none of kExploreTries draws is.
ExploreResult mutateProject(const Project& parent, const MutationOptions& options,
                            const std::vector<std::string>& parents);

/// One draw of mutateProject, not judged.
Project drawMutation(const Project& parent, const MutationOptions& options, std::uint64_t draw);

}  // namespace gridifs
