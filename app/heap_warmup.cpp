#include "app/heap_warmup.h"

#include <cstdlib>
#include <cstring>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace gridifs::cli {
namespace {

// glibc refuses an mmap threshold above 32 MB on 64-bit systems; blocks of 16 MB stay below it.
constexpr std::size_t kBlock = std::size_t(16) << 20;
constexpr std::size_t kMaxWarm = std::size_t(1) << 30;
bool gKeeping = false;

}  // namespace

void keepFreedMemory() {
#if defined(__GLIBC__)
  gKeeping = mallopt(M_MMAP_THRESHOLD, int(2 * kBlock)) == 1 && mallopt(M_TRIM_THRESHOLD, int(kMaxWarm)) == 1;
#endif
}

void warmHeap(std::size_t bytes) {
  if (!gKeeping) return;  // without the settings above the memory would go back to the system at once
  bytes = bytes < kMaxWarm ? bytes : kMaxWarm;
  std::vector<void*> blocks;
  for (std::size_t done = 0; done < bytes; done += kBlock) {
    void* p = std::malloc(kBlock);
    if (!p) break;
    // Not zeros: GCC turns malloc + memset(0) into calloc, which leaves fresh pages untouched, and
    // it would drop stores to memory that is freed unread.
    std::memset(p, 0x5A, kBlock);
    asm volatile("" : : "r"(p) : "memory");
    blocks.push_back(p);
  }
  for (void* p : blocks) std::free(p);
}

std::size_t renderOutputBytes(int width, int height, bool colourSums) {
  const std::size_t pixels = std::size_t(width > 0 ? width : 0) * std::size_t(height > 0 ? height : 0);
  // Accumulation: 8-byte keys and 4-byte hit counts (+ 4 × 8-byte colour sums); image: RGBA8,
  // float depth, hit counts (+ 4 float colour sums); the file's RGB8 pixels.
  return pixels * (12 + 12 + 3 + (colourSums ? 32 + 16 : 0));
}

}  // namespace gridifs::cli
