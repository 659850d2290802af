// gridifs export-flame FILE -o OUT.flame: a project as a flame genome for flam3, Apophysis,
// JWildfire and Fractorium (each function as its least-squares affine fit).
#include <cstdio>

#include "app/cli.h"
#include "app/render_setup.h"
#include "base/atomic_file.h"
#include "io/flame_export.h"
#include "io/project_io.h"

namespace gridifs::cli {
namespace {

int runExportFlame(const std::string& file, const std::string& out) {
  checkOutputPath(out, {"flame", "flam3", "xml"}, "the flame file");
  const Project project = loadForVerb(file);
  const std::filesystem::path path(file);
  FlameExport exported;
  try {
    exported = exportFlame(project, path.parent_path(), path.stem().string());
  } catch (const ModelError& e) {
    throw CliError(kBadInput, file + ": " + e.what());
  }
  for (const std::string& w : exported.warnings) std::fprintf(stderr, "warning: %s: %s.\n", file.c_str(), w.c_str());
  writeFileAtomically(out, exported.xml);  // IoError: exit 1 with its sentence
  return kSuccess;
}

const VerbRegistration kExportFlame{
    {"export-flame", "FILE -o OUT.flame: the project as a flame genome (its variations, or affine fits of its grids)",
     [](CLI::App& app) {
       auto file = std::make_shared<std::string>();
       auto out = std::make_shared<std::string>();
       app.add_option("FILE", *file, "project file (.gridifs)")->required();
       addSetOption(app);
       app.add_option("-o,--output", *out, "output flame (.flame)")->required();
       return [=] { return runExportFlame(*file, *out); };
     }}};

}  // namespace
}  // namespace gridifs::cli
