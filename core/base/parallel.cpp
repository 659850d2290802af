#include "base/parallel.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <thread>

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
  // An arena caps the concurrency at what the caller asked for; the pool's threads are shared
  // with every other arena, so nested or concurrent loops do not oversubscribe the machine.
  tbb::task_arena arena(threads);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, grain),
                      [&](const tbb::blocked_range<std::size_t>& r) { body(r.begin(), r.end()); });
  });
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
