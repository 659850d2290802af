#include "edit/edit_queue.h"

#include <exception>

namespace gridifs {

void EditQueue::commit(ProjectEdit edit) {
  std::string label = editLabel(edit);
  commit(std::move(label), std::move(edit));
}
void EditQueue::commit(std::string label, ProjectEdit edit) {
  items_.push_back({Kind::Commit, std::move(label), std::move(edit)});
}
void EditQueue::begin(std::string label) { items_.push_back({Kind::Begin, std::move(label), {}}); }
void EditQueue::update(ProjectEdit edit) { items_.push_back({Kind::Update, {}, std::move(edit)}); }
void EditQueue::end() { items_.push_back({Kind::End, {}, {}}); }
void EditQueue::cancel() { items_.push_back({Kind::Cancel, {}, {}}); }
void EditQueue::undo() { items_.push_back({Kind::Undo, {}, {}}); }
void EditQueue::redo() { items_.push_back({Kind::Redo, {}, {}}); }
void EditQueue::after(std::function<void()> action) { after_.push_back(std::move(action)); }

std::string EditQueue::apply(Document& document) {
  std::string error;
  for (Item& item : items_) {
    try {
      switch (item.kind) {
        case Kind::Commit:
          document.apply(item.label, *item.edit);
          break;
        case Kind::Begin:
          document.beginGesture(item.label);
          break;
        case Kind::Update:
          if (!document.inGesture()) document.beginGesture("Edit");
          document.updateGesture(*item.edit);
          break;
        case Kind::End:
          document.endGesture();
          break;
        case Kind::Cancel:
          document.cancelGesture();
          break;
        case Kind::Undo:
          document.undo();
          break;
        case Kind::Redo:
          document.redo();
          break;
      }
    } catch (const ModelError& e) {
      error = e.what();
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  items_.clear();
  auto actions = std::move(after_);
  after_.clear();
  for (auto& action : actions) action();
  return error;
}

}  // namespace gridifs
