#include "app/explore_output.h"

#include <cstdio>

#include "app/cli.h"
#include "app/render_sequence.h"
#include "app/render_setup.h"
#include "base/errors.h"
#include "base/text_format.h"
#include "io/project_io.h"

namespace gridifs::cli {

void checkExploreOutput(const std::string& pattern, int count, int maxCount) {
  if (count < 1 || count > maxCount)
    throw CliError(kBadInput,
                   "--count must be between 1 and " + std::to_string(maxCount) + ", not " + std::to_string(count));
  if (count > 1) {
    checkFramePattern(pattern);
    checkOutputPath(frameFileName(pattern, 0), {"gridifs"}, "the project");
  } else {
    checkOutputPath(pattern, {"gridifs"}, "the project");
  }
}

std::string exploreOutputFile(const std::string& pattern, int count, int index) {
  if (count == 1 && pattern.find('%') == std::string::npos) return pattern;
  return frameFileName(pattern, index);
}

void writeExploreResult(const ExploreResult& result, const std::string& file, const std::string& what) {
  try {
    saveProject(result.project, file);
  } catch (const IoError& e) {
    throw CliError(kFailure, e.what());
  } catch (const ModelError& e) {
    throw CliError(kFailure, file + ": " + e.what());
  }
  const std::size_t n = result.project.functions.size();
  std::printf("%s: %s, seed %llu, %zu function%s (covers %.0f%% of the frame; drawn %d time%s)\n", file.c_str(),
              what.c_str(), static_cast<unsigned long long>(result.project.lineage ? result.project.lineage->seed : 0),
              n, n == 1 ? "" : "s", 100.0 * result.verdict.covered, result.tries, result.tries == 1 ? "" : "s");
}

}  // namespace gridifs::cli
