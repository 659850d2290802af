#include "app/huge_page_heap.h"

#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <string>

namespace gridifs::cli {

void restartWithHugePageHeap(char** argv) {
#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
  constexpr const char* kTunable = "glibc.malloc.hugetlb";
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (tunables && std::strstr(tunables, kTunable)) return;
  // valgrind preloads its core into the program; an exec would leave its instrumentation behind.
  if (const char* preload = std::getenv("LD_PRELOAD"); preload && std::strstr(preload, "vgpreload")) return;
  const std::string before = tunables ? tunables : "";
  // First in the list: glibc cuts the variable after the first tunable it parses where the
  // process started, so a later check that only saw the user's first tunable would exec again.
  const std::string with = std::string(kTunable) + "=1" + (before.empty() ? std::string() : ":" + before);
  if (setenv("GLIBC_TUNABLES", with.c_str(), 1) != 0) return;
  // By its own path rather than /proc/self/exe, which would name the process "exe" in ps and top.
  char self[4096];
  const ssize_t length = readlink("/proc/self/exe", self, sizeof self - 1);
  if (length > 0) {
    self[length] = '\0';
    execv(self, argv);
  }
  // No /proc, or the exec failed: run on as we are.
  if (tunables)
    setenv("GLIBC_TUNABLES", before.c_str(), 1);
  else
    unsetenv("GLIBC_TUNABLES");
#else
  (void)argv;
#endif
}

}  // namespace gridifs::cli
