// gridifs: parse the command line, then run one verb or open the modeller.
#include <unistd.h>

#include <cstdio>
#include <iostream>

#include "app/cli.h"
#include "app/huge_page_heap.h"

int main(int argc, char** argv) {
  // A render is a short process whose system time is mostly page faults (app/huge_page_heap.h).
  if (argc >= 2 && gridifs::cli::verbWantsHugePageHeap(argv[1])) gridifs::cli::restartWithHugePageHeap(argv);
  const int code = gridifs::cli::run(argc, argv, gridifs::cli::openModeller);
#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
  if (argc >= 2 && gridifs::cli::isVerb(argv[1])) {
    // A verb has written and closed its outputs by now. Leave without the destructors of every
    // loaded library's statics (the image library's DICOM dictionary alone takes 2 ms) and without
    // freeing the render buffers block by block: the system takes the memory back at once.
    // Sanitizer builds return normally, for their checks at exit.
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    _exit(code);
  }
#endif
  return code;
}
