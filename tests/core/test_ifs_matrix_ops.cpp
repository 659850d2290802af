// The operations on IFS matrices (Thollot, Zair, Tosan & Vandorpe 1997, §4), checked by the
// languages the results accept: every word of length ≤ k accepted from Q_I to Q_F is compared
// with the language the paper's definition gives, computed here from the two operands' languages
// or by simulating the definition directly on pairs of states.
#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "freeform/ifs_matrix_ops.h"
#include "model_error_text.h"

using namespace gridifs;

namespace {

constexpr std::size_t kMaxLength = 5;
constexpr std::uint32_t kLetters = 3;

using Language = std::set<FunctionWord>;

/// A random matrix over letters 0..kLetters−1 with n states (seeded: the same every run).
IfsMatrix randomMatrix(std::size_t n, std::mt19937& rng) {
  IfsMatrix m = emptyIfsMatrix(n);
  std::bernoulli_distribution coin(0.35);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      for (std::uint32_t f = 0; f < kLetters; ++f)
        if (coin(rng)) m.entries[i][j].insert({f});
  for (std::size_t s = 0; s < n; ++s) {
    if (coin(rng) || s == 0) m.initial.push_back(s);
    if (coin(rng) || s + 1 == n) m.final.push_back(s);
  }
  return m;
}

/// Every word over the alphabet of length ≤ kMaxLength.
std::vector<FunctionWord> allWords() {
  std::vector<FunctionWord> out{{}};
  for (std::size_t k = 0; k < out.size(); ++k)
    if (out[k].size() < kMaxLength)
      for (std::uint32_t f = 0; f < kLetters; ++f) {
        FunctionWord w = out[k];
        w.push_back(f);
        out.push_back(w);
      }
  return out;
}

bool reads(const WordSet& entry, std::uint32_t f) { return entry.count({f}) > 0; }

/// Words accepted by the automaton on pairs of states (i, k) that `step(i, k, j, l, f)` defines,
/// from Q_I × Q′_I to Q_F × Q′_F: the paper's definitions of the tensor operations, simulated.
Language pairLanguage(
    const IfsMatrix& a, const IfsMatrix& b,
    const std::function<bool(std::size_t, std::size_t, std::size_t, std::size_t, std::uint32_t)>& step) {
  Language out;
  for (const FunctionWord& w : allWords()) {
    std::set<std::pair<std::size_t, std::size_t>> now;
    for (std::size_t i : a.initial)
      for (std::size_t k : b.initial) now.insert({i, k});
    for (std::uint32_t f : w) {
      std::set<std::pair<std::size_t, std::size_t>> next;
      for (auto [i, k] : now)
        for (std::size_t j = 0; j < a.size(); ++j)
          for (std::size_t l = 0; l < b.size(); ++l)
            if (step(i, k, j, l, f)) next.insert({j, l});
      now = std::move(next);
    }
    bool accepted = false;
    for (auto [i, k] : now)
      accepted |= std::count(a.final.begin(), a.final.end(), i) && std::count(b.final.begin(), b.final.end(), k);
    if (accepted) out.insert(w);
  }
  return out;
}

/// All interleavings of u and v.
void shuffles(const FunctionWord& u, const FunctionWord& v, FunctionWord prefix, Language& out) {
  if (u.empty() && v.empty()) {
    out.insert(prefix);
    return;
  }
  if (!u.empty()) {
    FunctionWord p = prefix;
    p.push_back(u[0]);
    shuffles(FunctionWord(u.begin() + 1, u.end()), v, p, out);
  }
  if (!v.empty()) {
    prefix.push_back(v[0]);
    shuffles(u, FunctionWord(v.begin() + 1, v.end()), prefix, out);
  }
}

struct Pair {
  IfsMatrix a, b;
};

/// Seeded random pairs: different sizes for the block and tensor operations, equal for the
/// entrywise ones.
std::vector<Pair> randomPairs(bool sameSize) {
  std::mt19937 rng(20240611);
  std::vector<Pair> out;
  for (int t = 0; t < 12; ++t) {
    const std::size_t n = 1 + std::size_t(t % 3), m = sameSize ? n : 1 + std::size_t((t / 3) % 3);
    out.push_back({randomMatrix(n, rng), randomMatrix(m, rng)});
  }
  return out;
}

}  // namespace

TEST(IfsMatrixOps, BlockUnionAcceptsTheUnionOfTheLanguages) {
  for (const auto& [a, b] : randomPairs(false)) {
    Language expected = acceptedWords(a, kMaxLength);
    const Language lb = acceptedWords(b, kMaxLength);
    expected.insert(lb.begin(), lb.end());
    EXPECT_EQ(acceptedWords(blockUnion(a, b), kMaxLength), expected);
  }
}

