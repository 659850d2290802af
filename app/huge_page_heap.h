#pragma once
// A command-line render is a short process, and on the virtual machines renders run on most of
// its system time is page faults: zero-filling the fresh 4 KiB pages of its buffers, and of the
// tens of megabytes the image library's static initializers allocate in small blocks when it
// loads (OpenImageIO's string table alone touches about 6,000 pages). glibc serves its heaps
// from transparent huge pages when its `glibc.malloc.hugetlb` tunable asks for it: one fault per
// 2 MiB instead of per 4 KiB, which took a small render from 21,000 faults to 8,300 and from 0.52
// to 0.37 CPU-seconds (docs/RENDERER.md, "Fixed costs"). glibc reads its tunables only when a
// process starts, so the process starts itself again with the tunable set.

namespace gridifs::cli {

/// Re-executes this program (same arguments, same process id) with `glibc.malloc.hugetlb=1`
/// added to GLIBC_TUNABLES, unless that tunable is already set (to any value: a user or a
/// profiler that sets it keeps its choice), the program runs under valgrind (which would not
/// follow the exec), or a sanitizer replaces the allocator. Returns only when it did not
/// re-execute, with the environment as it found it.
void restartWithHugePageHeap(char** argv);

}  // namespace gridifs::cli
