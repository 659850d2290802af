#pragma once
// The volume transfer function's editor: density → colour and opacity as a list of stops
// (render.volume.transfer), with a strip that previews the colours weighted by their opacity.
// Every change is one undo step through the Document (SetTransferFunction; one per drag), and
// the same settings drive `gridifs render --mode volume`.
#include "ui/base/edit_queue.h"
#include "ui/base/modeller_state.h"

namespace gridifs::ui {

class TransferEditor {
 public:
  void toggle() { open_ = !open_; }
  bool isOpen() const { return open_; }
  /// Draws the window while it is open.
  void draw(ModellerState& state, EditQueue& edits);

 private:
  bool open_ = false;
};

}  // namespace gridifs::ui
