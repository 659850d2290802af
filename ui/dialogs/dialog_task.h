#pragma once
// The background work of a modal dialog (Export mesh/points, Render animation): one worker thread
// with progress and cancelling, its outcome handed back to the UI thread, and the dialog's centred
// modal window. The dialogs keep only their options and what their work does.
//
// Thread-safety: every method on the UI thread; the work runs on the task's BackgroundJob thread
// and reaches the task only through its JobContext (progress, stopRequested, stopFlag).
#include <functional>
#include <string>

#include "base/background_job.h"

namespace gridifs::ui {

/// Where a dialog stands: choosing options, working, or the outcome of its last run.
enum class TaskPhase { Options, Running, Done, Failed, Cancelled };
/// "options", "running", "done", "failed", "cancelled": for the GUI tests' probe.
const char* taskPhaseName(TaskPhase phase);

/// A run's outcome: Done, Failed or Cancelled, and the message to show.
struct TaskOutcome {
  TaskPhase phase = TaskPhase::Done;
  std::string message;
};

class DialogTask {
 public:
  /// The work: polls context.stopRequested() (Cancel) and reports context.progress(); returns its
  /// outcome, which poll() hands to the UI thread.
  using Work = std::function<TaskOutcome(JobContext& context)>;

  /// Runs `work` on the task's worker thread (the dialogs start only while not running()).
  void start(Work work);
  bool running() const { return job_.busy(); }

  double progress() const { return job_.progress().fraction; }
  /// Asks the work to stop; it still reports its outcome (how far it got).
  void cancel() { job_.interrupt(); }
  bool cancelled() const { return job_.interrupted(); }

  /// On the UI thread every frame: true once after the worker finished, with its outcome.
  bool poll(TaskPhase& phase, std::string& message);

 private:
  // Destroyed with the dialog: marks the work stale (stopRequested) and joins it.
  BackgroundJob<Work, TaskOutcome> job_{
      [](const Work& work, BackgroundJob<Work, TaskOutcome>::Context& context) { context.publish(work(context)); }};
};

/// The dialog's modal `title`, centred, `widthEm` font sizes wide and as tall as its contents (at
/// most 90% of the window). Opens it when `justOpened` is set (and clears it); offers the close
/// box only while not `busy`. Returns false when it is not shown, clearing `open` unless busy;
/// otherwise the caller draws the contents and calls endTaskModal.
bool beginTaskModal(const char* title, float widthEm, bool busy, bool& open, bool& justOpened, bool& keepOpen);
/// Ends the modal; closing its box closes the dialog.
void endTaskModal(bool keepOpen, bool& open);

}  // namespace gridifs::ui