TEST(IfsMatrixOps, ConcatenationAcceptsTheProductOfTheLanguages) {
  for (const auto& [a, b] : randomPairs(false)) {
    Language expected;
    for (const FunctionWord& u : acceptedWords(a, kMaxLength))
      for (const FunctionWord& v : acceptedWords(b, kMaxLength))
        if (u.size() + v.size() <= kMaxLength) {
          FunctionWord uv = u;
          uv.insert(uv.end(), v.begin(), v.end());
          expected.insert(uv);
        }
    const IfsMatrix c = concatenation(a, b);
    EXPECT_EQ(acceptedWords(c, kMaxLength), expected);
    EXPECT_EQ(acceptedWords(lettersOnly(c), kMaxLength), expected);  // ε removed, same words
    EXPECT_EQ(acceptedWords(trimmed(lettersOnly(c)), kMaxLength), expected);
  }
}

TEST(IfsMatrixOps, TensorSumAcceptsTheShuffle) {
  for (const auto& pair : randomPairs(false)) {
    // Named references: clang 14 cannot capture structured bindings in a lambda.
    const IfsMatrix& a = pair.a;
    const IfsMatrix& b = pair.b;
    Language expected;
    for (const FunctionWord& u : acceptedWords(a, kMaxLength))
      for (const FunctionWord& v : acceptedWords(b, kMaxLength))
        if (u.size() + v.size() <= kMaxLength) shuffles(u, v, {}, expected);
    const IfsMatrix s = tensorSum(a, b);
    EXPECT_EQ(acceptedWords(s, kMaxLength), expected);
    // The paper's block form: (i,k) → (j,l) reads H̃_ij when k = l and H̃′_kl when i = j.
    EXPECT_EQ(acceptedWords(s, kMaxLength),
              pairLanguage(a, b, [&](std::size_t i, std::size_t k, std::size_t j, std::size_t l, std::uint32_t f) {
                return (k == l && reads(a.entries[i][j], f)) || (i == j && reads(b.entries[k][l], f));
              }));
  }
}

TEST(IfsMatrixOps, TensorProductReadsEitherMatrixOnEachPairOfStates) {
  for (const auto& pair : randomPairs(false)) {
    // Named references: clang 14 cannot capture structured bindings in a lambda.
    const IfsMatrix& a = pair.a;
    const IfsMatrix& b = pair.b;
    const IfsMatrix t = tensorProduct(a, b);
    ASSERT_EQ(t.size(), a.size() * b.size());
    EXPECT_EQ(acceptedWords(t, kMaxLength),
              pairLanguage(a, b, [&](std::size_t i, std::size_t k, std::size_t j, std::size_t l, std::uint32_t f) {
                return reads(a.entries[i][j], f) || reads(b.entries[k][l], f);
              }));
    // And each entry is H̃_ij ∪ H̃′_kl, as the paper writes it.
    for (std::size_t i = 0; i < a.size(); ++i)
      for (std::size_t k = 0; k < b.size(); ++k)
        for (std::size_t j = 0; j < a.size(); ++j)
          for (std::size_t l = 0; l < b.size(); ++l) {
            WordSet expected = a.entries[i][j];
            expected.insert(b.entries[k][l].begin(), b.entries[k][l].end());
            EXPECT_EQ(t.entries[i * b.size() + k][j * b.size() + l], expected);
          }
  }
}

TEST(IfsMatrixOps, EntrywiseUnionAndIntersection) {
  for (const auto& pair : randomPairs(true)) {
    // Named references: clang 14 cannot capture structured bindings in a lambda.
    const IfsMatrix& a = pair.a;
    const IfsMatrix& b = pair.b;
    const IfsMatrix u = matrixUnion(a, b), n = matrixIntersection(a, b);
    // The definition, on the pair automaton restricted to equal states: a path of the intersection
    // is a path of both matrices reading the same letters; of the union, of either at each step.
    const auto sameState = [](std::size_t i, std::size_t k, std::size_t j, std::size_t l) { return i == k && j == l; };
    const Language ln = acceptedWords(n, kMaxLength);
    // Q_I ∩ Q′_I and Q_F ∩ Q′_F: the pair automaton starts on (q, q) pairs only.
    IfsMatrix a1 = a, b1 = b;
    a1.initial = b1.initial = n.initial;
    a1.final = b1.final = n.final;
    EXPECT_EQ(ln,
              pairLanguage(a1, b1, [&](std::size_t i, std::size_t k, std::size_t j, std::size_t l, std::uint32_t f) {
                return sameState(i, k, j, l) && reads(a.entries[i][j], f) && reads(b.entries[k][l], f);
              }));
    // L(H̃ ∩ H̃′) ⊆ L ∩ L′ and L ∪ L′ ⊆ L(H̃ ∪ H̃′).
    const Language la = acceptedWords(a, kMaxLength), lb = acceptedWords(b, kMaxLength),
                   lu = acceptedWords(u, kMaxLength);
    for (const FunctionWord& w : ln) {
      EXPECT_TRUE(la.count(w) && lb.count(w));
    }
    for (const FunctionWord& w : la) EXPECT_TRUE(lu.count(w));
    for (const FunctionWord& w : lb) EXPECT_TRUE(lu.count(w));
  }
  // One state each (plain IFSs): exactly L ∩ L′ and L ∪ L′.
  IfsMatrix a = emptyIfsMatrix(1), b = emptyIfsMatrix(1);
  a.entries[0][0] = {{0}, {1}};
  b.entries[0][0] = {{1}, {2}};
  a.initial = a.final = b.initial = b.final = {0};
  const Language la = acceptedWords(a, 4), lb = acceptedWords(b, 4);
  Language both, either = la;
  for (const FunctionWord& w : la)
    if (lb.count(w)) both.insert(w);
  either.insert(lb.begin(), lb.end());
  EXPECT_EQ(acceptedWords(matrixIntersection(a, b), 4), both);
  const Language lu = acceptedWords(matrixUnion(a, b), 4);
  for (const FunctionWord& w : either) EXPECT_TRUE(lu.count(w));
  EXPECT_EQ(lu.size(), 1u + 3u + 9u + 27u + 81u);  // (Σ ∪ Σ′)*: every word over {0, 1, 2}
}

