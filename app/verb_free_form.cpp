// gridifs free-form -o OUT.gridifs (--preset NAME | --from GRID.gridifs): a free-form project
// (Thollot, Zair, Tosan & Vandorpe 1997, §5), either a preset (Bézier or B-spline curve or patch
// of a degree, the Sierpinski gasket) or F̂ of a grid project: its functions as matrices on a
// control net, flat or one of the paper's quadratic deformations (freeform/free_form_deformation.h).
#include <cstdio>
#include <optional>

#include "app/cli.h"
#include "app/render_setup.h"
#include "freeform/free_form_deformation.h"
#include "freeform/free_form_presets.h"
#include "io/project_io.h"
#include "model/final_function.h"

namespace gridifs::cli {
namespace {

struct FreeFormArgs {
  std::string preset, from, net = "flat", out;
  std::optional<int> degree;
  double split = 0.5, roughness = 0.0, height = 0.5;
  std::uint64_t seed = 1;
};

Project presetProject(const FreeFormArgs& a) {
  FreeFormPreset preset;
  if (!parseFreeFormPreset(a.preset, preset))
    throw CliError(kBadInput,
                   "--preset must be bezier-curve, bezier-patch, bspline-curve, bspline-patch, "
                   "sierpinski or sierpinski-patch, not \"" +
                       a.preset + "\"");
  if ((preset == FreeFormPreset::BSplineCurve || preset == FreeFormPreset::BSplinePatch) && a.roughness != 0.0)
    throw CliError(kBadInput,
                   "--roughness: the B-spline presets stay smooth (blending their rows would break the "
                   "joint between the halves)");
  FreeFormPresetOptions options;
  options.degree = a.degree.value_or(3);
  options.split = a.split;
  options.roughness = a.roughness;
  options.seed = a.seed;
  Project p = defaultNewProject();
  try {
    applyFreeFormPreset(p, preset, options);
  } catch (const ModelError& e) {
    throw CliError(kBadInput, "--" + e.path() + ": " + e.message());
  }
  removeFinalFunction(p);
  return p;
}

Project mappedProject(const FreeFormArgs& a) {
  ControlNetOptions options;
  if (!parseControlNetShape(a.net, options.shape))
    throw CliError(kBadInput,
                   "--net must be flat, elliptic-paraboloid or hyperbolic-paraboloid, not \"" + a.net + "\"");
  options.degree = a.degree.value_or(2);
  options.height = a.height;
  const Project grid = loadForVerb(a.from);
  try {
    ControlNetResult result = mapOntoControlNet(grid, options);
    for (const std::string& note : result.notes)
      std::fprintf(stderr, "gridifs: note: %s: %s\n", a.from.c_str(), note.c_str());
    return std::move(result.project);
  } catch (const ModelError& e) {
    if (e.path() == "degree" || e.path() == "height") throw CliError(kBadInput, "--" + e.path() + ": " + e.message());
    throw CliError(kBadInput, "cannot map " + a.from + " onto a control net: " + e.what());
  }
}

int runFreeForm(const FreeFormArgs& a) {
  if (a.preset.empty() == a.from.empty())
    throw CliError(kBadInput, "free-form needs exactly one of --preset NAME and --from GRID.gridifs");
  checkOutputPath(a.out, {"gridifs"}, "the free-form project");
  const Project p = a.preset.empty() ? mappedProject(a) : presetProject(a);
  try {
    saveProject(p, a.out);
  } catch (const IoError& e) {
    throw CliError(kFailure, e.what());
  } catch (const ModelError& e) {
    throw CliError(kFailure, a.out + ": " + e.what());
  }
  return kSuccess;
}

const VerbRegistration kFreeForm{
    {"free-form",
     "-o OUT.gridifs (--preset NAME [--degree N --split R --roughness A --seed S] | --from GRID.gridifs "
     "[--net flat|elliptic-paraboloid|hyperbolic-paraboloid --degree N --height H]): a free-form project",
     [](CLI::App& app) {
       auto a = std::make_shared<FreeFormArgs>();
       app.add_option("-o,--output", a->out, "output project (.gridifs)")->required();
       app.add_option("--preset", a->preset,
                      "bezier-curve, bezier-patch, bspline-curve, bspline-patch, sierpinski or sierpinski-patch");
       app.add_option("--from", a->from, "a grid project whose functions are mapped onto a control net (F̂)");
       app.add_option("--degree", a->degree,
                      "degree of the preset (1-7, default 3) or total degree of the net (default 2; at most 7 for a "
                      "planar attractor, 5 for a spatial one)");
       app.add_option("--split", a->split, "r of the Bézier presets' de Casteljau subdivision, in (0, 1)");
       app.add_option("--roughness", a->roughness, "0..1: blends the Bézier and Sierpinski matrices into fractal ones");
       app.add_option("--seed", a->seed, "seed of the roughness");
       app.add_option("--net", a->net,
                      "the control net's shape: flat (the identity), elliptic-paraboloid, "
                      "hyperbolic-paraboloid");
       app.add_option("--height", a->height, "height of the paraboloids, in half-widths of the attractor");
       return [a] { return runFreeForm(*a); };
     }}};

}  // namespace
}  // namespace gridifs::cli
