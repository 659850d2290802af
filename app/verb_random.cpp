// gridifs random -o OUT.gridifs [--seed S] [--style grid|flame|free-form|volume] [--functions N]
// [--count K]: new projects whose attractors are worth looking at (core/explore/explore.h).
#include <optional>

#include "app/cli.h"
#include "app/explore_output.h"

namespace gridifs::cli {
namespace {

constexpr int kMaxCount = 1000;

struct RandomArgs {
  std::string out, style = "grid";
  std::optional<std::uint64_t> seed;
  int functions = 0, count = 1;
};

int runRandom(const RandomArgs& a) {
  RandomWorldOptions options;
  if (!parseExploreStyle(a.style, options.style))
    throw CliError(kBadInput, std::string("--style must be ") + exploreStyleList() + ", not \"" + a.style + "\"");
  if (a.functions != 0 && (a.functions < kMinExploreFunctions || a.functions > kMaxExploreFunctions))
    throw CliError(kBadInput, "--functions must be between " + std::to_string(kMinExploreFunctions) + " and " +
                                  std::to_string(kMaxExploreFunctions) + ", not " + std::to_string(a.functions));
  checkExploreOutput(a.out, a.count, kMaxCount);
  options.functions = a.functions;
  const std::uint64_t seed = a.seed.value_or(clockSeed());
  for (int i = 0; i < a.count; ++i) {
    options.seed = seed + std::uint64_t(i);
    ExploreResult result;
    try {
      result = randomWorld(options);
    } catch (const ModelError& e) {
      throw CliError(kFailure, e.message());
    }
    writeExploreResult(result, exploreOutputFile(a.out, a.count, i),
                       std::string(exploreStyleName(options.style)) + " world");
  }
  return kSuccess;
}

const VerbRegistration kRandom{
    {"random",
     "-o OUT.gridifs [--seed S --style grid|flame|free-form|volume --functions N --count K]: new projects "
     "worth looking at",
     [](CLI::App& app) {
       auto a = std::make_shared<RandomArgs>();
       app.add_option("-o,--output", a->out,
                      "output project (.gridifs); with --count, a pattern with one %d field, e.g. world_%02d.gridifs")
           ->required();
       app.add_option("--seed", a->seed,
                      "seed of the draw: the same seed and options give the same bytes (default: from the clock, "
                      "printed); with --count, project i has seed S+i");
       app.add_option("--style", a->style,
                      "grid (distorted grids), flame (affine grids with flam3's variations), free-form or "
                      "volume (sets and fields); default grid");
       app.add_option("--functions", a->functions, "number of functions (default: 3 to 5, drawn)");
       app.add_option("--count", a->count, "how many projects to write (default 1)");
       return [a] { return runRandom(*a); };
     },
     /*hugePageHeap=*/true}};

}  // namespace
}  // namespace gridifs::cli
