#pragma once
// A render on the command line allocates its output buffers once the chaos game is done: the
// accumulation, the developed image and the file's pixels, 30 to 80 bytes a pixel. The first touch
// of each new page is a page fault that the kernel fills with zeros, about 20 ms of the 60 ms a
// 1024² render spends after its chaos game. While the chaos game runs, the main thread only
// waits, so it touches that much memory ahead of time and frees it again; kept in the process, the
// later allocations reuse pages that are already there.
#include <cstddef>

namespace gridifs::cli {

/// Keeps memory the process frees for its own later allocations instead of handing it back to
/// the system (glibc: blocks up to 32 MB come from the heap, and the heap is not trimmed). For the
/// command line's one-shot renders only.
void keepFreedMemory();

/// Touches `bytes` of heap memory (in blocks the heap serves) and frees it again. Call after
/// keepFreedMemory(), on the thread that will allocate the buffers.
void warmHeap(std::size_t bytes);

/// The bytes a render of width × height pixels allocates after its chaos game (with the flame
/// display's colour sums or without).
std::size_t renderOutputBytes(int width, int height, bool colourSums);

}  // namespace gridifs::cli
