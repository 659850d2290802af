#include "edit/document.h"

#include "base/errors.h"
#include "model/stack_evaluator.h"
#include "schema/live_binding.h"
#include "schema/validation.h"

namespace gridifs {

namespace {

/// What the shaded display asks of the chaos game: a depth buffer per shadowed light (its
/// direction) and the depth-of-field lens. Nothing outside the shaded mode.
std::vector<double> shadedChaosInputs(const RenderSettings& r) {
  std::vector<double> inputs;
  if (r.mode != DisplayMode::Shaded) return inputs;
  for (const ShadingLight& l : r.shading.lights)
    if (l.shadows) inputs.insert(inputs.end(), {l.direction.x, l.direction.y, l.direction.z});
  inputs.push_back(-1.0);  // separates the lights from the lens
  if (r.shading.dof.focus && r.shading.dof.aperture > 0.0)
    inputs.insert(inputs.end(), {r.shading.dof.aperture, *r.shading.dof.focus});
  return inputs;
}

}  // namespace

bool sameDisplay(const RenderSettings& a, const RenderSettings& b) {
  FlameSettings toneA = a.flame, toneB = b.flame;
  // The palette (its reference, gradient keys and hue) is looked up per sample: a render input.
  toneA.palette = toneB.palette = toneA.palette_keys = toneB.palette_keys = "";
  toneA.hue = toneB.hue = 0.0;
  return a.background == b.background && a.depth_cue == b.depth_cue && a.mode == b.mode && toneA == toneB &&
         a.shading == b.shading;
}

bool sameRenderInput(const RenderSettings& a, const RenderSettings& b) {
  return a.width == b.width && a.height == b.height && a.samples == b.samples && a.quality == b.quality &&
         a.seed == b.seed && a.skip == b.skip && a.flame.palette == b.flame.palette &&
         a.flame.palette_keys == b.flame.palette_keys && a.flame.hue == b.flame.hue &&
         shadedChaosInputs(a) == shadedChaosInputs(b);
}

Document::Document(Project project) : project_(std::move(project)), saved_(project_) {
  if (project_.functions.empty()) project_ = saved_ = defaultNewProject();
}

void Document::push(std::vector<Step>& to, Project project, std::string label) {
  const std::size_t bytes = approximateMemory(project);
  to.push_back({std::move(project), std::move(label), bytes});
  historyBytes_ += bytes;
  while (!undo_.empty() && (undo_.size() > kMaxUndoSteps || historyBytes_ > kMaxHistoryBytes) &&
         undo_.size() + redo_.size() > 1) {
    historyBytes_ -= undo_.front().bytes;
    undo_.erase(undo_.begin());
  }
}

void Document::commit(Project before, const std::string& label) {
  if (before == project_) return;
  for (const Step& step : redo_) historyBytes_ -= step.bytes;
  redo_.clear();
  push(undo_, std::move(before), label);
}

bool Document::applyChange(const ProjectEdit& edit, Project& before) {
  Project next = project_;
  applyEdit(next, edit);
  if (rule_) next = rule_(project_, std::move(next));
  // Bindings of numbers the change removed go with them (undo brings both back).
  if (!next.bindings.empty()) dropUnresolvedBindings(next);
  if (next == project_) return false;
  validate(next);
  std::swap(project_, next);
  changed(next);
  before = std::move(next);
  return true;
}

void Document::apply(const ProjectEdit& edit) { apply(editLabel(edit), edit); }

void Document::apply(const std::string& label, const ProjectEdit& edit) {
  if (gesture_) endGesture();
  Project before;
  if (applyChange(edit, before)) commit(std::move(before), label);
}

void Document::applyUnrecorded(const ProjectEdit& edit) {
  Project before;
  applyChange(edit, before);
}

void Document::applyLiveValue(const ProjectEdit& edit) {
  Rule rule = std::move(rule_);
  rule_ = nullptr;
  try {
    applyUnrecorded(edit);
  } catch (...) {
    rule_ = std::move(rule);
    throw;
  }
  rule_ = std::move(rule);
}

void Document::validate(const Project& next) {
  // After a checked edit only the functions that changed are checked again; a project that came
  // from outside (constructor, reset, undo history from before) gets the full check once.
  if (validated_)
    validateProjectChange(next, project_);
  else
    validateProject(next);
  validated_ = true;
}

void Document::beginGesture(const std::string& label) {
  if (gesture_) endGesture();
  gesture_ = Step{project_, label};
}

void Document::updateGesture(const ProjectEdit& edit) {
  if (!gesture_) beginGesture("Edit");
  Project before;
  applyChange(edit, before);
}

void Document::endGesture() {
  if (!gesture_) return;
  Step step = std::move(*gesture_);
  gesture_.reset();
  commit(std::move(step.project), step.label);
}

void Document::cancelGesture() {
  if (!gesture_) return;
  if (project_ != gesture_->project) {
    std::swap(project_, gesture_->project);
    validated_ = false;
    changed(gesture_->project);
  }
  gesture_.reset();
}

bool Document::travel(std::vector<Step>& from, std::vector<Step>& to) {
  if (gesture_) endGesture();
  if (from.empty()) return false;
  Step step = std::move(from.back());
  from.pop_back();
  historyBytes_ -= step.bytes;
  const double time = project_.time;
  push(to, std::move(project_), step.label);
  project_ = std::move(step.project);
  if (rule_ && project_.time != time) {
    // The playhead is not part of the history: the restored project is shown at the current time.
    Project at = project_;
    at.time = time;
    try {
      project_ = rule_(at, at);
    } catch (const ModelError&) {
      // A restored project was valid at its own time; it stays at that time.
    }
  }
  validated_ = false;
  changed(to.back().project);
  return true;
}

bool Document::undo() { return travel(undo_, redo_); }

bool Document::redo() { return travel(redo_, undo_); }

void Document::reset(Project project, std::filesystem::path path) {
  gesture_.reset();
  project_ = std::move(project);
  if (rule_) {
    // A file's stored values of animated parameters give way to their tracks at its time.
    try {
      project_ = rule_(project_, project_);
    } catch (const ModelError&) {
      // The file was checked when it was read; what the rule cannot apply stays as stored.
    }
  }
  saved_ = project_;
  validated_ = false;
  path_ = std::move(path);
  undo_.clear();
  redo_.clear();
  historyBytes_ = 0;
  ++revision_;
  revisions_.geometry = revisions_.render = revisions_.display = revisions_.camera = revision_;
}

void Document::changed(const Project& before) {
  // Every field of Project belongs to one concern here; a new field must join one.
  ++revision_;
  const Project& now = project_;
  // A new time changes the geometry only where an operation reads it (a field op, a calculator's
  // t); keyed parameters already show up as changed functions.
  auto readsTime = [](const Project& p) {
    for (const Function& f : p.functions)
      if (dependsOnTime(f)) return true;
    return p.final_function && dependsOnTime(*p.final_function);
  };
  // The control points of a free-form IFS are geometry too: every matrix function plots through them.
  if (now.functions != before.functions || now.final_function != before.final_function ||
      now.transitions != before.transitions || now.states != before.states || now.space != before.space ||
      (now.time != before.time && readsTime(now)))
    revisions_.geometry = revision_;
  if (now.camera != before.camera) revisions_.camera = revision_;
  if (!sameRenderInput(now.render, before.render)) revisions_.render = revision_;
  if (!sameDisplay(now.render, before.render)) revisions_.display = revision_;
}

void Document::markSaved(const std::filesystem::path& path) {
  saved_ = project_;
  path_ = path;
}

std::shared_ptr<const Grid> Document::evaluatedGrid(std::size_t index) const {
  return evaluation_.function(project_, index);
}

std::shared_ptr<const Grid> Document::evaluatedFinal() const { return evaluation_.finalFunction(project_); }

}  // namespace gridifs
