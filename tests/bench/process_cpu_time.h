#pragma once
// The CPU seconds (user + system, every thread) this process has used: what a render costs on a
// busy machine, less sensitive to other load than wall time.
#include <ctime>

namespace gridifs {

inline double processCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

}  // namespace gridifs
