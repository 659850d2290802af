#pragma once
// The set editor of a condensation or median function (Sokolov & Gentil, §3.1–3.2, §4.1): a
// primitive (sphere, box, torus) with its numbers, a mesh file with its fill and placement, or a
// VDB file with its grid and threshold; a median function's rotation. Drawn where the Operations
// panel stands while such a function is active (a set function has no operation stack).
#include <string>

#include "ui/base/edit_queue.h"
#include "ui/base/file_browser.h"
#include "ui/base/modeller_state.h"

namespace gridifs::ui {

class CondensationSetPanel {
 public:
  void draw(ModellerState& state, EditQueue& edits);
  /// Why the set of the active function could not be drawn ("" when it could), for the probe.
  const std::string& message() const { return message_; }
  void clearMessage() { message_.clear(); }

 private:
  void drawFile(ModellerState& state, EditQueue& edits, FunctionRef ref, const CondensationSet& set);

  /// Opens the browser for a mesh or VDB file of the active function; its set takes `shape`
  /// once a file is chosen.
  void browse(ModellerState& state, const CondensationSet& set, SetShape shape);

  FileBrowser browser_;
  FunctionRef browsing_;                   // the function whose file the browser picks
  SetShape browsingFor_ = SetShape::Mesh;  // and the shape its set takes with that file
  std::string pathText_;                   // the file name as typed, while its field is being edited
  bool editingPath_ = false;
  std::string message_;  // why the set could not be drawn
};

}  // namespace gridifs::ui
