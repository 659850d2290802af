#include "schema/validation.h"

#include <cmath>
#include <sstream>

#include "freeform/free_form.h"
#include "freeform/state_expansion.h"
#include "freeform/transition_matrix.h"
#include "model/calculator.h"
#include "schema/field_layer.h"
#include "schema/operation_table.h"
#include "schema/settings_tables.h"

namespace gridifs {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& message) { throw ModelError(path, message); }

std::string join(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }
std::string item(const std::string& path, std::size_t index) { return path + "[" + std::to_string(index) + "]"; }

std::string rowPath(std::size_t i) { return "transitions[" + std::to_string(i) + "]"; }
std::string entryPath(std::size_t i, std::size_t j) { return rowPath(i) + "[" + std::to_string(j) + "]"; }

/// Checks `project.transitions` against its functions: N×N with N the number of functions,
/// finite non-negative entries, and every unmuted function's row has a positive entry on an
/// unmuted function. Throws ModelError with a JSON path (`transitions[2][1]`).
void checkTransitions(const Project& project) {
  const auto& t = project.transitions;
  if (t.empty()) return;
  const std::size_t n = project.functions.size();
  if (t.size() != n)
    throw ModelError("transitions",
                     "expected " + std::to_string(n) + " rows (one per function), found " + std::to_string(t.size()));
  for (std::size_t i = 0; i < n; ++i) {
    if (t[i].size() != n)
      throw ModelError(rowPath(i), "expected " + std::to_string(n) + " entries (one per function), found " +
                                       std::to_string(t[i].size()));
    for (std::size_t j = 0; j < n; ++j) {
      // The file reader's range and words (io/project_io).
      const FieldInfo& weight = transitionWeightField();
      if (!std::isfinite(t[i][j])) throw ModelError(entryPath(i, j), "expected a finite number");
      if (!(t[i][j] >= weight.min && t[i][j] <= weight.max)) {
        std::ostringstream message;
        message << "expected a number between " << weight.min << " and " << weight.max << ", found " << t[i][j];
        throw ModelError(entryPath(i, j), message.str());
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (project.functions[i].muted) continue;
    bool any = false;
    for (std::size_t j = 0; j < n; ++j) any |= !project.functions[j].muted && t[i][j] > 0.0;
    if (!any)
      throw ModelError(rowPath(i), "function " + std::to_string(i) +
                                       " can be followed by no unmuted function (the row needs a positive entry)");
  }
}

}  // namespace

void validateFlameSettings(const FlameSettings& f, const std::string& path) {
  validateSettings(flameSettingsTable(), f, path);
}

void validateCamera(const Camera& c, const std::string& path) {
  validateSettings(cameraTable(), c, path);
  if (c.stereo) validateSettings(stereoTable(), *c.stereo, join(path, "stereo"));
}

void validateRenderSettings(const RenderSettings& r, const std::string& path) {
  validateSettings(renderSettingsTable(), r, path);
}

void validateShadingSettings(const ShadingSettings& s, const std::string& path) {
  const std::string lights = settingPath(path, "lights");
  if (s.lights.size() > std::size_t(limits::kMaxLights))
    throw ModelError(lights, "at most " + std::to_string(limits::kMaxLights) + " lights are supported, found " +
                                 std::to_string(s.lights.size()));
  for (std::size_t i = 0; i < s.lights.size(); ++i)
    validateSettings(shadingLightTable(), s.lights[i], lights + "[" + std::to_string(i) + "]");
  validateSettings(shadingSettingsTable(), s, path);
  validateSettings(ambientOcclusionTable(), s.ao, settingPath(path, "ao"));
  validateSettings(fogTable(), s.fog, settingPath(path, "fog"));
  validateSettings(depthOfFieldTable(), s.dof, settingPath(path, "dof"));
}

void checkCondensationSet(const CondensationSet& set, const std::string& path) {
  const bool placed = set.shape == SetShape::Mesh || set.shape == SetShape::Image;
  if (set.shape == SetShape::Image && set.path.empty()) fail(join(path, "image"), "expected a file name");
  validateSettings(condensationSetTable(set.shape), set, path);
  if (set.shape == SetShape::Mesh && set.path.empty()) fail(join(path, "mesh"), "expected a file name");
  if (set.shape == SetShape::Vdb) {
    if (set.path.empty()) fail(join(path, "vdb"), "expected a file name");
    if (set.grid.empty()) fail(join(path, "grid"), "expected a grid name");
  }
  if (!placed) return;
  validateSettings(placementTable(), set.placement, join(path, "placement"));
  for (int d = 0; d < 3; ++d)
    if (set.placement.scale[d] == 0.0) fail(join(path, "placement.scale"), "a zero scale flattens the mesh");
}

void validateVolumeRender(const VolumeRenderSettings& s, const std::string& path) {
  validateSettings(volumeRenderTable(), s, path);
  const std::string transfer = settingPath(path, "transfer");
  if (s.transfer.size() > std::size_t(kMaxTransferStops))
    fail(transfer, "more than " + std::to_string(kMaxTransferStops) + " stops");
  for (std::size_t i = 0; i < s.transfer.size(); ++i) {
    const std::string p = item(transfer, i);
    validateSettings(transferStopTable(), s.transfer[i], p);
    if (i > 0 && !(s.transfer[i].density > s.transfer[i - 1].density))
      fail(p + ".density", "the stops must be sorted by increasing density");
  }
}

namespace {

// Condensation and median functions (Sokolov & Gentil, §3.1–3.2) and the "volume" block.
void checkCondensationFunctions(const Project& project) {
  for (std::size_t f = 0; f < project.functions.size(); ++f) {
    const Function& fn = project.functions[f];
    if (!isSetKind(fn.kind)) continue;
    const std::string path = item("functions", f);
    if (project.space) fail(join(path, "kind"), "a project with control points (\"space\") needs \"matrix\" functions");
    if (!fn.ops.empty())
      fail(join(path, "ops"), "a function with a condensation set has no grid, so no grid operations");
    checkCondensationSet(fn.set, join(path, "set"));
    if (fn.kind != FunctionKind::Median) continue;
    const FieldInfo& rotate = medianRotateField();
    if (!settingInRange(rotate, fn.rotate)) fail(join(path, rotate.key), numberRangeMessage(rotate, fn.rotate));
    const FieldInfo& axisField = medianRotateAxisField();
    const Vec3& axis = fn.rotate_axis;
    for (int d = 0; d < 3; ++d)
      if (!settingInRange(axisField, axis[d]))
        fail(item(join(path, axisField.key), d), numberRangeMessage(axisField, axis[d]));
    if (!(std::abs(axis.x) + std::abs(axis.y) + std::abs(axis.z) > 1e-9))
      fail(join(path, axisField.key), "expected a non-zero axis");
  }
  if (project.final_function && isSetKind(project.final_function->kind))
    fail("final.kind", "the final function must be a grid (a lattice)");
  if (project.volume) {
    validateSettings(volumeSettingsTable(), *project.volume, "volume");
    const VolumeSettings& volume = *project.volume;
    if (volume.start) checkCondensationSet(*volume.start, "volume.start");
    if (!volume.field && !volume.more_fields.empty()) fail("volume.field", "further field layers need a first one");
    // A single field is "volume.field"; a list's layers are "volume.field[i]".
    const bool list = !volume.more_fields.empty();
    if (volume.field) checkFieldLayer(*volume.field, list ? "volume.field[0]" : "volume.field");
    for (std::size_t i = 0; i < volume.more_fields.size(); ++i)
      checkFieldLayer(volume.more_fields[i], "volume.field[" + std::to_string(i + 1) + "]");
  }
}

// Checks `project`; a function equal to the one at the same place of `trusted` (a project that
// passed these checks) keeps its verdict, so its operations are not checked again.
void validate(const Project& project, const Project* trusted) {
  validateCamera(project.camera, "camera");
  validateRenderSettings(project.render, "render");
  validateFlameSettings(project.render.flame, "render.flame");
  validateShadingSettings(project.render.shading, "render.shading");
  if (project.render.volume) validateVolumeRender(*project.render.volume, "render.volume");
  if (project.functions.empty()) fail("functions", "the IFS needs at least one function");
  if (project.functions.size() > std::size_t(limits::kMaxFunctions))
    fail("functions", "more than " + std::to_string(limits::kMaxFunctions) + " functions");
  std::int64_t totalNodes = 0;
  double totalWeight = 0.0;
  auto checkFunction = [&](const Function& fn, const std::string& path, const Function* before) {
    const FieldInfo& resolution = gridResolutionField();
    for (int d = 0; d < 3; ++d)
      if (fn.resolution[d] < resolution.min || fn.resolution[d] > resolution.max)
        fail(item(join(path, resolution.key), d), integerRangeMessage(resolution));
    totalNodes += std::int64_t(fn.resolution[0]) * fn.resolution[1] * fn.resolution[2];
    validateSettings(functionTable(), fn, path);
    validateSettings(placementTable(), fn.placement, join(path, "placement"));
    if (fn.post && !fn.post->matrix) validateSettings(placementTable(), fn.post->placement, join(path, "post"));
    if (fn.hasVariationStage() && fn.kind != FunctionKind::Grid)
      fail(join(path, "variations"), "flame variations apply to grid functions only");
    try {
      validateFunctionVariations(fn.variations, fn.variation_params);
    } catch (const ModelError& e) {
      throw e.under(path);
    }
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
  checkStates(project);
  checkFreeForm(project);
  checkCondensationFunctions(project);
  if (project.construction) checkConstructionTree(*project.construction);
}

}  // namespace

void validateProject(const Project& project) { validate(project, nullptr); }

void validateProjectChange(const Project& project, const Project& previousValid) { validate(project, &previousValid); }

}  // namespace gridifs
