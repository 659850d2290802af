#include "io/parameter_paths.h"

#include <nlohmann/json.hpp>

#include "anim/track_path.h"
#include "io/project_io.h"
#include "schema/project_parameter.h"

namespace gridifs {
namespace {

using json = nlohmann::json;

/// Collects the numbers under `node`, whose path is `path`.
void collect(const json& node, const std::string& path, const Project& project, std::vector<std::string>& out) {
  if (node.is_number()) {
    // The file's numbers that are no parameter (a drawing's pixel data, a palette's colours)
    // are left out: findParameter is the judge.
    const std::optional<TrackPath> parsed = TrackPath::parse(path);
    if (parsed && findParameter(project, *parsed).lookup == ParameterLookup::Number) out.push_back(path);
    return;
  }
  if (node.is_array()) {
    for (std::size_t i = 0; i < node.size(); ++i) collect(node[i], path + "[" + std::to_string(i) + "]", project, out);
    return;
  }
  if (!node.is_object()) return;
  for (const auto& [key, value] : node.items()) {
    if (path.empty() &&
        (key == "version" || key == "tracks" || key == "lineage" || key == "audio" || key == "bindings"))
      continue;
    // Keys that are not names (a palette's colour table keyed by numbers) cannot be in a path.
    if (key.empty() || key.find_first_of(".[]/~") != std::string::npos) continue;
    collect(value, path.empty() ? key : path + "." + key, project, out);
  }
}

}  // namespace

std::vector<std::string> parameterPaths(const Project& project) {
  std::vector<std::string> paths;
  collect(json::parse(serializeProject(project)), "", project, paths);
  return paths;
}

}  // namespace gridifs
