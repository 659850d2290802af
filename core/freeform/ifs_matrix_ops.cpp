#include "freeform/ifs_matrix_ops.h"

#include <algorithm>
#include <functional>

#include "base/errors.h"
#include "freeform/transition_matrix.h"

namespace gridifs {
namespace {

/// The most states an operation may build (a tensor of two 64-state matrices).
constexpr std::size_t kMaxStates = 4096;

[[noreturn]] void fail(const std::string& message) { throw ModelError("", message); }

void checkStates(std::size_t n, const char* what) {
  if (n > kMaxStates)
    fail(std::string("the ") + what + " would have " + std::to_string(n) + " states, more than the limit of " +
         std::to_string(kMaxStates));
}

void requireSameStates(const IfsMatrix& a, const IfsMatrix& b, const char* what) {
  if (a.size() != b.size())
    fail(std::string(what) + " needs two matrices with the same states, not " + std::to_string(a.size()) + " and " +
         std::to_string(b.size()) + " states");
}

std::vector<std::size_t> sortedUnique(std::vector<std::size_t> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

std::vector<std::size_t> pairs(const std::vector<std::size_t>& a, const std::vector<std::size_t>& b, std::size_t m) {
  std::vector<std::size_t> out;
  for (std::size_t i : a)
    for (std::size_t k : b) out.push_back(i * m + k);
  return sortedUnique(out);
}

std::vector<std::size_t> shifted(const std::vector<std::size_t>& v, std::size_t by) {
  std::vector<std::size_t> out;
  for (std::size_t s : v) out.push_back(s + by);
  return out;
}

void insertAll(WordSet& into, const WordSet& from) { into.insert(from.begin(), from.end()); }

/// States reachable from `from` along non-empty entries (forward) or reaching it (backward).
std::vector<char> reach(const IfsMatrix& m, const std::vector<std::size_t>& from, bool forward) {
  const std::size_t n = m.size();
  std::vector<char> seen(n, 0);
  std::vector<std::size_t> stack;
  for (std::size_t s : from)
    if (s < n && !seen[s]) seen[s] = 1, stack.push_back(s);
  while (!stack.empty()) {
    const std::size_t s = stack.back();
    stack.pop_back();
    for (std::size_t t = 0; t < n; ++t) {
      const bool edge = forward ? !m.entries[s][t].empty() : !m.entries[t][s].empty();
      if (edge && !seen[t]) seen[t] = 1, stack.push_back(t);
    }
  }
  return seen;
}

}  // namespace

IfsMatrix emptyIfsMatrix(std::size_t n) {
  IfsMatrix m;
  m.entries.assign(n, std::vector<WordSet>(n));
  return m;
}

IfsMatrix singleStateMatrix(std::uint32_t count) {
  IfsMatrix m = emptyIfsMatrix(1);
  for (std::uint32_t f = 0; f < count; ++f) m.entries[0][0].insert({f});
  m.initial = m.final = {0};
  return m;
}

IfsMatrix relabel(const IfsMatrix& m, const std::vector<std::uint32_t>& map) {
  IfsMatrix out = m;
  for (std::size_t i = 0; i < m.size(); ++i)
    for (std::size_t j = 0; j < m.size(); ++j) {
      WordSet words;
      for (FunctionWord w : m.entries[i][j]) {
        for (auto& f : w) {
          if (f >= map.size()) fail("function " + std::to_string(f) + " has no new index");
          f = map[f];
        }
        words.insert(std::move(w));
      }
      out.entries[i][j] = std::move(words);
    }
  return out;
}

IfsMatrix matrixUnion(const IfsMatrix& a, const IfsMatrix& b) {
  requireSameStates(a, b, "the union of matrices");
  IfsMatrix out = a;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < a.size(); ++j) insertAll(out.entries[i][j], b.entries[i][j]);
  std::vector<std::size_t> qi = a.initial, qf = a.final;
  qi.insert(qi.end(), b.initial.begin(), b.initial.end());
  qf.insert(qf.end(), b.final.begin(), b.final.end());
  out.initial = sortedUnique(qi);
  out.final = sortedUnique(qf);
  return out;
}

IfsMatrix matrixIntersection(const IfsMatrix& a, const IfsMatrix& b) {
  requireSameStates(a, b, "the intersection of matrices");
  IfsMatrix out = emptyIfsMatrix(a.size());
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < a.size(); ++j)
      std::set_intersection(a.entries[i][j].begin(), a.entries[i][j].end(), b.entries[i][j].begin(),
                            b.entries[i][j].end(), std::inserter(out.entries[i][j], out.entries[i][j].end()));
  std::set_intersection(a.initial.begin(), a.initial.end(), b.initial.begin(), b.initial.end(),
                        std::back_inserter(out.initial));
  std::set_intersection(a.final.begin(), a.final.end(), b.final.begin(), b.final.end(), std::back_inserter(out.final));
  return out;
}

