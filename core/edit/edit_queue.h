#pragma once
// Edits collected while the UI is built and applied to the Document afterwards (the fixed
// frame order: build UI → apply edits). Widgets edit local copies and enqueue one named
// edit (edit/project_edit.h), the one vocabulary of changes; a slider drag is one gesture (begin on IsItemActivated,
// end on deactivation). Headless: the modeller's widgets fill it (ui/base/edit_queue.h), tests drive it directly.
//
// Thread-safety: used by the thread that owns the Document.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "edit/document.h"

namespace gridifs {

class EditQueue {
 public:
  /// One undo step: a named edit (edit/project_edit.h), named by its label() or by `label`.
  void commit(ProjectEdit edit);
  void commit(std::string label, ProjectEdit edit);
  /// A live-previewed gesture: begin, any number of updates, end (one undo step).
  void begin(std::string label);
  void update(ProjectEdit edit);
  void end();
  void cancel();
  void undo();
  void redo();
  /// Runs after this frame's document edits (file actions, selection changes that must see
  /// the edited document).
  void after(std::function<void()> action);

  bool empty() const { return items_.empty() && after_.empty(); }

  /// Applies everything in order. A change the Document rejects (ModelError) is dropped and
  /// its message returned (the last one); the document keeps its last valid state.
  std::string apply(Document& document);

 private:
  enum class Kind { Commit, Begin, Update, End, Cancel, Undo, Redo };
  struct Item {
    Kind kind;
    std::string label;
    std::optional<ProjectEdit> edit;  // Commit and Update
  };
  std::vector<Item> items_;
  std::vector<std::function<void()>> after_;
};

}  // namespace gridifs
