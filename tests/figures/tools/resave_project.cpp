// Writes each project given in GridIFS's own saved form (its key order, every number as the
// writer spells it), so an example project made by a script is byte for byte what the modeller
// would save: the form the shipped-projects test holds every file in assets/ to.
#include <cstdio>
#include <exception>

#include "io/project_io.h"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: gridifs_resave_project FILE.gridifs...\n");
    return 2;
  }
  for (int i = 1; i < argc; ++i) {
    try {
      gridifs::saveProject(gridifs::loadProject(argv[i]), argv[i]);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s: %s\n", argv[i], e.what());
      return 2;
    }
  }
  return 0;
}
