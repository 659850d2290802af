// libFuzzer target for the project loader: any byte string is either refused with the loader's
// documented error (ModelError with a JSON path) or loads into a project that validates,
// serialises and loads back to the same text. Anything else — a crash, a sanitizer report, an
// exception of another type, a hang or a runaway allocation — is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <string>

#include "io/project_io.h"
#include "render/compiled_ifs.h"

namespace {

/// Compiling evaluates every operation stack; keep it to projects small enough that one input
/// stays well under the fuzzer's time limit (the loader's own limits allow 2^22 nodes).
bool smallEnoughToCompile(const gridifs::Project& project) {
  std::size_t nodes = 0;
  for (const gridifs::Function& f : project.functions)
    nodes += std::size_t(f.resolution[0]) * std::size_t(f.resolution[1]) * std::size_t(f.resolution[2]);
  return nodes <= 20'000;
}

[[noreturn]] void finding(const char* what) {
  std::fprintf(stderr, "finding: %s\n", what);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  gridifs::Project project;
  try {
    project = gridifs::parseProject(text);
  } catch (const gridifs::ModelError&) {
    return 0;  // refused with a JSON path: the documented outcome for bad input
  }
  try {
    gridifs::validateProject(project);
  } catch (const gridifs::ModelError& e) {
    finding(("a loaded project does not validate: " + std::string(e.what())).c_str());
  }
  const std::string saved = gridifs::serializeProject(project);
  gridifs::Project again;
  try {
    again = gridifs::parseProject(saved);
  } catch (const gridifs::ModelError& e) {
    finding(("a saved project does not load back: " + std::string(e.what())).c_str());
  }
  if (gridifs::serializeProject(again) != saved) finding("save -> load -> save changed the file");
  if (smallEnoughToCompile(project)) {
    try {
      (void)gridifs::compileIfs(project);
    } catch (const gridifs::ModelError&) {
      // A stack that evaluates to non-finite nodes is refused with a path; that is fine.
    }
  }
  return 0;
}
