#pragma once
// The one Document: the project plus undo/redo by whole-project snapshots.
// The UI edits the project only through edit()/gestures; each committed edit is one undo step.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "model/evaluation_cache.h"
#include "model/grid.h"
#include "model/project.h"

namespace gridifs {

/// Not thread-safe: owned and used by one thread (the UI thread, or a CLI verb).
class Document {
 public:
  using Change = std::function<void(Project&)>;

  explicit Document(Project project = {});

  const Project& project() const { return project_; }
  const std::filesystem::path& path() const { return path_; }
  /// Bumped on every change of the project (edits, gesture updates, undo, redo, open).
  std::uint64_t revision() const { return revision_; }
  /// Whether the project differs from what was last saved or opened.
  bool dirty() const { return project_ != saved_; }

  /// Applies `change` as one undo step. The result is validated first: an invalid
  /// project throws ModelError and leaves the document untouched. No-op changes push nothing.
  void edit(const std::string& label, const Change& change);

  /// A gesture (slider drag, node drag) previews live and commits one undo step on end.
  void beginGesture(const std::string& label);
  /// Throws ModelError and keeps the last valid state when the change is invalid.
  void updateGesture(const Change& change);
  void endGesture();
  void cancelGesture();
  bool inGesture() const { return gesture_.has_value(); }

  bool canUndo() const { return !undo_.empty(); }
  bool canRedo() const { return !redo_.empty(); }
  std::string undoLabel() const { return undo_.empty() ? "" : undo_.back().label; }
  std::string redoLabel() const { return redo_.empty() ? "" : redo_.back().label; }
  bool undo();
  bool redo();

  /// Replaces everything (New/Open): clears history, the result counts as saved.
  void reset(Project project, std::filesystem::path path = {});
  /// Records that the current project is what `path` now holds.
  void markSaved(const std::filesystem::path& path);

  /// The evaluated (distorted and placed) grid of function `index`, cached until the
  /// function changes. Throws ModelError with a path such as `functions[1].ops[2].x`.
  std::shared_ptr<const Grid> evaluatedGrid(std::size_t index) const;
  /// The same for the final function; null when there is none.
  std::shared_ptr<const Grid> evaluatedFinal() const;
  /// The cache behind evaluatedGrid: hand it with project() to compileIfs or
  /// snapshotDeterministicIfs. Valid while the Document lives; same thread only.
  const EvaluationCache& evaluation() const { return evaluation_; }

  static constexpr std::size_t kMaxUndoSteps = 500;

 private:
  struct Step {
    Project project;
    std::string label;
  };
  void commit(Project before, const std::string& label);
  /// Throws ModelError when `next` is invalid.
  void validate(const Project& next);

  Project project_, saved_;
  std::filesystem::path path_;
  std::uint64_t revision_ = 1;
  std::vector<Step> undo_, redo_;
  std::optional<Step> gesture_;
  EvaluationCache evaluation_;
  bool validated_ = false;  // project_ passed validation (edits then re-check changed functions only)
};

}  // namespace gridifs
