#pragma once
// Matrices of function sets and the operations on them (Thollot, Zair, Tosan & Vandorpe 1997, §3.2
// and §4). An IfsMatrix is an automaton over the alphabet of function indices: entry (i, j) is the
// set H̃_ij of maps read going from state i to state j. A word σ1…σk labelling a path from an
// initial to a final state stands for the map T_σ1 ∘ … ∘ T_σk (σ1 outermost), and the attractor
// ⋃_{i∈Q_I, j∈Q_F} Ã(H̃)_ij is the limit of those maps' images (§3.2).
//
// Entries hold words rather than letters so that composition can be written as the paper writes
// it, (H̃H̃′)_ij = ⋃_k H̃_ik H̃′_kj (its entries are the composed maps T_a T_b), and concatenation
// with the identity (the empty word ε) in a block. lettersOnly() turns any matrix into one whose
// entries are single functions and which accepts the same words (the form a project stores).
//
// Every function here is pure: thread-safe. Each throws ModelError (empty path) with one sentence
// when its arguments do not fit (sizes, states out of range).
#include <cstddef>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace gridifs {

/// A word of function indices, outermost map first; empty: the identity (ε).
using FunctionWord = std::vector<std::uint32_t>;
using WordSet = std::set<FunctionWord>;

struct IfsMatrix {
  /// n × n entries.
  std::vector<std::vector<WordSet>> entries;
  std::vector<std::size_t> initial;  // Q_I, ascending
  std::vector<std::size_t> final;    // Q_F, ascending
  std::size_t size() const { return entries.size(); }
  bool operator==(const IfsMatrix&) const = default;
};

/// An n-state matrix with every entry empty and no initial or final state.
IfsMatrix emptyIfsMatrix(std::size_t n);

/// A plain IFS {T_0, …, T_{count−1}} as a 1 × 1 matrix, Q_I = Q_F = {0}.
IfsMatrix singleStateMatrix(std::uint32_t count);

/// The same matrix with every function index f replaced by map[f] (map must cover every index).
IfsMatrix relabel(const IfsMatrix& m, const std::vector<std::uint32_t>& map);

// ---- Thollot et al. §4.1: operations on matrices --------------------------------------------

/// (H̃ ∪ H̃′)_ij = H̃_ij ∪ H̃′_ij on matrices with the same states; Q_I ∪ Q′_I, Q_F ∪ Q′_F.
IfsMatrix matrixUnion(const IfsMatrix& a, const IfsMatrix& b);
/// (H̃ ∩ H̃′)_ij = H̃_ij ∩ H̃′_ij on matrices with the same states; Q_I ∩ Q′_I, Q_F ∩ Q′_F.
IfsMatrix matrixIntersection(const IfsMatrix& a, const IfsMatrix& b);
/// (H̃H̃′)_ij = ⋃_k H̃_ik H̃′_kj (each entry the words uv); Q_I of a, Q_F of b.
IfsMatrix matrixComposition(const IfsMatrix& a, const IfsMatrix& b);
/// H̃ ⊗ H̃′: n·m states (i, k) ↦ i·m + k, entry ((i,k), (j,l)) = H̃_ij ∪ H̃′_kl as the paper
/// defines it; Q_I × Q′_I, Q_F × Q′_F.
IfsMatrix tensorProduct(const IfsMatrix& a, const IfsMatrix& b);

// ---- Thollot et al. §4.2: language operations ------------------------------------------------

/// H̃ ◇⊔ H̃′ (tensor sum): entry ((i,k), (j,l)) = H̃_ij when k = l, plus H̃′_kl when i = j. It
/// accepts the shuffle of the two languages; Q_I × Q′_I, Q_F × Q′_F.
IfsMatrix tensorSum(const IfsMatrix& a, const IfsMatrix& b);
/// The block matrix diag(H̃, H̃′) with Q_I ∪ Q′_I and Q_F ∪ Q′_F (b's states after a's): it accepts
/// L ∪ L′ and its attractor is the union of the two attractors.
IfsMatrix blockUnion(const IfsMatrix& a, const IfsMatrix& b);
/// The block matrix with ε from each final state of a to each initial state of b, Q_I of a and Q_F
/// of b: it accepts the concatenation L·L′.
IfsMatrix concatenation(const IfsMatrix& a, const IfsMatrix& b);

// ---- Normal forms and analysis ---------------------------------------------------------------

/// The same words with entries that are single functions: longer words go through new states,
/// ε entries are removed by ε-closure. States are kept (new ones appended).
IfsMatrix lettersOnly(const IfsMatrix& m);
/// Only the useful states (reachable from Q_I and reaching Q_F), renumbered in order; `kept` (when
/// not null) receives the old index of each new state. Accepts the same words.
IfsMatrix trimmed(const IfsMatrix& m, std::vector<std::size_t>* kept = nullptr);
/// Whether the matrix accepts words of every length, i.e. its attractor is non-empty: some cycle
/// of non-empty words lies on a path from Q_I to Q_F.
bool hasAttractor(const IfsMatrix& m);
/// Throws ModelError (empty path) naming `what` when the matrix has no attractor: no initial or
/// final state, no path from Q_I to Q_F, or only finitely many words.
void requireAttractor(const IfsMatrix& m, const std::string& what);
/// Strongly connected components of the graph of non-empty entries, each ascending, sorted.
std::vector<std::vector<std::size_t>> stateComponents(const IfsMatrix& m);
/// Every word of length ≤ maxLength (as maps, ε entries contributing nothing) labelling a path
/// from Q_I to Q_F. For tests and small matrices: the count grows like |Σ|^maxLength.
std::set<FunctionWord> acceptedWords(const IfsMatrix& m, std::size_t maxLength);

}  // namespace gridifs
