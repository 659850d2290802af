// gridifs mutate FILE -o OUT_%02d.gridifs [--count K] [--seed S] [--strength X]
// [--keep ops,placement,colors,variations,palette,camera,tracks] [--mate OTHER.gridifs]:
// projects near FILE, or children of FILE and OTHER (core/explore/explore.h).
#include <optional>
#include <sstream>

#include "app/cli.h"
#include "app/explore_output.h"

namespace gridifs::cli {
namespace {

constexpr int kMaxCount = 1000;

std::string shortNumber(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

struct MutateArgs {
  std::string file, out, keep;
  std::optional<std::string> mate;
  std::optional<std::uint64_t> seed;
  double strength = 0.5;
  int count = 1;
};

int runMutate(const MutateArgs& a) {
  MutationOptions options;
  if (!(a.strength > 0.0 && a.strength <= 1.0))
    throw CliError(kBadInput, "--strength must be above 0 and at most 1, not " + shortNumber(a.strength));
  std::string unknown;
  if (!a.keep.empty() && !parseExploreKeep(a.keep, options.keep, unknown))
    throw CliError(kBadInput, std::string("--keep takes ") + exploreKeepList() + ", not \"" + unknown + "\"");
  checkExploreOutput(a.out, a.count, kMaxCount);
  const Project parent = loadForVerb(a.file);
  std::optional<Project> mate;
  std::vector<std::string> parents{a.file};
  if (a.mate) {
    mate = loadForVerb(*a.mate);
    options.mate = &*mate;
    parents.push_back(*a.mate);
  }
  options.strength = a.strength;
  options.folder = std::filesystem::path(a.file).parent_path();
  const std::uint64_t seed = a.seed.value_or(clockSeed());
  for (int i = 0; i < a.count; ++i) {
    options.seed = seed + std::uint64_t(i);
    ExploreResult result;
    try {
      result = mutateProject(parent, options, parents);
    } catch (const ModelError& e) {
      throw CliError(e.message().rfind("cannot breed", 0) == 0 ? kBadInput : kFailure,
                     (a.mate ? a.file + " and " + *a.mate : a.file) + ": " + e.message());
    }
    writeExploreResult(result, exploreOutputFile(a.out, a.count, i), a.mate ? "child" : "mutation");
  }
  return kSuccess;
}

const VerbRegistration kMutate{
    {"mutate",
     "FILE -o OUT_%02d.gridifs [--count K --seed S --strength X --keep LIST --mate OTHER.gridifs]: projects "
     "near FILE, or its children with OTHER",
     [](CLI::App& app) {
       auto a = std::make_shared<MutateArgs>();
       app.add_option("FILE", a->file, "the parent project (.gridifs)")->required();
       app.add_option("-o,--output", a->out,
                      "output project (.gridifs); with --count, a pattern with one %d field, e.g. child_%02d.gridifs")
           ->required();
       app.add_option("--count", a->count, "how many projects to write (default 1)");
       app.add_option("--seed", a->seed,
                      "seed of the draw: the same seed and options give the same bytes (default: from the clock, "
                      "printed); with --count, child i has seed S+i");
       app.add_option("--strength", a->strength,
                      "how far a child may move from its parent, above 0 and at most 1 (default 0.5)");
       app.add_option("--keep", a->keep,
                      "what stays byte-equal: a comma-separated list of ops, placement, colors, variations, "
                      "palette, camera, tracks");
       app.add_option("--mate", a->mate, "a second parent: the children draw their functions from both");
       return [a] { return runMutate(*a); };
     },
     /*hugePageHeap=*/true}};

}  // namespace
}  // namespace gridifs::cli
