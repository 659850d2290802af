#include "python/python_explore.h"

#include "app/cli.h"
#include "base/errors.h"
#include "explore/explore.h"

namespace gridifs::python {

std::unique_ptr<PythonProject> randomProject(const std::string& style, std::optional<std::uint64_t> seed,
                                             int functions) {
  RandomWorldOptions options;
  if (!parseExploreStyle(style, options.style))
    throw PythonError(std::string("random(): style must be ") + exploreStyleList() + ", not \"" + style + "\".");
  if (functions != 0 && (functions < kMinExploreFunctions || functions > kMaxExploreFunctions))
    throw PythonError("random(): functions must be between " + std::to_string(kMinExploreFunctions) + " and " +
                      std::to_string(kMaxExploreFunctions) + ", not " + std::to_string(functions) + ".");
  options.functions = functions;
  options.seed = seed.value_or(clockSeed());
  ExploreResult result;
  {
    py::gil_scoped_release release;
    try {
      result = randomWorld(options);
    } catch (const ModelError& e) {
      throw PythonError(cli::oneSentence(e.message()));
    }
  }
  return std::make_unique<PythonProject>(std::move(result.project), std::filesystem::path(), "<random>");
}

std::unique_ptr<PythonProject> mutatedProject(const PythonProject& parent, std::optional<std::uint64_t> seed,
                                              double strength, const std::vector<std::string>& keep,
                                              const PythonProject* mate) {
  MutationOptions options;
  if (!(strength > 0.0 && strength <= 1.0)) throw PythonError("mutate(): strength must be above 0 and at most 1.");
  std::string list;
  for (const std::string& k : keep) list += (list.empty() ? "" : ",") + k;
  std::string unknown;
  if (!list.empty() && !parseExploreKeep(list, options.keep, unknown))
    throw PythonError(std::string("mutate(): keep takes ") + exploreKeepList() + ", not \"" + unknown + "\".");
  options.strength = strength;
  options.seed = seed.value_or(clockSeed());
  options.folder = parent.folder();
  const Project project = parent.snapshot();
  std::optional<Project> other;
  std::vector<std::string> parents{parent.source()};
  if (mate) {
    other = mate->snapshot();
    options.mate = &*other;
    parents.push_back(mate->source());
  }
  ExploreResult result;
  {
    py::gil_scoped_release release;
    try {
      result = mutateProject(project, options, parents);
    } catch (const ModelError& e) {
      throw PythonError(cli::oneSentence(e.message()));
    }
  }
  return std::make_unique<PythonProject>(std::move(result.project), parent.folder(), "<mutation>");
}

}  // namespace gridifs::python
