#pragma once
// Parallel loops over an index range, on oneTBB's work-stealing pool. The tone map, the density
// estimator and the deterministic algorithm use these; the chaos game keeps its own persistent
// workers (their generation handshake and lowered priority are part of how the preview behaves).
//
// Thread-safety: the functions block until every index is done. `body` runs concurrently on up
// to `threads` threads and must be safe for that; the first exception a body throws is rethrown
// here and the remaining indices are skipped.
#include <cstddef>
#include <functional>

namespace gridifs {

/// The number of threads to use when a caller asks for `requested` (≤ 0: every hardware thread).
int resolveThreadCount(int requested);

/// Calls body(begin, end) on disjoint chunks covering [0, count), on at most `threads` threads
/// (the caller is one of them). Chunks hold at least `grain` indices; with one thread, or when
/// `count` ≤ `grain`, body(0, count) runs on the caller.
void parallelFor(std::size_t count, int threads, std::size_t grain,
                 const std::function<void(std::size_t begin, std::size_t end)>& body);

/// Calls task(i) for every i in [0, count) on at most `threads` threads, one index at a time,
/// and `reportOnCaller()` after each index that the calling thread ran itself: progress
/// callbacks documented to run on the calling thread stay there.
void parallelForEach(std::size_t count, int threads, const std::function<void(std::size_t index)>& task,
                     const std::function<void()>& reportOnCaller);

}  // namespace gridifs