IfsMatrix matrixComposition(const IfsMatrix& a, const IfsMatrix& b) {
  requireSameStates(a, b, "the composition of matrices");
  const std::size_t n = a.size();
  IfsMatrix out = emptyIfsMatrix(n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t k = 0; k < n; ++k)
        for (const FunctionWord& u : a.entries[i][k])
          for (const FunctionWord& v : b.entries[k][j]) {
            FunctionWord uv = u;
            uv.insert(uv.end(), v.begin(), v.end());
            out.entries[i][j].insert(std::move(uv));
          }
  out.initial = a.initial;
  out.final = b.final;
  return out;
}

namespace {

/// The matrix over the pairs of a's and b's states: `fill` makes entry ((i, k), (j, l)) from a's
/// entry (i, j) and b's (k, l); the initial and final states are the pairs of a's and b's.
template <class Fill>
IfsMatrix overStatePairs(const IfsMatrix& a, const IfsMatrix& b, const char* what, Fill fill) {
  const std::size_t n = a.size(), m = b.size();
  checkStates(n * m, what);
  IfsMatrix out = emptyIfsMatrix(n * m);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t k = 0; k < m; ++k)
        for (std::size_t l = 0; l < m; ++l) fill(out.entries[i * m + k][j * m + l], i, j, k, l);
  out.initial = pairs(a.initial, b.initial, m);
  out.final = pairs(a.final, b.final, m);
  return out;
}

}  // namespace

IfsMatrix tensorProduct(const IfsMatrix& a, const IfsMatrix& b) {
  return overStatePairs(a, b, "tensor product",
                        [&](WordSet& e, std::size_t i, std::size_t j, std::size_t k, std::size_t l) {
                          e = a.entries[i][j];
                          insertAll(e, b.entries[k][l]);
                        });
}

IfsMatrix tensorSum(const IfsMatrix& a, const IfsMatrix& b) {
  return overStatePairs(a, b, "tensor sum",
                        [&](WordSet& e, std::size_t i, std::size_t j, std::size_t k, std::size_t l) {
                          if (k == l) insertAll(e, a.entries[i][j]);  // Ĩd · H̃_ij: a steps, b stays
                          if (i == j) insertAll(e, b.entries[k][l]);  // H̃′ on the diagonal blocks: b steps, a stays
                        });
}

IfsMatrix blockUnion(const IfsMatrix& a, const IfsMatrix& b) {
  const std::size_t n = a.size(), m = b.size();
  checkStates(n + m, "block matrix");
  IfsMatrix out = emptyIfsMatrix(n + m);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) out.entries[i][j] = a.entries[i][j];
  for (std::size_t k = 0; k < m; ++k)
    for (std::size_t l = 0; l < m; ++l) out.entries[n + k][n + l] = b.entries[k][l];
  out.initial = a.initial;
  out.final = a.final;
  for (std::size_t s : shifted(b.initial, n)) out.initial.push_back(s);
  for (std::size_t s : shifted(b.final, n)) out.final.push_back(s);
  return out;
}

IfsMatrix concatenation(const IfsMatrix& a, const IfsMatrix& b) {
  IfsMatrix out = blockUnion(a, b);
  const std::size_t n = a.size();
  // Thollot et al. §4.2: some ∅ of the block matrix replaced by the identity — from where a word
  // of L may end to where a word of L′ may begin.
  for (std::size_t k : a.final)
    for (std::size_t l : b.initial) out.entries[k][n + l].insert(FunctionWord{});
  out.initial = a.initial;
  out.final = shifted(b.final, n);
  return out;
}

