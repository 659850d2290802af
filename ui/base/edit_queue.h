#pragma once
// The modeller's edit queue (edit/edit_queue.h) and the ImGui side of a gesture.
#include <string>

#include "edit/edit_queue.h"

namespace gridifs::ui {

using gridifs::EditQueue;

/// The undo-per-gesture pattern for the ImGui item just submitted: begin on activation,
/// apply `edit` when `changed`, end on deactivation.
void gestureItem(EditQueue& edits, const std::string& label, bool changed, ProjectEdit edit);

}  // namespace gridifs::ui
