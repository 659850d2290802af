// gridifs info FILE [--json]: functions, weights and a contractivity bound per function.
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "anim/track_path.h"
#include "app/cli.h"
#include "app/render_device_option.h"
#include "freeform/free_form.h"
#include "freeform/state_expansion.h"
#include "freeform/transition_matrix.h"
#include "io/parameter_paths.h"
#include "model/contractivity.h"
#include "schema/project_parameter.h"

namespace gridifs::cli {
namespace {

/// The strongly connected components of a project's useful states (reachable from Q_I and reaching
/// Q_F), in the file's state numbers; `cyclic` says whether a component reads words of every length
/// (a part of the attractor) or is passed through once.
struct StateComponent {
  std::vector<std::size_t> states;
  bool cyclic = false;
};

std::vector<StateComponent> stateComponentsOf(const Project& p) {
  std::vector<StateComponent> out;
  if (!p.states) return out;
  std::vector<std::size_t> kept;
  const IfsMatrix useful = trimmed(toIfsMatrix(*p.states), &kept);
  for (const auto& component : stateComponents(useful)) {
    StateComponent c;
    for (std::size_t s : component) c.states.push_back(kept[s]);
    c.cyclic = component.size() > 1 || !useful.entries[component[0]][component[0]].empty();
    out.push_back(std::move(c));
  }
  return out;
}

std::string stateList(const std::vector<std::size_t>& states) {
  std::string list = "{";
  for (std::size_t k = 0; k < states.size(); ++k) list += (k ? " " : "") + std::to_string(states[k]);
  return list + "}";
}

template <class T>
std::vector<std::size_t> widen(const std::vector<T>& v) {
  return std::vector<std::size_t>(v.begin(), v.end());
}

struct FunctionReport {
  const Function* function;
  double probability;
  ContractivityEstimate contractivity;
};

std::vector<FunctionReport> analyse(const Document& document, const std::filesystem::path& file) {
  const Project& p = document.project();
  double total = 0.0;
  for (const Function& f : p.functions)
    if (!f.muted) total += f.weight;
  std::vector<FunctionReport> reports;
  for (std::size_t i = 0; i < p.functions.size(); ++i) {
    const Function& f = p.functions[i];
    const double probability = f.muted || total <= 0 ? 0.0 : f.weight / total;
    if (f.kind == FunctionKind::Matrix) {
      reports.push_back({&f, probability, {simplexContraction(f.matrix), Index3{-1, -1, -1}}});
      continue;
    }
    if (isSetKind(f.kind)) {
      // Barnsley's condensation map has contractivity factor 0 (Sokolov & Gentil, §3.1); the median
      // moves every point of either set half way to the other, so d_H(M(B, C), C) ≤ d_H(B, C) / 2
      // (§3.2; the rotated median of §4.1 has no such bound).
      const double bound = f.kind == FunctionKind::Condensation ? 0.0 : (f.rotate == 0.0 ? 0.5 : 1.0);
      reports.push_back({&f, probability, {bound, Index3{-1, -1, -1}}});
      continue;
    }
    const auto grid = evaluateForVerb(document, i, file);
    reports.push_back({&f, probability, estimateContractivity(*grid)});
  }
  return reports;
}

/// Every number of the project by its parameter path (the paths of --set, keyframe tracks and
/// scripts), with its value and the range a slider moves it over.
int runParameters(const std::string& file, bool asJson) {
  const Project project = loadForVerb(file);
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const std::string& path : parameterPaths(project)) {
    const ProjectParameter parameter = findParameter(project, *TrackPath::parse(path)).parameter;
    const ParameterSpan span = parameter.span();
    if (asJson) {
      nlohmann::ordered_json entry{{"path", path}, {"value", parameter.get(project)}};
      if (span.lo < span.hi) entry["range"] = {span.lo, span.hi};
      list.push_back(entry);
    } else if (span.lo < span.hi) {
      std::printf("%s = %.15g  (%g to %g)\n", path.c_str(), parameter.get(project), span.lo, span.hi);
    } else {
      std::printf("%s = %.15g\n", path.c_str(), parameter.get(project));
    }
  }
  if (asJson) std::printf("%s\n", list.dump(2).c_str());
  return kSuccess;
}

int runInfo(const std::string& file, bool asJson, const std::optional<std::string>& deviceOption) {
  const std::string device = checkedDevice(deviceOption);
  Document document(loadForVerb(file));
  bool gpu = false;
  const std::string deviceLine = deviceReport(device, gpu);
  const auto reports = analyse(document, file);
  const Project& p = document.project();
  bool allContractive = true;
  for (const auto& r : reports) allContractive &= r.function->muted || r.contractivity.bound < 1.0;
  const auto components = transitionComponents(p);
  const auto stateComps = stateComponentsOf(p);
  if (asJson) {
    nlohmann::ordered_json out;
    out["file"] = file;
    out["function_count"] = reports.size();
    out["has_final"] = p.final_function.has_value();
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < reports.size(); ++i) {
      const auto& r = reports[i];
      list.push_back({{"index", i},
                      {"name", r.function->name},
                      {"weight", r.function->weight},
                      {"probability", r.probability},
                      {"muted", r.function->muted},
                      {"resolution", r.function->resolution},
                      {"ops", r.function->ops.size()},
                      {"contractivity", r.contractivity.bound},
                      {"contractive", r.contractivity.bound < 1.0}});
      if (r.function->sampling_error) list.back()["sampling_error"] = *r.function->sampling_error;
      if (r.function->kind != FunctionKind::Grid) {
        list.back()["kind"] = functionKindName(r.function->kind);
        list.back().erase("resolution");
        list.back().erase("ops");
      }
    }
    out["functions"] = list;
    out["transitions"] = !p.transitions.empty();
    if (p.space) out["control_points"] = p.space->control_points.size();
    out["strongly_connected"] = components.size() <= 1 && stateComps.size() <= 1;
    if (p.states) {
      nlohmann::ordered_json comps = nlohmann::ordered_json::array();
      for (const auto& c : stateComps) comps.push_back({{"states", c.states}, {"cyclic", c.cyclic}});
      out["states"] = {{"count", p.states->matrix.size()},
                       {"initial", p.states->initial},
                       {"final", p.states->final},
                       {"components", comps}};
    }
    out["contractive"] = allContractive;
    out["render_device"] = gpu ? "gpu" : "cpu";
    out["render_device_detail"] = deviceLine;
    std::cout << out.dump(2) << "\n";
  } else {
    std::printf("%s: %zu function%s%s\n", file.c_str(), reports.size(), reports.size() == 1 ? "" : "s",
                p.final_function ? " and a final function" : "");
    std::printf("  %-3s %-16s %8s %7s %-11s %4s  %s\n", "#", "name", "weight", "prob", "resolution", "ops",
                "contractivity (Lipschitz bound)");
    for (std::size_t i = 0; i < reports.size(); ++i) {
      const auto& r = reports[i];
      char res[32];
      if (r.function->kind == FunctionKind::Matrix)
        std::snprintf(res, sizeof res, "matrix %zu", r.function->matrix.size());
      else if (isSetKind(r.function->kind))
        std::snprintf(res, sizeof res, "%s", r.function->kind == FunctionKind::Median ? "median" : "condensation");
      else
        std::snprintf(res, sizeof res, "%dx%dx%d", r.function->resolution[0], r.function->resolution[1],
                      r.function->resolution[2]);
      std::printf("  %-3zu %-16.16s %8.4g %7.4f %-11s %4zu  %.4f%s%s\n", i, r.function->name.c_str(),
                  r.function->weight, r.probability, res, r.function->ops.size(), r.contractivity.bound,
                  r.contractivity.bound < 1.0 ? "" : "  (not contractive)", r.function->muted ? "  muted" : "");
      if (r.function->sampling_error)
        std::printf("      sampled from a closed-form map: largest grid error %.3g\n", *r.function->sampling_error);
    }
    std::printf("  render device (--device %s): %s\n", device.c_str(), deviceLine.c_str());
    if (p.space)
      std::printf("  free-form space: %zu control points (contractivity of a matrix: its contraction of the simplex)\n",
                  p.space->control_points.size());
    if (!p.transitions.empty())
      std::printf("  transition matrix: %zu x %zu\n", p.transitions.size(), p.transitions.size());
    if (p.states) {
      std::printf("  states: %zu, initial %s, final %s\n", p.states->matrix.size(),
                  stateList(widen(p.states->initial)).c_str(), stateList(widen(p.states->final)).c_str());
      for (const auto& c : stateComps)
        std::printf("  strongly connected component %s: %s\n", stateList(c.states).c_str(),
                    c.cyclic ? "a cycle (part of the attractor)" : "passed through once (no cycle)");
    }
  }
  if (components.size() > 1) {
    std::string list;
    for (const auto& component : components) {
      list += list.empty() ? "{" : ", {";
      for (std::size_t k = 0; k < component.size(); ++k) list += (k ? " " : "") + std::to_string(component[k]);
      list += "}";
    }
    std::fprintf(stderr,
                 "warning: the transition graph is not strongly connected (components %s): parts of the "
                 "attractor are only reached transiently.\n",
                 list.c_str());
  }
  std::size_t cyclic = 0;
  for (const auto& c : stateComps) cyclic += c.cyclic;
  if (cyclic > 1)
    std::fprintf(stderr,
                 "warning: the state graph has %zu strongly connected parts with cycles: the chaos game reaches "
                 "each from its own chains, restarted regularly.\n",
                 cyclic);
  for (std::size_t i = 0; i < reports.size(); ++i) {
    const auto& r = reports[i];
    if (!r.function->muted && r.contractivity.bound >= 1.0 && r.function->kind == FunctionKind::Matrix)
      std::fprintf(stderr,
                   "warning: function %zu \"%s\" may not be contractive: its matrix contracts the simplex by "
                   "%.4g (>= 1).\n",
                   i, r.function->name.c_str(), r.contractivity.bound);
    else if (!r.function->muted && r.contractivity.bound >= 1.0)
      std::fprintf(stderr,
                   "warning: function %zu \"%s\" may not be contractive: its Lipschitz bound is %.4g (>= 1) "
                   "around cell (%d, %d, %d).\n",
                   i, r.function->name.c_str(), r.contractivity.bound, r.contractivity.worstCell[0],
                   r.contractivity.worstCell[1], r.contractivity.worstCell[2]);
  }
  for (const std::string& w : freeFormWarnings(p)) std::fprintf(stderr, "warning: %s.\n", w.c_str());
  return kSuccess;
}

const VerbRegistration kInfo{
    {"info",
     "FILE [--json --device D --parameters --set PATH=NUMBER]: functions, weights, contractivity and the render "
     "device, or every number of the project by its parameter path",
     [](CLI::App& app) {
       auto file = std::make_shared<std::string>();
       auto asJson = std::make_shared<bool>(false);
       auto parameters = std::make_shared<bool>(false);
       auto device = std::make_shared<std::optional<std::string>>();
       app.add_option("FILE", *file, "project file (.gridifs)")->required();
       app.add_flag("--json", *asJson, "print JSON instead of a table");
       app.add_option("--device", *device, "which render device to report: auto (default), gpu or cpu");
       app.add_flag("--parameters", *parameters,
                    "list every number of the project by its parameter path (the paths of --set, keyframe tracks "
                    "and scripts), with its value and slider range");
       addSetOption(app);
       return [=] { return *parameters ? runParameters(*file, *asJson) : runInfo(*file, *asJson, *device); };
     }}};

}  // namespace
}  // namespace gridifs::cli
