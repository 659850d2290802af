// libFuzzer target for the .flame importer: any byte string is either refused with FlameError
// (one sentence) or every genome in it imports into a project that validates and survives a
// save/load round trip. Anything else — a crash, a sanitizer report, another exception type, a
// hang or a runaway allocation — is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "io/flame_genome.h"
#include "io/flame_import.h"
#include "io/project_io.h"
#include "schema/validation.h"

namespace {

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "finding: %s\n", what.c_str());
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<gridifs::FlameGenome> genomes;
  try {
    genomes = gridifs::parseFlameFile(text);
  } catch (const gridifs::FlameError&) {
    return 0;  // refused with a sentence: the documented outcome for a bad file
  }
  gridifs::FlameImportOptions options;
  options.resolution = 6;  // small grids: the sampling code is the same, each input stays fast
  options.inlinePaletteReference = "file:fuzz.palette.json";
  for (std::size_t g = 0; g < genomes.size() && g < 2; ++g) {
    gridifs::FlameImport imported;
    try {
      imported = gridifs::importFlameGenome(genomes[g], options);
    } catch (const gridifs::FlameError&) {
      continue;
    }
    try {
      gridifs::validateProject(imported.project);
    } catch (const gridifs::ModelError& e) {
      finding("an imported genome does not validate: " + std::string(e.what()));
    }
    const std::string saved = gridifs::serializeProject(imported.project);
    try {
      if (gridifs::serializeProject(gridifs::parseProject(saved)) != saved) finding("save -> load -> save changed it");
    } catch (const gridifs::ModelError& e) {
      finding("an imported project does not load back: " + std::string(e.what()));
    }
  }
  return 0;
}
