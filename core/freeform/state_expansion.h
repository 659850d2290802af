#pragma once
// A project's IFS matrix with states (Thollot, Zair, Tosan & Vandorpe 1997, §3.2), checked,
// converted to and from IfsMatrix (freeform/ifs_matrix_ops.h), and compiled for the chaos game and
// the deterministic algorithm.
//
// The chaos game applies maps one after the other, the last one outermost: the point after
// choosing f_1, …, f_t is T_{f_t} ∘ … ∘ T_{f_1}(p), the word f_t … f_1. The matrix reads words from
// the outermost map, so the chain walks the matrix backwards: a virtual function is one entry
// (i → j, f) of H̃, and after it (its word starts in state i) the next map must be an entry
// (i′ → i, f′) that ends in i. A point is on the attractor when its word starts in an initial
// state, so points whose last map left a state outside Q_I are hidden (moved, not plotted). Q_F
// constrains the innermost end of the words, which the limit forgets: states that cannot reach
// Q_F (or be reached from Q_I) are trimmed away first. An entry leaving an initial state that no
// entry enters ends every word that uses it: it is a "peek" — its image of the current point is
// plotted and the chain stays where it was.
//
// Pure functions of their arguments: thread-safe.
#include <cstdint>
#include <vector>

#include "freeform/ifs_matrix_ops.h"
#include "model/project.h"

namespace gridifs {

/// Checks `project.states` against its functions: n × n entries, function indices in range, at
/// least one state, non-empty Q_I and Q_F with states in range, no `transitions` beside it, and a
/// path from Q_I to Q_F through a cycle (else the attractor is empty). Throws ModelError with a
/// JSON path (`states.matrix[1][0][2]`).
void checkStates(const Project& project);

/// The project's IFS as a matrix of function sets: its states; or, with `transitions`, one state
/// per function (word σ1σ2… allowed when σ_{s+1} may be followed by σ_s, every state initial and
/// final); or one state reading every function. Muted functions stay (compiling drops them).
IfsMatrix ifsMatrixOf(const Project& project);

/// Stores `m` as the project's states (single functions only, useful states only) and clears
/// `transitions`. Throws ModelError (empty path) when `m` has no attractor.
void setIfsMatrix(Project& project, const IfsMatrix& m);

/// IfsStates ⇄ IfsMatrix (letters only), without trimming.
IfsMatrix toIfsMatrix(const IfsStates& states);
IfsStates toIfsStates(const IfsMatrix& m);

/// What the chaos game does after a virtual function.
enum class StateStep : std::uint8_t {
  Plot,    // moves the point and plots it (its word starts in an initial state)
  Hidden,  // moves the point without plotting it
  Peek,    // plots its image of the point and leaves the chain where it was
};

/// The virtual functions of a project with states, over the functions `active` says may be picked.
struct StateExpansion {
  std::vector<std::size_t> function;  // index in Project::functions of each virtual function
  std::vector<std::size_t> from, to;  // its entry (from → to) in the trimmed matrix
  std::vector<StateStep> step;
  /// internal[v]: the entry lies inside one strongly connected part of the states (which then has
  /// a cycle): the entries a word's infinite tail can be made of.
  std::vector<char> internal;
  /// follows[v][w]: w may be applied right after v (w's entry ends where v's starts).
  std::vector<std::vector<char>> follows;
  std::size_t states = 0;  // states of the trimmed matrix
};

/// The most virtual functions a project's states may expand to.
inline constexpr std::size_t kMaxVirtualFunctions = 1024;

/// Expands the states over the functions with active[f] set. Throws ModelError (`states`) when
/// nothing of the attractor is left with those functions or the expansion is too large.
StateExpansion expandStates(const Project& project, const std::vector<char>& active);

/// expandStates over the functions a compiled form holds: present[k] is the project index of its
/// k-th function (each index at most once). `position` receives each virtual function's k.
StateExpansion expandStatesOver(const Project& project, const std::vector<std::size_t>& present,
                                std::vector<std::size_t>& position);

}  // namespace gridifs
