#include "app/render_setup.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "app/cli.h"
#include "job/prepared_render.h"
#include "model/contractivity.h"
#include "model/free_form.h"
#include "volume/measure_attractor.h"
#include "volume/volume_points.h"

namespace gridifs::cli {

std::int64_t parseSamples(const std::string& text, std::int64_t maximum) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || !end || *end != '\0' || !std::isfinite(value) || value != std::floor(value))
    throw CliError(kBadInput, "--samples must be a whole number such as 20000000 or 2e7, not \"" + text + "\"");
  if (value < 1) throw CliError(kBadInput, "--samples must be at least 1, not " + text);
  if (value > double(maximum))
    throw CliError(kBadInput,
                   "--samples " + text + " is more than the limit of " + std::to_string(maximum) + " samples");
  return std::int64_t(value);
}

void checkOutputPath(const std::filesystem::path& out, const std::vector<std::string>& allowed,
                     const std::string& what) {
  const std::string ext = lowerExtension(out);
  if (std::find(allowed.begin(), allowed.end(), ext) == allowed.end()) {
    std::string list;
    for (std::size_t i = 0; i < allowed.size(); ++i)
      list += (i ? (i + 1 == allowed.size() ? " or ." : ", .") : ".") + allowed[i];
    throw CliError(kBadInput, "cannot write " + out.string() + ": " + what + " must end in " + list);
  }
  std::filesystem::path folder = out.parent_path();
  if (folder.empty()) folder = ".";
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec))
    throw CliError(kBadInput, "cannot write " + out.string() + ": the folder " + folder.string() + " does not exist");
  if (::access(folder.c_str(), W_OK) != 0)
    throw CliError(kBadInput, "cannot write " + out.string() + ": the folder " + folder.string() + " is not writable");
  if (std::filesystem::is_directory(out, ec))
    throw CliError(kBadInput, "cannot write " + out.string() + ": it is a folder");
}

RenderSetup prepareRender(const std::filesystem::path& file, const RenderOverrides& overrides,
                          std::int64_t maxSamples) {
  return prepareRenderOf(loadForVerb(file), file, overrides, maxSamples);
}

RenderSetup prepareRenderOf(const Project& loaded, const std::filesystem::path& file, const RenderOverrides& overrides,
                            std::int64_t maxSamples, bool warn) {
  // The steps of gridifs::prepareRender (job/prepared_render.h), with the command line's own
  // checks and wording between them; the display mode's job is made by the mode's runner
  // (app/verb_render.cpp), which knows --palette and merged parts.
  RenderSetup setup;
  setup.project = projectForVerbAt(loaded, file, overrides.time);
  // Precedence: --samples, then --quality, then the project's quality, then its samples.
  if (overrides.quality) {
    if (overrides.samples) throw CliError(kBadInput, "--samples and --quality exclude each other: give one of them");
    if (!(*overrides.quality >= 1e-3 && *overrides.quality <= 1e6))
      throw CliError(kBadInput, "--quality must be between 0.001 and 1000000 samples per pixel");
    setup.project.render.quality = *overrides.quality;
  }
  RenderJobOptions options;
  options.threads = overrides.threads.value_or(0);
  options.width = overrides.width;
  options.height = overrides.height;
  options.seed = overrides.seed;
  if (overrides.samples) options.samples = parseSamples(*overrides.samples, maxSamples);
  // Condensation sets read from files (meshes, VDB grids) are found beside the project.
  options.folder = file.parent_path();
  RenderJob& job = setup.job;
  job = outputRenderJob(setup.project, options);
  if (overrides.threads && (*overrides.threads < 1 || *overrides.threads > limits::kMaxRenderThreads))
    throw CliError(kBadInput, "--threads must be between 1 and " + std::to_string(limits::kMaxRenderThreads));
  if (job.samples < 1)
    throw CliError(kBadInput, file.string() + ": render.samples must be at least 1 (or pass --samples)");
  if (job.samples > maxSamples)
    throw CliError(kBadInput, file.string() + ": " + std::to_string(job.samples) +
                                  " samples is more than the limit of " + std::to_string(maxSamples));
  try {
    validateRenderJob(job);
  } catch (const ModelError& e) {
    throw CliError(kBadInput, file.string() + ": " + e.message());
  }
  // Median functions (or a page of the book of drawings) draw the points of a density volume;
  // the grids are evaluated once, for the IFS and for the contractivity warnings below.
  Document document(setup.project);
  try {
    setup.ifs = compileChaosIfs(document.project(), document.evaluation(), options, overrides.volume);
  } catch (const RenderJobError& e) {
    throw CliError(kBadInput, file.string() + ": " + e.what());
  }
  if (overrides.volume || usesSetIteration(setup.project)) return setup;
  // The chaos game still draws something for an expanding function (clamping to X keeps the chain
  // bounded), so this is a warning, as in `gridifs info`.
  for (const CompiledFunction& f : setup.ifs->functions) {
    if (!warn) break;
    const Function& source = setup.project.functions[f.sourceIndex];
    if (isSetKind(source.kind)) continue;  // a constant map: contraction factor 0
    const ContractivityEstimate c = source.kind == FunctionKind::Matrix
                                        ? ContractivityEstimate{simplexContraction(source.matrix), Index3{0, 0, 0}}
                                        : estimateContractivity(*document.evaluatedGrid(f.sourceIndex));
    if (c.bound >= 1.0)
      std::fprintf(stderr, "warning: %s: function %zu \"%s\" may not be contractive (Lipschitz bound %.3g).\n",
                   file.c_str(), f.sourceIndex, setup.project.functions[f.sourceIndex].name.c_str(), c.bound);
  }
  return setup;
}

}  // namespace gridifs::cli
