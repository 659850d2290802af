#include "base/parallel.h"

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

// ThreadSanitizer cannot see oneTBB's hand-offs: the scheduler synchronises inside libtbb.so,
// which is not instrumented, so every loop would read as a race between the caller's writes and
// the workers' reads. Under TSan the loops run on plain std::threads instead (spawned and joined
// per loop), whose start and join TSan does see, so the bodies themselves are still checked.
#if defined(__SANITIZE_THREAD__)
#define GRIDIFS_PARALLEL_PLAIN_THREADS 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define GRIDIFS_PARALLEL_PLAIN_THREADS 1
#endif
#endif

namespace gridifs {

int resolveThreadCount(int requested) {
  return requested > 0 ? requested : int(std::max(1u, std::thread::hardware_concurrency()));
}

void parallelFor(std::size_t count, int threads, std::size_t grain,
                 const std::function<void(std::size_t, std::size_t)>& body) {
  grain = std::max<std::size_t>(grain, 1);
  if (count == 0) return;
  if (threads <= 1 || count <= grain) {
    body(0, count);
    return;
  }
#ifdef GRIDIFS_PARALLEL_PLAIN_THREADS
  // Chunks of `grain` indices handed out in order; the first exception stops the rest.
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex errorMutex;
  auto work = [&] {
    while (!failed.load()) {
      const std::size_t begin = next.fetch_add(grain);
      if (begin >= count) return;
      try {
        body(begin, std::min(count, begin + grain));
      } catch (...) {
        const std::lock_guard<std::mutex> lock(errorMutex);
        if (!error) error = std::current_exception();
        failed = true;
      }
    }
  };
  const std::size_t chunks = (count + grain - 1) / grain;
  std::vector<std::thread> helpers;
  for (std::size_t i = 1; i < std::min<std::size_t>(std::size_t(threads), chunks); ++i) helpers.emplace_back(work);
  work();
  for (std::thread& t : helpers) t.join();
  if (error) std::rethrow_exception(error);
#else
  // An arena caps the concurrency at what the caller asked for; the pool's threads are shared
  // with every other arena, so nested or concurrent loops do not oversubscribe the machine.
  // No more than the machine's cores: oneTBB cannot give an arena more workers than that, and
  // warned on stderr ("The request for 2 workers is ignored") when asked to.
  tbb::task_arena arena(std::max(1, std::min(threads, tbb::info::default_concurrency())));
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, grain),
                      [&](const tbb::blocked_range<std::size_t>& r) { body(r.begin(), r.end()); });
  });
#endif
}

void parallelForEach(std::size_t count, int threads, const std::function<void(std::size_t)>& task,
                     const std::function<void()>& reportOnCaller) {
  const std::thread::id caller = std::this_thread::get_id();
  parallelFor(count, threads, 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      task(i);
      if (std::this_thread::get_id() == caller) reportOnCaller();
    }
  });
}

}  // namespace gridifs