IfsMatrix lettersOnly(const IfsMatrix& m) {
  const std::size_t n0 = m.size();
  std::size_t n = n0;
  for (std::size_t i = 0; i < n0; ++i)
    for (std::size_t j = 0; j < n0; ++j)
      for (const FunctionWord& w : m.entries[i][j])
        if (w.size() > 1) n += w.size() - 1;
  checkStates(n, "matrix of single functions");
  IfsMatrix letters = emptyIfsMatrix(n);
  std::vector<std::vector<char>> eps(n, std::vector<char>(n, 0));
  std::size_t next = n0;
  for (std::size_t i = 0; i < n0; ++i)
    for (std::size_t j = 0; j < n0; ++j)
      for (const FunctionWord& w : m.entries[i][j]) {
        if (w.empty()) {
          eps[i][j] = 1;
          continue;
        }
        // T_w1 … T_wr through r − 1 new states: i → s1 → … → j.
        std::size_t from = i;
        for (std::size_t r = 0; r < w.size(); ++r) {
          const std::size_t to = r + 1 == w.size() ? j : next++;
          letters.entries[from][to].insert({w[r]});
          from = to;
        }
      }
  // ε-closure: a state reads what every state it reaches by identities reads, and is final when
  // one of them is.
  IfsMatrix out = emptyIfsMatrix(n);
  std::vector<char> isFinal(n, 0);
  for (std::size_t f : m.final) isFinal[f] = 1;
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<char> closure(n, 0);
    std::vector<std::size_t> stack{i};
    closure[i] = 1;
    while (!stack.empty()) {
      const std::size_t s = stack.back();
      stack.pop_back();
      for (std::size_t t = 0; t < n; ++t)
        if (eps[s][t] && !closure[t]) closure[t] = 1, stack.push_back(t);
    }
    for (std::size_t k = 0; k < n; ++k) {
      if (!closure[k]) continue;
      if (isFinal[k]) out.final.push_back(i);
      for (std::size_t j = 0; j < n; ++j) insertAll(out.entries[i][j], letters.entries[k][j]);
    }
  }
  out.initial = m.initial;
  out.final = sortedUnique(out.final);
  return out;
}

IfsMatrix trimmed(const IfsMatrix& m, std::vector<std::size_t>* kept) {
  const auto forward = reach(m, m.initial, true), backward = reach(m, m.final, false);
  std::vector<std::size_t> keep, newIndex(m.size(), std::size_t(-1));
  for (std::size_t s = 0; s < m.size(); ++s)
    if (forward[s] && backward[s]) newIndex[s] = keep.size(), keep.push_back(s);
  IfsMatrix out = emptyIfsMatrix(keep.size());
  for (std::size_t i = 0; i < keep.size(); ++i)
    for (std::size_t j = 0; j < keep.size(); ++j) out.entries[i][j] = m.entries[keep[i]][keep[j]];
  for (std::size_t s : m.initial)
    if (newIndex[s] != std::size_t(-1)) out.initial.push_back(newIndex[s]);
  for (std::size_t s : m.final)
    if (newIndex[s] != std::size_t(-1)) out.final.push_back(newIndex[s]);
  if (kept) *kept = keep;
  return out;
}

std::vector<std::vector<std::size_t>> stateComponents(const IfsMatrix& m) {
  return stronglyConnectedComponents(m.size(), [&](std::size_t v, std::size_t w) { return !m.entries[v][w].empty(); });
}

bool hasAttractor(const IfsMatrix& m) {
  const IfsMatrix useful = trimmed(lettersOnly(m));
  if (useful.initial.empty()) return false;
  // Without ε entries every edge reads a map: words of every length exist iff a cycle does.
  for (const auto& component : stateComponents(useful))
    if (component.size() > 1 || !useful.entries[component[0]][component[0]].empty()) return true;
  return false;
}

void requireAttractor(const IfsMatrix& m, const std::string& what) {
  if (m.initial.empty()) fail("the " + what + " has no initial state (Q_I is empty), so it has no attractor");
  if (m.final.empty()) fail("the " + what + " has no final state (Q_F is empty), so it has no attractor");
  if (trimmed(lettersOnly(m)).initial.empty())
    fail("the " + what + " has no path from an initial to a final state, so it has no attractor");
  if (!hasAttractor(m))
    fail("the " + what + " accepts only finitely many words (no cycle between its initial and final states), so " +
         "it has no attractor");
}

std::set<FunctionWord> acceptedWords(const IfsMatrix& m, std::size_t maxLength) {
  std::set<FunctionWord> words;
  std::set<std::pair<std::size_t, FunctionWord>> seen;
  std::vector<std::pair<std::size_t, FunctionWord>> stack;
  for (std::size_t s : m.initial)
    if (seen.insert({s, {}}).second) stack.push_back({s, {}});
  std::vector<char> isFinal(m.size(), 0);
  for (std::size_t f : m.final) isFinal[f] = 1;
  while (!stack.empty()) {
    auto [s, w] = stack.back();
    stack.pop_back();
    if (isFinal[s]) words.insert(w);
    for (std::size_t t = 0; t < m.size(); ++t)
      for (const FunctionWord& e : m.entries[s][t]) {
        if (w.size() + e.size() > maxLength) continue;
        FunctionWord longer = w;
        longer.insert(longer.end(), e.begin(), e.end());
        if (seen.insert({t, longer}).second) stack.push_back({t, std::move(longer)});
      }
  }
  return words;
}

}  // namespace gridifs
