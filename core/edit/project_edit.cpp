#include "edit/project_edit.h"

namespace gridifs {

void ReplaceProject::apply(Project& target) const { target = project; }

void applyEdit(Project& project, const ProjectEdit& edit) {
  std::visit([&project](const auto& e) { e.apply(project); }, edit);
}

std::string editLabel(const ProjectEdit& edit) {
  return std::visit([](const auto& e) { return e.label(); }, edit);
}

}  // namespace gridifs
