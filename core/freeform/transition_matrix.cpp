#include "freeform/transition_matrix.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <string>

namespace gridifs {
namespace {

std::string rowPath(std::size_t i) { return "transitions[" + std::to_string(i) + "]"; }

/// Renumbers the functions named by the project's states (`to` returns -1 for a removed one).
template <class Map>
void remapStates(Project& project, Map to) {
  if (!project.states) return;
  for (auto& row : project.states->matrix)
    for (auto& entry : row) {
      std::vector<std::uint32_t> kept;
      for (std::uint32_t f : entry)
        if (const int g = to(int(f)); g >= 0) kept.push_back(std::uint32_t(g));
      std::sort(kept.begin(), kept.end());
      entry = std::move(kept);
    }
}

}  // namespace

std::vector<std::size_t> activeFunctionIndices(const Project& project) {
  std::vector<std::size_t> active;
  for (std::size_t i = 0; i < project.functions.size(); ++i)
    if (!project.functions[i].muted && project.functions[i].weight > 0.0) active.push_back(i);
  return active;
}

std::vector<std::vector<double>> activeTransitionWeights(const Project& project,
                                                         const std::vector<std::size_t>& active) {
  const auto& t = project.transitions;
  if (t.empty() || active.empty()) return {};
  bool uniform = true;
  const double first = t[active[0]][active[0]];
  for (std::size_t i : active)
    for (std::size_t j : active) uniform &= t[i][j] == first;
  if (uniform && first > 0.0) return {};
  std::vector<std::vector<double>> rows(active.size(), std::vector<double>(active.size(), 0.0));
  for (std::size_t r = 0; r < active.size(); ++r) {
    double total = 0.0;
    for (std::size_t c = 0; c < active.size(); ++c) {
      rows[r][c] = t[active[r]][active[c]] * project.functions[active[c]].weight;
      total += rows[r][c];
    }
    if (!(total > 0.0))
      throw ModelError(rowPath(active[r]), "function " + std::to_string(active[r]) +
                                               " can be followed by no function with a positive weight");
  }
  return rows;
}

std::vector<std::vector<std::size_t>> stronglyConnectedComponents(
    std::size_t n, const std::function<bool(std::size_t, std::size_t)>& edge) {
  std::vector<int> index(n, -1), low(n, 0);
  std::vector<bool> onStack(n, false);
  std::vector<std::size_t> stack;
  std::vector<std::vector<std::size_t>> components;
  int counter = 0;
  std::function<void(std::size_t)> visit = [&](std::size_t v) {
    index[v] = low[v] = counter++;
    stack.push_back(v);
    onStack[v] = true;
    for (std::size_t w = 0; w < n; ++w) {
      if (!edge(v, w)) continue;
      if (index[w] < 0) {
        visit(w);
        low[v] = std::min(low[v], low[w]);
      } else if (onStack[w]) {
        low[v] = std::min(low[v], index[w]);
      }
    }
    if (low[v] != index[v]) return;
    std::vector<std::size_t> component;
    std::size_t w;
    do {
      w = stack.back();
      stack.pop_back();
      onStack[w] = false;
      component.push_back(w);
    } while (w != v);
    std::sort(component.begin(), component.end());
    components.push_back(std::move(component));
  };
  for (std::size_t v = 0; v < n; ++v)
    if (index[v] < 0) visit(v);
  std::sort(components.begin(), components.end());
  return components;
}

std::vector<std::vector<std::size_t>> transitionComponents(const Project& project) {
  // Over the active functions; `active` ascends, so the components keep their order as indices.
  const std::vector<std::size_t> active = activeFunctionIndices(project);
  std::vector<std::vector<std::size_t>> components =
      stronglyConnectedComponents(active.size(), [&](std::size_t a, std::size_t b) {
        return project.transitions.empty() || project.transitions[active[a]][active[b]] > 0.0;
      });
  for (auto& component : components)
    for (std::size_t& v : component) v = active[v];
  return components;
}

void insertFunction(Project& project, std::size_t index, Function function) {
  index = std::min(index, project.functions.size());
  project.functions.insert(project.functions.begin() + std::ptrdiff_t(index), std::move(function));
  const int at = int(index);
  remapTrackIndices(project.tracks, "functions", [at](int i) { return i >= at ? i + 1 : i; });
  remapStates(project, [at](int i) { return i >= at ? i + 1 : i; });
  auto& t = project.transitions;
  if (t.empty()) return;
  for (auto& row : t) row.insert(row.begin() + std::ptrdiff_t(std::min(index, row.size())), 1.0);
  t.insert(t.begin() + std::ptrdiff_t(std::min(index, t.size())), std::vector<double>(project.functions.size(), 1.0));
}

void eraseFunction(Project& project, std::size_t index) {
  if (index >= project.functions.size()) return;
  project.functions.erase(project.functions.begin() + std::ptrdiff_t(index));
  const int at = int(index);
  remapTrackIndices(project.tracks, "functions", [at](int i) { return i == at ? -1 : i > at ? i - 1 : i; });
  remapStates(project, [at](int i) { return i == at ? -1 : i > at ? i - 1 : i; });
  auto& t = project.transitions;
  if (t.empty()) return;
  if (index < t.size()) t.erase(t.begin() + std::ptrdiff_t(index));
  for (auto& row : t)
    if (index < row.size()) row.erase(row.begin() + std::ptrdiff_t(index));
  // A row whose only allowed successor was the removed function would be invalid: allow all.
  for (auto& row : t)
    if (std::none_of(row.begin(), row.end(), [](double w) { return w > 0.0; })) std::fill(row.begin(), row.end(), 1.0);
  if (t.empty()) t.clear();
}

void swapFunctions(Project& project, std::size_t a, std::size_t b) {
  if (a >= project.functions.size() || b >= project.functions.size()) return;
  std::swap(project.functions[a], project.functions[b]);
  const int ia = int(a), ib = int(b);
  remapTrackIndices(project.tracks, "functions", [ia, ib](int i) { return i == ia ? ib : i == ib ? ia : i; });
  remapStates(project, [ia, ib](int i) { return i == ia ? ib : i == ib ? ia : i; });
  auto& t = project.transitions;
  if (t.size() != project.functions.size()) return;
  std::swap(t[a], t[b]);
  for (auto& row : t)
    if (row.size() == t.size()) std::swap(row[a], row[b]);
}

}  // namespace gridifs
