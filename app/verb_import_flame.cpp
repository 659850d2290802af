// gridifs import-flame IN.flame -o OUT.gridifs [--genome N|NAME] [--grids] [--resolution R] [--list]:
// a flame genome (flam3, Apophysis, JWildfire, Fractorium) as a GridIFS project.
#include <cstdio>
#include <fstream>

#include "app/cli.h"
#include "app/render_setup.h"
#include "base/atomic_file.h"
#include "io/flame_import.h"
#include "io/project_io.h"

namespace gridifs::cli {
namespace {

std::vector<FlameGenome> readGenomes(const std::string& file) {
  try {
    return loadFlameFile(file);
  } catch (const FlameError& e) {
    throw CliError(kBadInput, file + ": " + e.what());
  } catch (const IoError& e) {
    throw CliError(kBadInput, "cannot read " + file + ": " + e.what());
  }
}

int listGenomes(const std::string& file) {
  const auto genomes = readGenomes(file);
  std::printf("%s: %zu genome%s\n", file.c_str(), genomes.size(), genomes.size() == 1 ? "" : "s");
  for (std::size_t i = 0; i < genomes.size(); ++i) {
    const FlameGenome& g = genomes[i];
    std::printf("  %-3zu %-32.32s %5dx%-5d %2zu xform%s%s\n", i, g.name.empty() ? "(unnamed)" : g.name.c_str(), g.width,
                g.height, g.xforms.size(), g.xforms.size() == 1 ? " " : "s", g.finalXform ? " + final" : "");
  }
  return kSuccess;
}

int runImportFlame(const std::string& file, const std::string& out, const std::string& genome, int resolution,
                   bool list, bool grids) {
  if (list) return listGenomes(file);
  if (out.empty()) throw CliError(kBadInput, "import-flame needs -o OUT.gridifs (or --list)");
  checkOutputPath(out, {"gridifs"}, "the project");
  if (resolution < 2 || resolution > limits::kMaxResolution)
    throw CliError(kBadInput, "--resolution must be between 2 and " + std::to_string(limits::kMaxResolution) +
                                  ", not " + std::to_string(resolution));
  const auto genomes = readGenomes(file);
  FlameImportOptions options;
  options.resolution = resolution;
  options.sampleOntoGrids = grids;
  const std::filesystem::path outPath(out);
  const std::filesystem::path paletteFile = outPath.parent_path() / (outPath.stem().string() + ".palette.json");
  options.inlinePaletteReference = "file:" + paletteFile.filename().string();
  FlameImport imported;
  try {
    imported = importFlameGenome(selectGenome(genomes, genome), options);
  } catch (const FlameError& e) {
    throw CliError(kBadInput, file + ": " + e.what());
  }
  for (const std::string& w : imported.warnings) std::fprintf(stderr, "warning: %s: %s.\n", file.c_str(), w.c_str());
  if (imported.palette) writeFileAtomically(paletteFile, serializePaletteJson(*imported.palette));
  try {
    saveProject(imported.project, out);
  } catch (const IoError& e) {
    throw CliError(kFailure, e.what());
  } catch (const ModelError& e) {
    throw CliError(kFailure, out + ": " + e.what());
  }
  return kSuccess;
}

const VerbRegistration kImportFlame{
    {"import-flame",
     "IN.flame -o OUT.gridifs [--genome N|NAME] [--grids] [--resolution R] [--list]: a flame genome as a project",
     [](CLI::App& app) {
       auto file = std::make_shared<std::string>();
       auto out = std::make_shared<std::string>();
       auto genome = std::make_shared<std::string>();
       auto resolution = std::make_shared<int>(64);
       auto list = std::make_shared<bool>(false);
       auto grids = std::make_shared<bool>(false);
       app.add_option("IN", *file, "flame file (.flame, .flam3 or .xml)")->required();
       app.add_option("-o,--output", *out, "output project (.gridifs)");
       app.add_option("--genome", *genome, "which genome: its index (0, 1, ...) or its name (default: the first)");
       app.add_flag("--grids", *grids,
                    "sample every xform onto a grid to sculpt (random variations are left out) instead of keeping "
                    "the variations");
       app.add_option("--resolution", *resolution,
                      "grid nodes per axis for sampled non-linear xforms (2..128, default 64)");
       app.add_flag("--list", *list, "list the file's genomes and exit");
       return [=] { return runImportFlame(*file, *out, *genome, *resolution, *list, *grids); };
     }}};

}  // namespace
}  // namespace gridifs::cli
