#include "schema/wind_drift.h"

#include <regex>

#include "anim/track_path.h"
#include "schema/project_parameter.h"

namespace gridifs {
namespace {

void clearDrift(Function& function) {
  for (Operation& op : function.ops)
    if (auto* field = std::get_if<FieldOp>(&op.params)) field->drift.reset();
}

/// The field whose wind component the canonical parameter path names, or null.
FractalFieldParams* windOf(Project& project, const std::string& path, int& component) {
  static const std::regex kOpWind(R"(^(?:functions\[(\d+)\]|(final))\.ops\[(\d+)\]\.wind\[([012])\]$)");
  static const std::regex kVolumeWind(R"(^volume\.field(?:\[(\d+)\])?\.wind\[([012])\]$)");
  std::smatch m;
  if (std::regex_match(path, m, kVolumeWind)) {
    component = std::stoi(m[2].str());
    if (!project.volume || !project.volume->field) return nullptr;
    const std::size_t layer = m[1].matched ? std::stoul(m[1].str()) : 0;
    if (layer == 0) return &project.volume->field->field;
    return layer <= project.volume->more_fields.size() ? &project.volume->more_fields[layer - 1].field : nullptr;
  }
  if (!std::regex_match(path, m, kOpWind)) return nullptr;
  component = std::stoi(m[4].str());
  Function* function = nullptr;
  if (m[2].matched) {
    if (project.final_function) function = &*project.final_function;
  } else if (const std::size_t f = std::stoul(m[1].str()); f < project.functions.size()) {
    function = &project.functions[f];
  }
  const std::size_t op = std::stoul(m[3].str());
  if (!function || op >= function->ops.size()) return nullptr;
  return std::get_if<FieldOp>(&function->ops[op].params);
}

}  // namespace

void applyWindDrift(Project& project) {
  for (Function& function : project.functions) clearDrift(function);
  if (project.final_function) clearDrift(*project.final_function);
  if (project.volume) {
    if (project.volume->field) project.volume->field->field.drift.reset();
    for (VolumeDensityField& layer : project.volume->more_fields) layer.field.drift.reset();
  }
  for (const auto& [path, track] : project.tracks) {
    if (track.keys.empty() || path.find("wind") == std::string::npos) continue;
    const std::optional<TrackPath> parsed = TrackPath::parse(path);
    if (!parsed) continue;
    const FoundParameter found = findParameter(project, *parsed);
    if (found.lookup != ParameterLookup::Number) continue;
    int component = 0;
    FractalFieldParams* field = windOf(project, found.parameter.path(), component);
    if (!field) continue;
    // The components nobody keys keep the constant wind's displacement.
    if (!field->drift) field->drift = field->wind * project.time;
    (*field->drift)[component] = track.integral(0.0, project.time);
  }
}

}  // namespace gridifs
