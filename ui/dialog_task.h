#pragma once
// The background work of a modal dialog (Export mesh/points, Render animation): one worker thread
// with progress and cancelling, its outcome handed back to the UI thread, and the dialog's centred
// modal window. The dialogs keep only their options and what their work does.
//
// Thread-safety: start(), poll(), join() and the destructor on the UI thread; progress(),
// cancelled() and finish() from the worker as well.
#include <atomic>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace gridifs::ui {

/// Where a dialog stands: choosing options, working, or the outcome of its last run.
enum class TaskPhase { Options, Running, Done, Failed, Cancelled };
/// "options", "running", "done", "failed", "cancelled": for the GUI tests' probe.
const char* taskPhaseName(TaskPhase phase);

class DialogTask {
 public:
  DialogTask() = default;
  ~DialogTask();  // cancels and joins a running worker
  DialogTask(const DialogTask&) = delete;
  DialogTask& operator=(const DialogTask&) = delete;

  /// Joins a finished worker, resets progress and cancelling, and runs `work` on a new thread.
  /// `work` reports its outcome with finish().
  void start(std::function<void()> work);
  bool running() const { return running_.load(); }
  void join();

  double progress() const { return progress_.load(); }
  void setProgress(double fraction) { progress_ = fraction; }
  void cancel() { cancel_ = true; }
  bool cancelled() const { return cancel_.load(); }
  /// The flag itself, for work that polls an std::atomic<bool>* (runDeterministic).
  std::atomic<bool>* cancelFlag() { return &cancel_; }

  /// From the worker, last: its outcome (Done, Failed or Cancelled) and the message to show.
  void finish(TaskPhase phase, std::string message);
  /// On the UI thread every frame: true once after the worker finished, with its outcome.
  bool poll(TaskPhase& phase, std::string& message);

 private:
  std::thread worker_;
  std::atomic<bool> running_{false}, cancel_{false};
  std::atomic<double> progress_{0.0};
  std::mutex mutex_;
  bool haveResult_ = false;
  TaskPhase result_ = TaskPhase::Options;
  std::string resultMessage_;
};

/// The dialog's modal `title`, centred, `widthEm` font sizes wide and as tall as its contents (at
/// most 90% of the window). Opens it when `justOpened` is set (and clears it); offers the close
/// box only while not `busy`. Returns false when it is not shown, clearing `open` unless busy;
/// otherwise the caller draws the contents and calls endTaskModal.
bool beginTaskModal(const char* title, float widthEm, bool busy, bool& open, bool& justOpened, bool& keepOpen);
/// Ends the modal; closing its box closes the dialog.
void endTaskModal(bool keepOpen, bool& open);

}  // namespace gridifs::ui
