#include "model/validation.h"

#include <cmath>
#include <sstream>

#include "model/calculator.h"
#include "model/free_form.h"
#include "model/palette_reference.h"
#include "model/operation_table.h"
#include "model/transition_matrix.h"

namespace gridifs {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& message) { throw ModelError(path, message); }

std::string join(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }
std::string item(const std::string& path, std::size_t index) { return path + "[" + std::to_string(index) + "]"; }

}  // namespace

void validateFlameSettings(const FlameSettings& f, const std::string& path) {
  auto range = [&](double v, const char* key, double lo, double hi) {
    if (!(v >= lo && v <= hi)) {
      std::ostringstream s;
      s << "expected a number between " << lo << " and " << hi << ", found " << v;
      fail(join(path, key), s.str());
    }
  };
  if (f.palette.size() > limits::kMaxNameLength || !isPaletteReferenceSyntax(f.palette))
    fail(join(path, "palette"), "expected a built-in palette name, \"flam3:NUMBER\", \"flam3:NAME\" or \"file:PATH\"");
  range(f.brightness, "brightness", 0.0, 1e4);
  range(f.gamma, "gamma", 0.05, 100.0);
  range(f.gamma_threshold, "gamma_threshold", 0.0, 1.0);
  range(f.vibrancy, "vibrancy", 0.0, 1.0);
  range(f.highlight_power, "highlight_power", -1.0, 100.0);
  if (f.supersample < 1 || f.supersample > 8) fail(join(path, "supersample"), "expected an integer between 1 and 8");
  range(f.estimator_radius, "estimator_radius", 0.0, 64.0);
  range(f.estimator_minimum, "estimator_minimum", 0.0, 64.0);
  range(f.estimator_curve, "estimator_curve", 0.05, 10.0);
  range(f.filter_radius, "filter_radius", 0.0, 10.0);
  range(f.density_unit, "density_unit", 1e-6, 1e6);
  if (f.estimator_radius > 0.0) {
    if (f.estimator_minimum > f.estimator_radius)
      fail(join(path, "estimator_minimum"), "the estimator minimum is larger than its radius");
    // The density estimator builds ((radius·ss + 1)/(minimum·ss + 1))^(1/curve) kernels.
    const double kernels =
        std::pow((f.estimator_radius * f.supersample + 1.0) / (f.estimator_minimum * f.supersample + 1.0),
                 1.0 / f.estimator_curve);
    if (!(kernels <= 1e7))
      fail(join(path, "estimator_curve"), "the curve is too small for this radius (too many kernels)");
  }
}

void validateCamera(const Camera& c, const std::string& path) {
  auto range = [&](double v, const std::string& key, double lo, double hi) {
    if (!(v >= lo && v <= hi)) {
      std::ostringstream s;
      s << "expected a number between " << lo << " and " << hi << ", found " << v;
      fail(join(path, key), s.str());
    }
  };
  // The same ranges the project reader accepts, so whatever validates also loads back.
  range(c.yaw, "yaw", -1e6, 1e6);
  range(c.pitch, "pitch", -90.0, 90.0);
  range(c.distance, "distance", 1e-3, 1e4);
  for (int d = 0; d < 3; ++d) range(c.target[d], "target[" + std::to_string(d) + "]", -1e4, 1e4);
  range(c.fov, "fov", 1.0, 170.0);
}

void validateRenderSettings(const RenderSettings& r, const std::string& path) {
  auto range = [&](double v, const std::string& key, double lo, double hi) {
    if (!(v >= lo && v <= hi)) {
      std::ostringstream s;
      s << "expected a number between " << lo << " and " << hi << ", found " << v;
      fail(join(path, key), s.str());
    }
  };
  range(r.width, "width", 1, 16384);
  range(r.height, "height", 1, 16384);
  range(double(r.samples), "samples", 1, 1e11);
  range(r.skip, "skip", 0, 100000);
  for (int d = 0; d < 3; ++d) range(r.background[d], "background[" + std::to_string(d) + "]", 0.0, 1.0);
  range(r.depth_cue, "depth_cue", 0.0, 1.0);
}

