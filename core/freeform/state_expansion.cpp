#include "freeform/state_expansion.h"

#include <algorithm>
#include <string>

namespace gridifs {
namespace {

std::string matrixPath(std::size_t i) { return "states.matrix[" + std::to_string(i) + "]"; }
std::string entryPath(std::size_t i, std::size_t j) { return matrixPath(i) + "[" + std::to_string(j) + "]"; }

void checkStateList(const std::vector<std::uint32_t>& list, std::size_t n, const std::string& path, const char* name) {
  if (list.empty())
    throw ModelError(path, std::string("the ") + name + " state set is empty, so the attractor would be empty");
  for (std::size_t k = 0; k < list.size(); ++k)
    if (list[k] >= n)
      throw ModelError(
          path + "[" + std::to_string(k) + "]",
          "state " + std::to_string(list[k]) + " does not exist (the matrix has " + std::to_string(n) + " states)");
}

}  // namespace

void checkStates(const Project& project) {
  if (!project.states) return;
  const IfsStates& s = *project.states;
  if (!project.transitions.empty())
    throw ModelError("states", "a project has either states or transitions, not both; remove one of them");
  const std::size_t n = s.matrix.size(), functions = project.functions.size();
  if (n == 0) throw ModelError("states.matrix", "the matrix needs at least one state");
  for (std::size_t i = 0; i < n; ++i) {
    if (s.matrix[i].size() != n)
      throw ModelError(matrixPath(i), "expected " + std::to_string(n) + " entries (the matrix is square), found " +
                                          std::to_string(s.matrix[i].size()));
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t k = 0; k < s.matrix[i][j].size(); ++k)
        if (s.matrix[i][j][k] >= functions)
          throw ModelError(entryPath(i, j) + "[" + std::to_string(k) + "]",
                           "function " + std::to_string(s.matrix[i][j][k]) + " does not exist (the project has " +
                               std::to_string(functions) + " functions)");
  }
  checkStateList(s.initial, n, "states.initial", "initial");
  checkStateList(s.final, n, "states.final", "final");
  try {
    requireAttractor(toIfsMatrix(s), "state matrix");
  } catch (const ModelError& e) {
    throw ModelError("states", e.message());
  }
}

IfsMatrix toIfsMatrix(const IfsStates& states) {
  IfsMatrix m = emptyIfsMatrix(states.matrix.size());
  for (std::size_t i = 0; i < states.matrix.size(); ++i)
    for (std::size_t j = 0; j < states.matrix[i].size() && j < m.size(); ++j)
      for (std::uint32_t f : states.matrix[i][j]) m.entries[i][j].insert({f});
  for (std::uint32_t q : states.initial) m.initial.push_back(q);
  for (std::uint32_t q : states.final) m.final.push_back(q);
  std::sort(m.initial.begin(), m.initial.end());
  m.initial.erase(std::unique(m.initial.begin(), m.initial.end()), m.initial.end());
  std::sort(m.final.begin(), m.final.end());
  m.final.erase(std::unique(m.final.begin(), m.final.end()), m.final.end());
  return m;
}

IfsStates toIfsStates(const IfsMatrix& m) {
  const IfsMatrix letters = lettersOnly(m);
  IfsStates s;
  s.matrix.assign(letters.size(), std::vector<std::vector<std::uint32_t>>(letters.size()));
  for (std::size_t i = 0; i < letters.size(); ++i)
    for (std::size_t j = 0; j < letters.size(); ++j)
      for (const FunctionWord& w : letters.entries[i][j]) s.matrix[i][j].push_back(w.at(0));
  for (std::size_t q : letters.initial) s.initial.push_back(std::uint32_t(q));
  for (std::size_t q : letters.final) s.final.push_back(std::uint32_t(q));
  return s;
}

IfsMatrix ifsMatrixOf(const Project& project) {
  if (project.states) return toIfsMatrix(*project.states);
  const std::size_t n = project.functions.size();
  if (project.transitions.empty()) return singleStateMatrix(std::uint32_t(n));
  // State a: the next map read is a. Reading a from state a leads to state b when b may be
  // applied before a, i.e. a may follow b.
  IfsMatrix m = emptyIfsMatrix(n);
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = 0; b < n; ++b)
      if (project.transitions[b][a] > 0.0) m.entries[a][b].insert({std::uint32_t(a)});
    m.initial.push_back(a);
    m.final.push_back(a);
  }
  return m;
}

void setIfsMatrix(Project& project, const IfsMatrix& m) {
  requireAttractor(m, "result");
  project.states = toIfsStates(trimmed(lettersOnly(m)));
  project.transitions.clear();
}

StateExpansion expandStates(const Project& project, const std::vector<char>& active) {
  IfsMatrix m = toIfsMatrix(*project.states);
  for (auto& row : m.entries)
    for (auto& entry : row)
      std::erase_if(entry, [&](const FunctionWord& w) { return w.at(0) >= active.size() || !active[w[0]]; });
  if (!hasAttractor(m))
    throw ModelError("states",
                     "with the muted functions and those of weight 0 left out, no path from an initial to a final "
                     "state goes through a cycle, so the attractor is empty");
  m = trimmed(m);
  StateExpansion x;
  x.states = m.size();
  std::vector<char> isInitial(m.size(), 0), entered(m.size(), 0);
  for (std::size_t q : m.initial) isInitial[q] = 1;
  for (std::size_t i = 0; i < m.size(); ++i)
    for (std::size_t j = 0; j < m.size(); ++j)
      if (!m.entries[i][j].empty()) entered[j] = 1;
  for (std::size_t i = 0; i < m.size(); ++i)
    for (std::size_t j = 0; j < m.size(); ++j)
      for (const FunctionWord& w : m.entries[i][j]) {
        if (x.function.size() == kMaxVirtualFunctions)
          throw ModelError("states", "the state matrix has more than " + std::to_string(kMaxVirtualFunctions) +
                                         " entries (function, from, to) in all");
        x.function.push_back(w[0]);
        x.from.push_back(i);
        x.to.push_back(j);
        x.step.push_back(!isInitial[i] ? StateStep::Hidden : entered[i] ? StateStep::Plot : StateStep::Peek);
      }
  std::vector<std::size_t> componentOf(m.size(), 0);
  const auto components = stateComponents(m);
  for (std::size_t c = 0; c < components.size(); ++c)
    for (std::size_t q : components[c]) componentOf[q] = c;
  for (std::size_t k = 0; k < x.function.size(); ++k)
    x.internal.push_back(componentOf[x.from[k]] == componentOf[x.to[k]]);
  const std::size_t v = x.function.size();
  x.follows.assign(v, std::vector<char>(v, 0));
  for (std::size_t a = 0; a < v; ++a)
    for (std::size_t b = 0; b < v; ++b) x.follows[a][b] = x.to[b] == x.from[a];
  return x;
}

StateExpansion expandStatesOver(const Project& project, const std::vector<std::size_t>& present,
                                std::vector<std::size_t>& position) {
  std::vector<char> active(project.functions.size(), 0);
  std::vector<std::size_t> at(project.functions.size(), 0);
  for (std::size_t k = 0; k < present.size(); ++k) {
    active[present[k]] = 1;
    at[present[k]] = k;
  }
  StateExpansion x = expandStates(project, active);
  position.clear();
  for (std::size_t f : x.function) position.push_back(at[f]);
  return x;
}

}  // namespace gridifs
