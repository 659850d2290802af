#pragma once
// One worker thread that turns immutable inputs into results, for the GUI's previews and dialogs:
// the renderer's generation handshake in a reusable form. Each submit() hands the worker a new
// input with the next generation number and supersedes the one before; the work polls a cheap
// stale() flag and stops early when it is set, and what a stale run publishes is dropped, so an
// older result never arrives after a newer one. The controlling thread polls the latest result
// without waiting: the internal mutex is held only to swap an input or a result in or out, never
// while the work runs or across a frame.
//
// Thread-safety: every public method of BackgroundJob may be called from any thread (the design
// is one controlling thread, the UI's); the work runs on the job's own thread and talks to the job
// only through its Context, whose methods are meant for that thread. The destructor marks the run
// stale, drops a pending input and joins the worker: it waits for the work's next stale() poll.
// Nothing here throws except std::system_error when the thread cannot start; an exception that
// escapes the work terminates the program, as with std::thread.
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

namespace gridifs {

/// A snapshot of a run's progress: `fraction` in [0, 1]; `done` of `total` when the work counts
/// in units (iterations, points), else both 0.
struct JobProgress {
  double fraction = 0.0;
  std::int64_t done = 0, total = 0;
};

/// What one run of a BackgroundJob's work sees of the job (used on the worker thread).
class JobContext {
 public:
  std::uint64_t generation() const { return run_->generation; }
  /// A newer input was submitted, cancel() was called or the job is being destroyed: stop soon,
  /// nothing this run publishes from now on is delivered. One relaxed atomic load.
  bool stale() const { return run_->stale.load(std::memory_order_relaxed); }
  /// stale(), or interrupt() asked this run to stop early while keeping what it publishes.
  bool stopRequested() const { return run_->stop.load(std::memory_order_relaxed); }
  /// The flag behind stopRequested(), for work that polls an std::atomic<bool>* (the mesh
  /// builder, the volume binning). Valid while the work runs.
  const std::atomic<bool>* stopFlag() const { return &run_->stop; }
  void progress(double fraction) { run_->fraction.store(fraction, std::memory_order_relaxed); }
  void progress(std::int64_t done, std::int64_t total) {
    run_->done.store(done, std::memory_order_relaxed);
    run_->total.store(total, std::memory_order_relaxed);
    run_->fraction.store(total > 0 ? double(done) / double(total) : 0.0, std::memory_order_relaxed);
  }

  /// Internal to BackgroundJob: one run's flags and progress. Each run has its own, so a stale run's progress never
  /// shows as the new one's.
  struct Run {
    explicit Run(std::uint64_t g) : generation(g) {}
    const std::uint64_t generation;
    std::atomic<bool> stale{false}, stop{false};
    std::atomic<double> fraction{0.0};
    std::atomic<std::int64_t> done{0}, total{0};
  };

 protected:
  explicit JobContext(std::shared_ptr<Run> run) : run_(std::move(run)) {}
  std::shared_ptr<Run> run_;
};

/// The job. `Input` is copied or moved in once and then only read; `Output` is moved out to the
/// poller. See the thread-safety note at the top of this file.
template <class Input, class Output>
class BackgroundJob {
 public:
  /// A result with the generation of the input it came from.
  struct Result {
    std::uint64_t generation = 0;
    Output value;
  };

  class Context : public JobContext {
   public:
    /// Offers a result (the final one, or a partial one of a progressive computation; a run may
    /// publish any number). Replaces a result not yet polled. Dropped, returning false, when the
    /// run is stale; the check and the store are one step under the job's mutex, so once submit()
    /// or cancel() has returned no older result can appear.
    bool publish(Output value) { return job_->publish(*run_, std::move(value)); }

   private:
    friend class BackgroundJob;
    Context(BackgroundJob* job, std::shared_ptr<Run> run) : JobContext(std::move(run)), job_(job) {}
    BackgroundJob* job_;
  };

  /// The work, run on the job's thread once per input it reaches (an input superseded before the
  /// worker took it is never run). It should poll context.stale() (or stopFlag()) every few
  /// milliseconds and return soon after it turns true.
  using Work = std::function<void(const Input&, Context&)>;

