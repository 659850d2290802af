#pragma once
// The "states" of a project: an IFS matrix with states (Thollot, Zair, Tosan & Vandorpe 1997,
// §3.2). n states; matrix[i][j] lists the functions (indices in Project::functions) of H̃_ij, the
// set of maps that may be read going from state i to state j; the attractor is
// ⋃_{i∈Q_I, j∈Q_F} Ã(H̃)_ij, the limit of the words T_σ1…T_σk that label a path from an initial to
// a final state (freeform/state_expansion.h compiles it for the renderers). Plain data.
#include <cstdint>
#include <vector>

namespace gridifs {

struct IfsStates {
  /// n × n entries, each a list of function indices (no duplicates, ascending after loading).
  std::vector<std::vector<std::vector<std::uint32_t>>> matrix;
  std::vector<std::uint32_t> initial;  // Q_I, state indices
  std::vector<std::uint32_t> final;    // Q_F, state indices
  bool operator==(const IfsStates&) const = default;
};

}  // namespace gridifs
