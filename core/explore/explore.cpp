#include "explore/explore.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <glm/geometric.hpp>

#include "anim/track_path.h"
#include "base/errors.h"
#include "edit/new_function.h"
#include "edit/parameter_edit.h"
#include "edit/project_edit.h"
#include "explore/explore_stream.h"
#include "freeform/free_form_presets.h"
#include "io/parameter_paths.h"
#include "schema/live_binding.h"
#include "schema/operation_table.h"
#include "schema/palette_reference.h"
#include "schema/project_parameter.h"
#include "schema/project_time.h"
#include "schema/validation.h"
#include "variations/flame_variations.h"

namespace gridifs {
namespace {

/// flam3's palette file holds palettes 0..700.
constexpr int kFlam3Palettes = 701;

// ---------------------------------------------------------------------------------------------
// Drawing from the descriptions

/// A number of a field near its default: within the slider's range (the span artists reach for),
/// `reach` of it on either side of the default, kept inside the valid range.
double drawNear(const FieldSchema& spec, double current, double reach, ExploreStream& s) {
  double lo = spec.sliderMin, hi = spec.sliderMax;
  if (!(lo < hi)) {
    lo = current - 1.0;
    hi = current + 1.0;
  }
  const double v = current + s.uniform(-0.5, 0.5) * reach * (hi - lo);
  return std::clamp(v, std::max(spec.min, lo), std::min(spec.max, hi));
}

/// Every numeric, choice and switch parameter of `params` drawn from its description; text,
/// lists and the node moves keep their defaults (an identity calculator, no morph pairs).
void drawParameters(OpParams& params, double reach, ExploreStream& s) {
  const OperationSpec& spec = operationSpec(params);
  for (const ParamSpec& p : spec.params) {
    switch (p.type) {
      case FieldType::Number:
      case FieldType::Integer:
      case FieldType::Vector:
        for (int c = 0; c < p.components; ++c) p.setNumber(&params, c, drawNear(p, p.number(&params, c), reach, s));
        break;
      case FieldType::Choice:
        if (p.choices && !p.choices->names.empty()) p.setChoiceOf(&params, int(s.index(p.choices->names.size())));
        break;
      case FieldType::Boolean:
        p.value<bool>(static_cast<void*>(&params)) = s.chance(0.5);
        break;
      default:
        break;
    }
  }
}

/// A random operation of the table (those the panel offers), checked by the table's own rules.
Operation randomOperation(double reach, ExploreStream& s) {
  std::vector<const OperationSpec*> offered;
  for (const OperationSpec& spec : operationTable())
    if (spec.addable) offered.push_back(&spec);
  for (int attempt = 0; attempt < 8; ++attempt) {
    Operation op;
    op.params = offered[s.index(offered.size())]->defaults;
    drawParameters(op.params, reach, s);
    try {
      validateOperationParams(op.params);
      return op;
    } catch (const ModelError&) {
      // a combination the rules refuse (a bend about its own axis): draw again
    }
  }
  Operation op;
  op.params = offered.front()->defaults;
  return op;
}

Vec3 randomColor(ExploreStream& s) {
  // A saturated hue with some lightness, as the function colours of the examples.
  const double h = s.uniform() * 6.0, sat = s.uniform(0.45, 0.9), val = s.uniform(0.7, 1.0);
  const double c = val * sat, x = c * (1.0 - std::fabs(std::fmod(h, 2.0) - 1.0)), m = val - c;
  const int sector = int(h) % 6;
  const double rgb[6][3] = {{c, x, 0}, {x, c, 0}, {0, c, x}, {0, x, c}, {x, 0, c}, {c, 0, x}};
  return Vec3{rgb[sector][0] + m, rgb[sector][1] + m, rgb[sector][2] + m};
}

std::string randomPalette(ExploreStream& s) {
  const std::vector<std::string>& builtin = builtinPaletteNames();
  if (!builtin.empty() && s.chance(0.3)) return builtin[s.index(builtin.size())];
  return "flam3:" + std::to_string(s.index(kFlam3Palettes));
}

/// A contractive placement: scaled into [0.3, 0.55] per axis, turned, and moved inside X.
Placement randomPlacement(ExploreStream& s) {
  Placement p;
  const double base = s.uniform(0.32, 0.55);
  for (int d = 0; d < 3; ++d) {
    p.scale[d] = base * s.uniform(0.85, 1.15);
    p.rotate[d] = s.uniform(-50.0, 50.0);
    p.translate[d] = s.uniform(-0.5, 0.5);
  }
  return p;
}

void recolor(Function& f, std::size_t index, std::size_t count, ExploreStream& s) {
  f.color = randomColor(s);
  f.palette_index = count > 1 ? double(index) / double(count - 1) : s.uniform();
}

void colorFunction(Function& f, std::size_t index, std::size_t count, ExploreStream& s) {
  recolor(f, index, count, s);
  f.weight = s.uniform(0.5, 1.5);
}

int functionCount(const RandomWorldOptions& options, ExploreStream& s) {
  return options.functions > 0 ? options.functions : 3 + int(s.index(3));
}

// ---------------------------------------------------------------------------------------------
// The styles

Project gridWorld(const RandomWorldOptions& options, ExploreStream& s) {
  Project p;
  const int n = functionCount(options, s);
  for (int i = 0; i < n; ++i) {
    Function f = newGridFunction(p);
    f.placement = randomPlacement(s);
    const int ops = 1 + int(s.index(2));
    for (int k = 0; k < ops; ++k) f.ops.push_back(randomOperation(0.5, s));
    colorFunction(f, std::size_t(i), std::size_t(n), s);
    p.functions.push_back(std::move(f));
  }
  p.camera.yaw = s.uniform(0.0, 360.0);
  p.camera.pitch = s.uniform(10.0, 40.0);
  return p;
}

/// flam3's variations the flame style draws from: all but the pre-variations, which only move
/// the point the others see.
std::vector<const FlameVariation*> drawableVariations() {
  std::vector<const FlameVariation*> out;
  for (const FlameVariation& v : flameVariations())
    if (!v.pre) out.push_back(&v);
  return out;
}

Project flameWorld(const RandomWorldOptions& options, ExploreStream& s) {
  Project p;
  const int n = functionCount(options, s);
  const std::vector<const FlameVariation*> variations = drawableVariations();
  for (int i = 0; i < n; ++i) {
    Function f = newGridFunction(p);
    f.resolution = Index3{2, 2, 2};  // an affine map, as imported flame xforms are
    const double scale = s.uniform(0.4, 0.8);
    // Depth contracts too, so the world settles on its plane (the camera looks along z).
    f.placement.scale = Vec3{scale * s.uniform(0.8, 1.2), scale * s.uniform(0.8, 1.2), 0.5};
    f.placement.rotate = Vec3{0.0, 0.0, s.uniform(-180.0, 180.0)};
    f.placement.translate = Vec3{s.uniform(-0.6, 0.6), s.uniform(-0.6, 0.6), 0.0};
    const int count = 1 + int(s.index(2));
    double total = 0.0;
    for (int k = 0; k < count; ++k) {
      const double w = s.uniform(0.2, 1.0);
      f.variations[variations[s.index(variations.size())]->name] += w;
      total += w;
    }
    for (auto& [name, w] : f.variations) w /= total;  // flam3's xforms mostly sum to 1
    colorFunction(f, std::size_t(i), std::size_t(n), s);
    p.functions.push_back(std::move(f));
  }
  // flam3's frame: the xy plane seen from +z, orthographic, as imported genomes are.
  p.camera.yaw = -90.0;
  p.camera.pitch = -90.0;
  p.camera.projection = CameraProjection::Orthographic;
  p.camera.fov = 53.13010235415598;
  p.camera.distance = 4.0;
  p.render.mode = DisplayMode::Flame;
  p.render.flame.palette = randomPalette(s);
  return p;
}

Project freeFormWorld(const RandomWorldOptions& options, ExploreStream& s) {
  Project p = defaultNewProject();
  // Surfaces and gaskets: a curve preset, even a rough one, is a thread on screen.
  static constexpr FreeFormPreset kPresets[] = {FreeFormPreset::BezierPatch, FreeFormPreset::Sierpinski,
                                                FreeFormPreset::SierpinskiPatch, FreeFormPreset::BSplinePatch};
  const FreeFormPreset chosen = kPresets[s.index(std::size(kPresets))];
  FreeFormPresetOptions preset;
  preset.degree = 2 + int(s.index(3));
  preset.split = s.uniform(0.35, 0.65);
  preset.roughness = s.uniform(0.0, 0.35);
  preset.seed = s.next() & 0xFFFFFFFFu;
  applyFreeFormPreset(p, chosen, preset);
  // The control net moved: the same fractal bent into another shape.
  if (p.space)
    for (Vec3& point : p.space->control_points)
      for (int d = 0; d < 3; ++d) point[d] = std::clamp(point[d] + 0.25 * s.normal(), -0.95, 0.95);
  for (std::size_t i = 0; i < p.functions.size(); ++i) p.functions[i].color = randomColor(s);
  (void)options;  // a preset fixes its own number of maps
  p.camera.yaw = s.uniform(0.0, 360.0);
  p.camera.pitch = s.uniform(10.0, 50.0);
  return p;
}

CondensationSet randomSet(ExploreStream& s) {
  CondensationSet set;
  static constexpr SetShape kShapes[] = {SetShape::Sphere, SetShape::Box, SetShape::Torus};
  set.shape = kShapes[s.index(std::size(kShapes))];
  set.center = Vec3{s.uniform(-0.4, 0.4), s.uniform(-0.4, 0.4), s.uniform(-0.4, 0.4)};
  set.radius = s.uniform(0.15, 0.35);
  set.size = Vec3{s.uniform(0.2, 0.6), s.uniform(0.2, 0.6), s.uniform(0.2, 0.6)};
  set.major = s.uniform(0.2, 0.35);
  set.minor = s.uniform(0.05, 0.12);
  return set;
}

Project volumeWorld(const RandomWorldOptions& options, ExploreStream& s) {
  Project p;
  VolumeSettings volume;
  if (s.chance(0.3)) {
    // Sokolov & Gentil's median functions: the density morphs between two or three sets. The
    // set iteration is kept small so the world previews at once.
    const int n = options.functions > 0 ? options.functions : 2 + int(s.index(2));
    for (int i = 0; i < n; ++i) {
      Function f = newSetFunction(p, FunctionKind::Median);
      f.set = randomSet(s);
      colorFunction(f, std::size_t(i), std::size_t(n), s);
      p.functions.push_back(std::move(f));
    }
    volume.resolution = 24;
    volume.iterations = 24;
    volume.skip = 6;
  } else {
    // Grid maps with a constant condensation set (Barnsley's condensation, Sokolov & Gentil §3.1):
    // copies of the set strewn along the attractor.
    const int n = functionCount(options, s);
    for (int i = 0; i + 1 < n; ++i) {
      Function f = newGridFunction(p);
      f.placement = randomPlacement(s);
      if (s.chance(0.6)) f.ops.push_back(randomOperation(0.4, s));
      colorFunction(f, std::size_t(i), std::size_t(n), s);
      p.functions.push_back(std::move(f));
    }
    Function set = newSetFunction(p, FunctionKind::Condensation);
    set.set = randomSet(s);
    colorFunction(set, std::size_t(n - 1), std::size_t(n), s);
    set.weight = s.uniform(0.2, 0.6);
    p.functions.push_back(std::move(set));
  }
  // Colonna's fractal field thinning the density.
  VolumeDensityField field;
  field.strength = s.uniform(0.5, 2.0);
  field.field.scale = s.uniform(0.3, 0.8);
  field.field.seed = s.next() & 0xFFFFu;
  volume.field = field;
  p.volume = volume;
  p.render.mode = DisplayMode::Flame;
  p.render.flame.palette = randomPalette(s);
  p.camera.yaw = s.uniform(0.0, 360.0);
  p.camera.pitch = s.uniform(10.0, 40.0);
  return p;
}

// ---------------------------------------------------------------------------------------------
// Mutation

/// Which parameter paths a mutation may change with `keep`: the genome (functions, the final
/// function, the free-form net, the volume's field, the camera), not the output's size, samples
/// or seeds, and nothing `keep` names.
bool mayMutate(const std::string& path, const ExploreKeep& keep) {
  auto starts = [&](const char* prefix) { return path.rfind(prefix, 0) == 0; };
  auto has = [&](const char* part) { return path.find(part) != std::string::npos; };
  if (starts("camera")) return !keep.camera;
  if (starts("volume.field")) return true;
  if (starts("space.control_points")) return !keep.placement;
  if (!starts("functions[") && !starts("final.")) return false;
  if (has(".resolution") || has(".sampling_error")) return false;  // the grid's size, not its shape
  if (has(".ops[")) return !keep.ops;
  if (has(".placement.") || has(".matrix[")) return !keep.placement;
  if (has(".color") || has(".palette_index") || has(".color_speed")) return !keep.colors;
  if (has(".variations.") || has(".variation_params.") || has(".post.")) return !keep.variations;
  return true;  // weights, sets, rotations of medians
}

/// Moves the number at `path` by up to strength × a quarter of its span (its slider's range, or
/// its own size where the description gives none). Returns whether the edit was accepted.
bool nudge(Project& child, const std::string& path, double strength, ExploreStream& s) {
  const std::optional<TrackPath> parsed = TrackPath::parse(path);
  if (!parsed) return false;
  const FoundParameter found = findParameter(child, *parsed);
  if (found.lookup != ParameterLookup::Number) return false;
  const double v = found.parameter.get(child);
  const ParameterSpan span = found.parameter.span();
  double next;
  if (span.lo < span.hi)
    next = std::clamp(v + strength * 0.25 * (span.hi - span.lo) * s.normal(), span.lo, span.hi);
  else
    next = v != 0.0 ? v * std::exp(strength * 0.3 * s.normal()) : strength * 0.2 * s.normal();
  try {
    applyEdit(child, SetParameter{path, next});
    return true;
  } catch (const ModelError&) {
    return false;
  }
}

bool keepsFunctions(const ExploreKeep& keep) { return keep.ops || keep.placement || keep.colors || keep.variations; }

void addOrDropOperation(Project& child, double strength, ExploreStream& s) {
  std::vector<std::size_t> grids;
  for (std::size_t i = 0; i < child.functions.size(); ++i)
    if (child.functions[i].kind == FunctionKind::Grid) grids.push_back(i);
  if (grids.empty()) return;
  Function& f = child.functions[grids[s.index(grids.size())]];
  const double u = s.uniform();
  if (u < 0.45 || f.ops.empty()) {
    f.ops.insert(f.ops.begin() + std::ptrdiff_t(s.index(f.ops.size() + 1)), randomOperation(0.5 * strength, s));
  } else if (u < 0.8) {
    f.ops.erase(f.ops.begin() + std::ptrdiff_t(s.index(f.ops.size())));
  } else if (f.ops.size() > 1) {
    const std::size_t a = s.index(f.ops.size()), b = s.index(f.ops.size());
    std::swap(f.ops[a], f.ops[b]);
  }
}

void replaceAddOrDropFunction(Project& child, ExploreStream& s) {
  if (child.space) return;  // a free-form IFS's maps are its matrices: moved through their paths
  const double u = s.uniform();
  if (u < 0.4) {
    Function& f = child.functions[s.index(child.functions.size())];
    if (f.kind == FunctionKind::Grid) f.placement = randomPlacement(s);
  } else if (u < 0.7 && int(child.functions.size()) < kMaxExploreFunctions) {
    Function f = newGridFunction(child);
    f.placement = randomPlacement(s);
    f.ops.push_back(randomOperation(0.4, s));
    colorFunction(f, child.functions.size(), child.functions.size() + 1, s);
    child.functions.push_back(std::move(f));
  } else if (child.functions.size() > 2) {
    child.functions.erase(child.functions.begin() + std::ptrdiff_t(s.index(child.functions.size())));
  }
}

void addOrRemoveVariation(Project& child, ExploreStream& s) {
  std::vector<std::size_t> grids;
  for (std::size_t i = 0; i < child.functions.size(); ++i)
    if (child.functions[i].kind == FunctionKind::Grid) grids.push_back(i);
  if (grids.empty()) return;
  Function& f = child.functions[grids[s.index(grids.size())]];
  if (!f.variations.empty() && (s.chance(0.4) || f.variations.size() > 3)) {
    auto it = f.variations.begin();
    std::advance(it, std::ptrdiff_t(s.index(f.variations.size())));
    f.variations.erase(it);
    return;
  }
  const std::vector<const FlameVariation*> variations = drawableVariations();
  f.variations[variations[s.index(variations.size())]->name] += s.uniform(0.1, 0.5);
}

/// Breeding: each of the child's functions from one parent or the other, with its stack.
void mate(Project& child, const Project& other, ExploreStream& s) {
  if (child.space.has_value() != other.space.has_value())
    throw ModelError("", "cannot breed a free-form IFS with a grid IFS; breed two of one kind");
  if (child.space && child.space->control_points.size() != other.space->control_points.size())
    throw ModelError("", "cannot breed free-form IFSs with different numbers of control points");
  std::vector<Function> functions;
  const std::size_t n = std::max(child.functions.size(), other.functions.size());
  for (std::size_t i = 0; i < n; ++i) {
    const bool fromOther = s.chance(0.5);
    const std::vector<Function>& from = fromOther ? other.functions : child.functions;
    const std::vector<Function>& fallback = fromOther ? child.functions : other.functions;
    if (i < from.size())
      functions.push_back(from[i]);
    else if (s.chance(0.5) && i < fallback.size())
      functions.push_back(fallback[i]);
  }
  if (functions.empty()) functions.push_back(child.functions.front());
  child.functions = std::move(functions);
  // Names stay unique (transitions and tracks name functions by index, cleared below if needed).
  for (std::size_t i = 0; i < child.functions.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (child.functions[j].name == child.functions[i].name) {
        Project names;
        names.functions.assign(child.functions.begin(), child.functions.begin() + std::ptrdiff_t(i));
        child.functions[i].name = uniqueFunctionName(names, "f");
        break;
      }
}

/// What `keep` names, put back from the parent.
void restoreKept(Project& child, const Project& parent, const ExploreKeep& keep) {
  if (keep.camera) child.camera = parent.camera;
  if (keep.palette) {
    child.render.flame.palette = parent.render.flame.palette;
    child.render.flame.palette_keys = parent.render.flame.palette_keys;
  }
  if (keep.tracks) {
    child.tracks = parent.tracks;
    child.animation = parent.animation;
  }
  if (child.functions.size() != parent.functions.size()) return;  // only when no function was added
  for (std::size_t i = 0; i < child.functions.size(); ++i) {
    Function& c = child.functions[i];
    const Function& p = parent.functions[i];
    if (keep.ops) c.ops = p.ops;
    if (keep.placement) c.placement = p.placement, c.matrix = p.matrix;
    if (keep.colors) c.color = p.color, c.palette_index = p.palette_index, c.color_speed = p.color_speed;
    if (keep.variations) c.variations = p.variations, c.variation_params = p.variation_params, c.post = p.post;
  }
  if (keep.placement && parent.space && child.space) child.space->control_points = parent.space->control_points;
}

/// Transitions and states hold one row per function: a child with another number of functions
/// drops them (it is then an ordinary IFS), and tracks that name what is gone are dropped.
void fitToFunctions(Project& child, const Project& parent) {
  if (child.functions.size() != parent.functions.size()) {
    child.transitions.clear();
    child.states.reset();
  }
  for (auto it = child.tracks.begin(); it != child.tracks.end();) {
    const std::optional<TrackPath> parsed = TrackPath::parse(it->first);
    if (!parsed || findParameter(child, *parsed).lookup != ParameterLookup::Number)
      it = child.tracks.erase(it);
    else
      ++it;
  }
  dropUnresolvedBindings(child);
}

std::uint64_t drawSeed(std::uint64_t seed, std::uint64_t draw) { return splitmix64(seed ^ splitmix64(draw + 1)); }

template <class Draw>
ExploreResult firstWorthLooking(Draw&& draw, const std::filesystem::path& folder, const char* what, bool frame) {
  std::string last;
  for (int t = 0; t < kExploreTries; ++t) {
    try {
      Project p = draw(std::uint64_t(t));
      validateProject(p);
      checkTrackPaths(p);
      const AttractorVerdict verdict = judgeDraw(p, folder, frame);
      if (verdict.worth) return {std::move(p), t + 1, verdict};
      last = verdict.why;
    } catch (const ModelError& e) {
      if (e.path().empty()) throw;  // a request that cannot be met (breeding two kinds)
      last = e.what();
    }
  }
  throw ModelError("", std::string("none of ") + std::to_string(kExploreTries) + " " + what +
                           " was worth looking at (the last: " + last + "); try another seed or style");
}

}  // namespace

AttractorVerdict judgeDraw(Project& project, const std::filesystem::path& folder, bool frame) {
  // A new world is judged as it will be seen: framed; a mutation keeps its parent's camera.
  return frame ? judgeFramed(project, folder) : judgeAttractor(project, folder);
}

std::uint64_t clockSeed() {
  const auto now = std::chrono::system_clock::now().time_since_epoch();
  return splitmix64(std::uint64_t(std::chrono::duration_cast<std::chrono::nanoseconds>(now).count())) % 1'000'000'000u;
}

const char* exploreStyleName(ExploreStyle style) {
  switch (style) {
    case ExploreStyle::Grid:
      return "grid";
    case ExploreStyle::Flame:
      return "flame";
    case ExploreStyle::FreeForm:
      return "free-form";
    case ExploreStyle::Volume:
      return "volume";
  }
  return "grid";
}

bool parseExploreStyle(std::string_view name, ExploreStyle& style) {
  for (ExploreStyle s : {ExploreStyle::Grid, ExploreStyle::Flame, ExploreStyle::FreeForm, ExploreStyle::Volume})
    if (name == exploreStyleName(s)) {
      style = s;
      return true;
    }
  return false;
}

const char* exploreStyleList() { return "grid, flame, free-form or volume"; }

bool parseExploreKeep(std::string_view list, ExploreKeep& keep, std::string& unknown) {
  keep = {};
  std::size_t begin = 0;
  while (begin <= list.size()) {
    const std::size_t end = std::min(list.find(',', begin), list.size());
    const std::string_view name = list.substr(begin, end - begin);
    if (name == "ops")
      keep.ops = true;
    else if (name == "placement")
      keep.placement = true;
    else if (name == "colors")
      keep.colors = true;
    else if (name == "variations")
      keep.variations = true;
    else if (name == "palette")
      keep.palette = true;
    else if (name == "camera")
      keep.camera = true;
    else if (name == "tracks")
      keep.tracks = true;
    else {
      unknown = std::string(name);
      return false;
    }
    begin = end + 1;
  }
  return true;
}

const char* exploreKeepList() { return "ops, placement, colors, variations, palette, camera or tracks"; }

Project drawRandomWorld(const RandomWorldOptions& options, std::uint64_t draw) {
  if (options.functions != 0 && (options.functions < kMinExploreFunctions || options.functions > kMaxExploreFunctions))
    throw ModelError("", "the number of functions must be between " + std::to_string(kMinExploreFunctions) + " and " +
                             std::to_string(kMaxExploreFunctions));
  ExploreStream s(drawSeed(options.seed, draw));
  Project p;
  switch (options.style) {
    case ExploreStyle::Grid:
      p = gridWorld(options, s);
      break;
    case ExploreStyle::Flame:
      p = flameWorld(options, s);
      break;
    case ExploreStyle::FreeForm:
      p = freeFormWorld(options, s);
      break;
    case ExploreStyle::Volume:
      p = volumeWorld(options, s);
      break;
  }
  p.render.seed = 1;
  p.lineage = Lineage{{}, options.seed, std::nullopt};
  return p;
}

ExploreResult randomWorld(const RandomWorldOptions& options) {
  return firstWorthLooking([&](std::uint64_t draw) { return drawRandomWorld(options, draw); }, {},
                           (std::string(exploreStyleName(options.style)) + " worlds").c_str(), true);
}

Project drawMutation(const Project& parent, const MutationOptions& options, std::uint64_t draw) {
  if (!(options.strength > 0.0 && options.strength <= 1.0))
    throw ModelError("", "the strength must be above 0 and at most 1");
  ExploreStream s(drawSeed(options.seed, draw));
  const double st = options.strength;
  Project child = parent;
  child.lineage.reset();
  if (options.mate) mate(child, *options.mate, s);
  const bool structural = !keepsFunctions(options.keep) && !options.mate;
  if (structural && s.chance(0.35 * st)) replaceAddOrDropFunction(child, s);
  if (!options.keep.ops && s.chance(0.4 * st)) addOrDropOperation(child, st, s);
  if (!options.keep.variations && (child.render.mode == DisplayMode::Flame || s.chance(0.2)) && s.chance(0.35 * st))
    addOrRemoveVariation(child, s);
  if (!options.keep.palette && s.chance(0.3 * st)) child.render.flame.palette = randomPalette(s);
  if (!options.keep.colors && s.chance(0.3 * st))
    for (std::size_t i = 0; i < child.functions.size(); ++i) recolor(child.functions[i], i, child.functions.size(), s);
  // Numbers: a few at a weak strength, more at a strong one.
  std::vector<std::string> paths;
  for (std::string& path : parameterPaths(child))
    if (mayMutate(path, options.keep)) paths.push_back(std::move(path));
  const int changes = paths.empty() ? 0 : 1 + int(st * 6.0 * s.uniform());
  for (int k = 0; k < changes; ++k) nudge(child, paths[s.index(paths.size())], st, s);
  restoreKept(child, parent, options.keep);
  fitToFunctions(child, parent);
  return child;
}

ExploreResult mutateProject(const Project& parent, const MutationOptions& options,
                            const std::vector<std::string>& parents) {
  ExploreResult result = firstWorthLooking([&](std::uint64_t draw) { return drawMutation(parent, options, draw); },
                                           options.folder, "mutations", false);
  result.project.lineage = Lineage{parents, options.seed, options.strength};
  return result;
}

}  // namespace gridifs