  explicit BackgroundJob(Work work) : work_(std::move(work)), thread_([this] { loop(); }) {}
  ~BackgroundJob() {
    {
      std::lock_guard lock(mutex_);
      quit_ = true;
      pending_.reset();
      if (running_) markStale(*running_);
    }
    wake_.notify_all();
    thread_.join();
  }
  BackgroundJob(const BackgroundJob&) = delete;
  BackgroundJob& operator=(const BackgroundJob&) = delete;

  /// Makes `input` the newest: the running work (if any) turns stale, an input the worker has not
  /// taken yet is dropped. Returns the input's generation (1, 2, ...). Never waits for the work.
  std::uint64_t submit(Input input) {
    std::uint64_t generation;
    {
      std::lock_guard lock(mutex_);
      generation = ++generation_;
      if (running_) markStale(*running_);
      latest_ = std::make_shared<JobContext::Run>(generation);
      pending_.emplace(std::move(input));
    }
    wake_.notify_all();
    return generation;
  }

  /// Drops the newest input: the running work turns stale (its results are dropped) and a pending
  /// input is never run. busy() is false afterwards; a result published before stays pollable.
  void cancel() {
    std::lock_guard lock(mutex_);
    ++generation_;  // no input has this generation: every run is stale
    if (running_) markStale(*running_);
    pending_.reset();
    latest_.reset();
  }

  /// Asks the newest input's run to stop early (stopRequested()) while what it publishes still
  /// counts: a dialog's Cancel button, whose work reports how far it got.
  void interrupt() {
    std::lock_guard lock(mutex_);
    if (latest_) latest_->stop.store(true, std::memory_order_relaxed);
  }
  /// Whether interrupt() was called for the newest input.
  bool interrupted() const {
    std::lock_guard lock(mutex_);
    return latest_ && latest_->stop.load(std::memory_order_relaxed);
  }

  /// The newest result published since the last poll, once; empty when there is none. Never
  /// waits for the work (one atomic load when nothing is new).
  std::optional<Result> poll() {
    if (!fresh_.load(std::memory_order_acquire)) return std::nullopt;
    std::optional<Result> result;
    std::lock_guard lock(mutex_);
    result.swap(result_);
    fresh_.store(false, std::memory_order_relaxed);
    return result;
  }

  /// The newest input is waiting for the worker or being worked on.
  bool busy() const {
    std::lock_guard lock(mutex_);
    return latest_ && (pending_ || (running_ && running_ == latest_));
  }
  /// The newest input's progress (zero before its run starts or after cancel()).
  JobProgress progress() const {
    std::lock_guard lock(mutex_);
    if (!latest_) return {};
    return {latest_->fraction.load(std::memory_order_relaxed), latest_->done.load(std::memory_order_relaxed),
            latest_->total.load(std::memory_order_relaxed)};
  }
  /// The newest generation handed out (by submit() or cancel()).
  std::uint64_t generation() const {
    std::lock_guard lock(mutex_);
    return generation_;
  }

 private:
  static void markStale(JobContext::Run& run) {
    run.stale.store(true, std::memory_order_relaxed);
    run.stop.store(true, std::memory_order_relaxed);
  }

  bool publish(const JobContext::Run& run, Output value) {
    std::lock_guard lock(mutex_);
    if (run.stale.load(std::memory_order_relaxed)) return false;
    result_.emplace(Result{run.generation, std::move(value)});
    fresh_.store(true, std::memory_order_release);
    return true;
  }

  void loop() {
    for (;;) {
      std::unique_lock lock(mutex_);
      running_.reset();
      wake_.wait(lock, [this] { return quit_ || pending_.has_value(); });
      if (quit_) return;
      // The input moves out of the optional and lives on this stack for the run: the controlling
      // thread only ever replaces pending_, never the input being worked on.
      const Input input = std::move(*pending_);
      pending_.reset();
      running_ = latest_;
      Context context(this, running_);
      lock.unlock();
      work_(input, context);
    }
  }

  const Work work_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  // Guarded by mutex_.
  bool quit_ = false;
  std::uint64_t generation_ = 0;
  std::optional<Input> pending_;
  std::shared_ptr<JobContext::Run> latest_;   // the newest input's run; null after cancel()
  std::shared_ptr<JobContext::Run> running_;  // the run the worker is on; null while idle
  std::optional<Result> result_;
  std::atomic<bool> fresh_{false};  // result_ holds something: lets poll() skip the mutex
  std::thread thread_;              // last: starts after everything it uses exists
};

}  // namespace gridifs