TEST(IfsMatrixOps, CompositionIsTheMatrixProduct) {
  for (const auto& [a, b] : randomPairs(true)) {
    const IfsMatrix c = matrixComposition(a, b);
    // Words u v read i → k in H̃ then k → j in H̃′, repeated: simulate that alternation directly.
    Language expected;
    for (const FunctionWord& w : allWords()) {
      if (w.size() % 2) continue;
      std::set<std::size_t> now(a.initial.begin(), a.initial.end());
      for (std::size_t t = 0; t < w.size(); t += 2) {
        std::set<std::size_t> next;
        for (std::size_t i : now)
          for (std::size_t k = 0; k < a.size(); ++k)
            for (std::size_t j = 0; j < a.size(); ++j)
              if (reads(a.entries[i][k], w[t]) && reads(b.entries[k][j], w[t + 1])) next.insert(j);
        now = std::move(next);
      }
      for (std::size_t j : now)
        if (std::count(b.final.begin(), b.final.end(), j)) {
          expected.insert(w);
          break;
        }
    }
    EXPECT_EQ(acceptedWords(c, kMaxLength), expected);
    EXPECT_EQ(acceptedWords(lettersOnly(c), kMaxLength), expected);
  }
  // One state: (H̃H̃′)_00 = {T_a T_b}.
  IfsMatrix a = emptyIfsMatrix(1), b = emptyIfsMatrix(1);
  a.entries[0][0] = {{0}};
  b.entries[0][0] = {{1}, {2}};
  a.initial = a.final = b.initial = b.final = {0};
  EXPECT_EQ(matrixComposition(a, b).entries[0][0], (WordSet{{0, 1}, {0, 2}}));
}

TEST(IfsMatrixOps, AttractorExistence) {
  IfsMatrix m = emptyIfsMatrix(2);
  m.entries[0][1] = {{0}};
  m.initial = {0};
  m.final = {1};
  EXPECT_FALSE(hasAttractor(m));  // one word only
  m.entries[1][1] = {{1}};
  EXPECT_TRUE(hasAttractor(m));
  m.final = {0};
  EXPECT_FALSE(hasAttractor(m));  // no path back to 0: only the empty word
  EXPECT_NE(test_support::modelErrorText([&] { requireAttractor(m, "result"); }).find("only finitely many words"),
            std::string::npos);
  m.initial = {1};
  EXPECT_NE(test_support::modelErrorText([&] { requireAttractor(m, "result"); }).find("no path from an initial"),
            std::string::npos);
  m.initial.clear();
  EXPECT_NE(test_support::modelErrorText([&] { requireAttractor(m, "result"); }).find("Q_I is empty"),
            std::string::npos);
  // An identity cycle reads no map: not an attractor by itself.
  IfsMatrix e = emptyIfsMatrix(1);
  e.entries[0][0] = {FunctionWord{}};
  e.initial = e.final = {0};
  EXPECT_FALSE(hasAttractor(e));
}

TEST(IfsMatrixOps, TrimmingKeepsUsefulStatesAndComponents) {
  IfsMatrix m = emptyIfsMatrix(4);
  m.entries[0][0] = {{0}};
  m.entries[0][1] = {{1}};
  m.entries[1][1] = {{2}};
  m.entries[2][2] = {{0}};  // unreachable from Q_I
  m.entries[1][3] = {{1}};  // 3 cannot reach Q_F
  m.initial = {0};
  m.final = {1};
  std::vector<std::size_t> kept;
  const IfsMatrix t = trimmed(m, &kept);
  EXPECT_EQ(kept, (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(acceptedWords(t, 6), acceptedWords(m, 6));
  EXPECT_EQ(stateComponents(t), (std::vector<std::vector<std::size_t>>{{0}, {1}}));
}
