// gridifs nodes / eval: the distorted nodes of a function, and f_I(p) for points on stdin.
#include <cstdio>
#include <iostream>
#include <sstream>

#include "app/cli.h"
#include "render/compiled_ifs.h"

namespace gridifs::cli {
namespace {

int runNodes(const std::string& file, const std::string& which, std::optional<double> time) {
  Document document(loadForVerbAt(file, time));
  const std::size_t index = resolveFunction(document.project(), which, file);
  const auto grid = evaluateForVerb(document, index, file);
  const Index3& n = grid->resolution();
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        const Vec3& p = grid->node(i, j, k);
        std::printf("%d %d %d %.9g %.9g %.9g\n", i, j, k, p.x, p.y, p.z);
      }
  return kSuccess;
}

int runEval(const std::string& file, const std::string& which, std::optional<double> time) {
  Document document(loadForVerbAt(file, time));
  const std::size_t index = resolveFunction(document.project(), which, file);
  const auto grid = evaluateForVerb(document, index, file);
  // A function with flame variations is its grid map extrapolated, then the variation stage, as
  // the chaos game runs it (in float); random variations draw from a fixed stream.
  const Function& function = document.project().functions[index];
  std::optional<CompiledFunction> compiled;
  if (function.hasVariationStage()) compiled = compileFunction(function, *grid, index);
  std::uint64_t random = 1;
  std::string line;
  std::size_t lineNumber = 0;
  std::string output;
  while (std::getline(std::cin, line)) {
    ++lineNumber;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::istringstream in(line);
    Vec3 p;
    std::string extra;
    if (!(in >> p.x >> p.y >> p.z) || (in >> extra))
      throw CliError(kBadInput, "stdin line " + std::to_string(lineNumber) + " is not three numbers \"x y z\"");
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw CliError(kBadInput, "stdin line " + std::to_string(lineNumber) + " has a non-finite coordinate");
    Vec3 q;
    if (compiled) {
      const auto r = compiled->evaluateMap({float(p.x), float(p.y), float(p.z)}, random);
      q = Vec3(r[0], r[1], r[2]);
    } else {
      q = grid->evaluate(p);
    }
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "%.9g %.9g %.9g\n", q.x, q.y, q.z);
    output += buffer;
    if (output.size() > (1 << 16)) {
      std::fputs(output.c_str(), stdout);
      output.clear();
    }
  }
  std::fputs(output.c_str(), stdout);
  return kSuccess;
}

std::function<int()> setupFunctionVerb(CLI::App& app,
                                       int (*action)(const std::string&, const std::string&, std::optional<double>)) {
  auto file = std::make_shared<std::string>();
  auto which = std::make_shared<std::string>();
  auto time = std::make_shared<std::optional<double>>();
  app.add_option("FILE", *file, "project file (.gridifs)")->required();
  app.add_option("--function", *which, "function index 0..n-1 (as in functions[I]) or name")->required();
  addTimeOption(app, *time);
  addSetOption(app);
  return [=] { return action(*file, *which, *time); };
}

const VerbRegistration kNodes{{"nodes", "FILE --function I [--time T]: print every distorted node as \"i j k x y z\"",
                               [](CLI::App& app) { return setupFunctionVerb(app, runNodes); }}};
const VerbRegistration kEval{{"eval", "FILE --function I [--time T]: read \"x y z\" lines, print f_I(p)",
                              [](CLI::App& app) { return setupFunctionVerb(app, runEval); }}};

}  // namespace
}  // namespace gridifs::cli
