#include "app/render_setup.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "app/cli.h"
#include "freeform/free_form.h"
#include "job/prepared_render.h"
#include "model/contractivity.h"
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

RenderJobOptions renderJobOptions(const std::filesystem::path& file, const RenderOverrides& overrides,
                                  std::int64_t maxSamples, std::optional<double> time) {
  if (overrides.threads && (*overrides.threads < 1 || *overrides.threads > limits::kMaxRenderThreads))
    throw CliError(kBadInput, "--threads must be between 1 and " + std::to_string(limits::kMaxRenderThreads));
  RenderJobOptions options;
  options.time = time;
  options.threads = overrides.threads.value_or(0);
  options.width = overrides.width;
  options.height = overrides.height;
  options.seed = overrides.seed;
  // Precedence: --samples, then --quality, then the project's quality, then its samples.
  if (overrides.samples) options.samples = parseSamples(*overrides.samples, maxSamples);
  if (overrides.quality) {
    if (overrides.samples) throw CliError(kBadInput, "--samples and --quality exclude each other: give one of them");
    if (!(*overrides.quality >= 1e-3 && *overrides.quality <= 1e6))
      throw CliError(kBadInput, "--quality must be between 0.001 and 1000000 samples per pixel");
    const double quality = *overrides.quality;
    options.adjust = [quality](Project& p) { p.render.quality = quality; };
  }
  // Condensation sets read from files (meshes, VDB grids) are found beside the project.
  options.folder = file.parent_path();
  options.volume = overrides.volume;
  options.device = overrides.device.value_or("auto");
  return options;
}

PreparedRender prepareForVerb(const Project& loaded, const std::filesystem::path& file, const RenderJobOptions& options,
                              std::int64_t maxSamples, bool warn, bool points) {
  // The grids are evaluated once, for the IFS and for the contractivity warnings below.
  EvaluationCache evaluation;
  RenderJobOptions asked = options;
  if (!asked.evaluation) asked.evaluation = &evaluation;
  PreparedRender prepared;
  try {
    prepared = points ? preparePoints(loaded, asked) : prepareRender(loaded, asked);
  } catch (const RenderJobError& e) {
    throw CliError(kBadInput, file.string() + ": " + e.what());
  }
  if (prepared.output.samples > maxSamples)
    throw CliError(kBadInput, file.string() + ": " + std::to_string(prepared.output.samples) +
                                  " samples is more than the limit of " + std::to_string(maxSamples));
  if (warn) warnIfNotContractive(prepared, *asked.evaluation, file);
  return prepared;
}

void warnIfNotContractive(const PreparedRender& prepared, const EvaluationCache& evaluation,
                          const std::filesystem::path& file) {
  if (!prepared.ifs || usesSetIteration(prepared.project)) return;
  // The chaos game still draws something for an expanding function (clamping to X keeps the chain
  // bounded), so this is a warning, as in `gridifs info`.
  for (const CompiledFunction& f : prepared.ifs->functions) {
    if (f.sourceIndex >= prepared.project.functions.size()) continue;  // a volume's points
    const Function& source = prepared.project.functions[f.sourceIndex];
    if (isSetKind(source.kind)) continue;  // a constant map: contraction factor 0
    const ContractivityEstimate c = source.kind == FunctionKind::Matrix
                                        ? ContractivityEstimate{simplexContraction(source.matrix), Index3{0, 0, 0}}
                                        : estimateContractivity(*evaluation.function(prepared.project, f.sourceIndex));
    if (c.bound >= 1.0)
      std::fprintf(stderr, "warning: %s: function %zu \"%s\" may not be contractive (Lipschitz bound %.3g).\n",
                   file.c_str(), f.sourceIndex, source.name.c_str(), c.bound);
  }
}

PreparedRender preparePointsOf(const std::filesystem::path& file, const RenderOverrides& overrides,
                               std::int64_t maxSamples) {
  const Project loaded = loadForVerb(file);
  return prepareForVerb(loaded, file,
                        renderJobOptions(file, overrides, maxSamples, overrides.time.value_or(loaded.time)), maxSamples,
                        true, true);
}

}  // namespace gridifs::cli