namespace {

// Condensation and median functions (Sokolov & Gentil, §3.1–3.2) and the "volume" block.
void checkCondensationFunctions(const Project& project) {
  for (std::size_t f = 0; f < project.functions.size(); ++f) {
    const Function& fn = project.functions[f];
    if (!isSetKind(fn.kind)) continue;
    const std::string path = item("functions", f);
    if (project.space) fail(join(path, "kind"), "a project with control points (\"space\") needs \"matrix\" functions");
    if (!fn.ops.empty()) fail(join(path, "ops"), "a function with a condensation set has no grid, so no grid operations");
    checkCondensationSet(fn.set, join(path, "set"));
    if (!std::isfinite(fn.rotate) || std::abs(fn.rotate) > 1e5)
      fail(join(path, "rotate"), "expected degrees per unit distance between -100000 and 100000");
  }
  if (project.final_function && isSetKind(project.final_function->kind))
    fail("final.kind", "the final function must be a grid (a lattice)");
  if (project.volume) {
    const VolumeSettings& v = *project.volume;
    if (v.resolution < kMinVolumeResolution || v.resolution > kMaxVolumeResolution)
      fail("volume.resolution", "expected an integer between " + std::to_string(kMinVolumeResolution) + " and " +
                                    std::to_string(kMaxVolumeResolution));
    if (v.iterations < 1 || v.iterations > 1'000'000) fail("volume.iterations", "expected an integer between 1 and 1000000");
    if (v.skip < 0 || v.skip >= v.iterations) fail("volume.skip", "expected fewer skipped iterations than iterations");
    if (v.samples < 1 || v.samples > 100'000'000'000LL) fail("volume.samples", "expected between 1 and 1e11 samples");
  }
}

// Checks `project`; a function equal to the one at the same place of `trusted` (a project that
// passed these checks) keeps its verdict, so its operations are not checked again.
void validate(const Project& project, const Project* trusted) {
  validateCamera(project.camera, "camera");
  validateRenderSettings(project.render, "render");
  validateFlameSettings(project.render.flame, "render.flame");
  validateShadingSettings(project.render.shading, "render.shading");
  if (project.functions.empty()) fail("functions", "the IFS needs at least one function");
  if (project.functions.size() > std::size_t(limits::kMaxFunctions))
    fail("functions", "more than " + std::to_string(limits::kMaxFunctions) + " functions");
  std::int64_t totalNodes = 0;
  double totalWeight = 0.0;
  auto checkFunction = [&](const Function& fn, const std::string& path, const Function* before) {
    for (int d = 0; d < 3; ++d)
      if (fn.resolution[d] < limits::kMinResolution || fn.resolution[d] > limits::kMaxResolution)
        fail(item(join(path, "resolution"), d), "expected an integer between 2 and 128");
    totalNodes += std::int64_t(fn.resolution[0]) * fn.resolution[1] * fn.resolution[2];
    if (!(fn.weight >= 0.0) || !std::isfinite(fn.weight)) fail(join(path, "weight"), "expected a non-negative weight");
    if (before && before->ops == fn.ops) return;  // calculator parses and morph solves are the cost
    for (std::size_t o = 0; o < fn.ops.size(); ++o) {
      try {
        validateOperationParams(fn.ops[o].params);
      } catch (const ModelError& e) {
        throw e.under(item(join(path, "ops"), o));
      }
    }
  };
  for (std::size_t f = 0; f < project.functions.size(); ++f) {
    const Function* before = trusted && f < trusted->functions.size() ? &trusted->functions[f] : nullptr;
    checkFunction(project.functions[f], item("functions", f), before);
    if (!project.functions[f].muted) totalWeight += project.functions[f].weight;
  }
  if (project.final_function)
    checkFunction(*project.final_function, "final",
                  trusted && trusted->final_function ? &*trusted->final_function : nullptr);
  if (totalNodes > limits::kMaxTotalNodes)
    fail("functions", "the grids have " + std::to_string(totalNodes) + " nodes in all, more than the limit of " +
                          std::to_string(limits::kMaxTotalNodes));
  bool anyActive = false;
  for (const Function& fn : project.functions) anyActive |= !fn.muted;
  if (anyActive && !(totalWeight > 0.0))
    fail("functions", "every active function has weight 0 (weights must not all be zero)");
  checkTransitions(project);
  checkFreeForm(project);
  checkCondensationFunctions(project);
}

}  // namespace

void validateProject(const Project& project) { validate(project, nullptr); }

void validateProjectChange(const Project& project, const Project& previousValid) { validate(project, &previousValid); }

}  // namespace gridifs
