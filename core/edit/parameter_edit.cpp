#include "edit/parameter_edit.h"

#include "anim/track_path.h"
#include "base/errors.h"
#include "schema/project_parameter.h"
#include "schema/settings_tables.h"

namespace gridifs {
namespace {

ProjectParameter numberAt(const Project& project, const std::string& path) {
  const std::optional<TrackPath> parsed = TrackPath::parse(path);
  if (!parsed) throw ModelError(path, "is not a parameter path like functions[0].ops[1].k");
  const FoundParameter found = findParameter(project, *parsed, ParameterScope::Edit);
  switch (found.lookup) {
    case ParameterLookup::Number:
      break;
    case ParameterLookup::NotANumber:
      throw ModelError(path, "is not a number (a string, a switch, a list or an object)");
    case ParameterLookup::Missing:
      throw ModelError(path, "names nothing this project holds");
  }
  return found.parameter;
}

}  // namespace

void SetParameter::apply(Project& project) const {
  const ProjectParameter parameter = numberAt(project, path);
  if (!parameter.inAnimation()) {
    parameter.set(project, value);
    return;
  }
  // The timeline's rules (an end not before its start) are checked by reading the file, not by
  // validateProject, so an edit checks them here.
  const AnimationSettings before = *project.animation;
  parameter.set(project, value);
  try {
    validateSettings(animationSettingsTable(), *project.animation, "animation");
  } catch (const ModelError&) {
    *project.animation = before;
    throw;
  }
}

double parameterValue(const Project& project, const std::string& path) { return numberAt(project, path).get(project); }

}  // namespace gridifs
