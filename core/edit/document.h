#pragma once
// The one Document: the project plus undo/redo by whole-project snapshots.
// The UI edits the project only through named edits (edit/project_edit.h), applied as one undo
// step or as the updates of one gesture; edit() takes any change, for tests and headless callers.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "edit/project_edit.h"
#include "model/evaluation_cache.h"
#include "model/grid.h"
#include "model/project.h"

namespace gridifs {

/// What changed in a project, by concern: each field is the Document::revision() at which that
/// concern last changed, so a consumer keeps the numbers it last saw and compares integers
/// instead of copying and comparing projects.
struct Revisions {
  std::uint64_t geometry = 1;  // functions and the final function (what compileIfs reads)
  std::uint64_t render = 1;    // render inputs of the chaos game: size, samples, seed, skip, palette
  std::uint64_t display = 1;   // how buffers become a picture: background, depth cue, mode, tone map
  std::uint64_t camera = 1;
  bool operator==(const Revisions&) const = default;
};

/// Whether two render settings give the same picture from the same buffers (background, depth
/// cue, display mode, the flame tone mapping and the shading; the palette is a render input).
bool sameDisplay(const RenderSettings& a, const RenderSettings& b);
/// Whether two render settings drive the chaos game the same way (everything but the display;
/// in the shaded mode the directions of shadowed lights and the depth of field are render inputs).
bool sameRenderInput(const RenderSettings& a, const RenderSettings& b);

/// Not thread-safe: owned and used by one thread (the UI thread, or a CLI verb).
class Document {
 public:
  explicit Document(Project project = {});

  const Project& project() const { return project_; }
  const std::filesystem::path& path() const { return path_; }
  /// Bumped on every change of the project (edits, gesture updates, undo, redo, open).
  std::uint64_t revision() const { return revision_; }
  /// The revision at which each concern last changed (all bumped by reset()).
  const Revisions& revisions() const { return revisions_; }
  /// Whether the project differs from what was last saved or opened.
  bool dirty() const { return project_ != saved_; }

  /// A named edit (edit/project_edit.h, the one vocabulary of changes) as one undo step named by
  /// its label() or by `label`. The result is validated first: an invalid project, or an edit
  /// that names something the project lacks, throws ModelError and leaves the document
  /// untouched. An edit that changes nothing pushes nothing.
  void apply(const ProjectEdit& edit);
  void apply(const std::string& label, const ProjectEdit& edit);
  /// A named edit like apply(), validated, but without an undo step (the modeller's playhead,
  /// SetTime: artists scrub and play without filling the history). Undo and redo keep it.
  void applyUnrecorded(const ProjectEdit& edit);
  /// A value from live input or sound (schema/live_binding.h): like applyUnrecorded(), but outside
  /// the keyframing rule, so a bound number moves over its track without being keyed.
  void applyLiveValue(const ProjectEdit& edit);

  /// A rule applied to every change after it is made and before it is validated, given the
  /// project before and after (the modeller's keyframing: schema/project_time.h
  /// keyEditedParameters). Undo and redo apply it with `before` equal to the restored project
  /// whose time is set to the current one, so unrecorded time changes survive them.
  using Rule = std::function<Project(const Project& before, Project next)>;
  void setRule(Rule rule) { rule_ = std::move(rule); }

  /// A gesture (slider drag, node drag) previews live and commits one undo step on end.
  void beginGesture(const std::string& label);
  /// Throws ModelError and keeps the last valid state when the change is invalid.
  void updateGesture(const ProjectEdit& edit);
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
  /// The undo and redo history together keep at most this much (approximateMemory of their
  /// snapshots); the oldest undo steps are dropped first. The newest step always stays.
  static constexpr std::size_t kMaxHistoryBytes = std::size_t(256) << 20;
  /// Bytes the history holds now (for the Help window and tests).
  std::size_t historyBytes() const { return historyBytes_; }

 private:
  struct Step {
    Project project;
    std::string label;
    std::size_t bytes = 0;  // approximateMemory(project)
  };
  /// Appends a step to `to`, counting its memory; drops the oldest undo steps past the caps.
  void push(std::vector<Step>& to, Project project, std::string label);
  void commit(Project before, const std::string& label);
  /// Bumps revision() and the revisions of the concerns that differ from `before`.
  void changed(const Project& before);
  /// Undo (from undo_ to redo_) or redo (the other way): one step through the history.
  bool travel(std::vector<Step>& from, std::vector<Step>& to);
  /// Throws ModelError when `next` is invalid.
  void validate(const Project& next);
  /// Applies `edit` to a copy, validates and publishes it; false (and nothing changed) when the
  /// edit changes nothing. `before` receives the project as it was.
  bool applyChange(const ProjectEdit& edit, Project& before);

  Project project_, saved_;
  std::filesystem::path path_;
  std::uint64_t revision_ = 1;
  Revisions revisions_;
  std::vector<Step> undo_, redo_;
  std::size_t historyBytes_ = 0;  // of undo_ and redo_
  std::optional<Step> gesture_;
  Rule rule_;
  EvaluationCache evaluation_;
  bool validated_ = false;  // project_ passed validation (edits then re-check changed functions only)
};

}  // namespace gridifs
