#include "ui/base/edit_queue.h"

#include <imgui.h>

namespace gridifs::ui {

void gestureItem(EditQueue& edits, const std::string& label, bool changed, ProjectEdit edit) {
  if (ImGui::IsItemActivated()) edits.begin(label);
  if (changed) edits.update(std::move(edit));
  if (ImGui::IsItemDeactivated()) edits.end();
}

}  // namespace gridifs::ui
