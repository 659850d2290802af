#pragma once
// The transition matrix of a language-restricted (graph-directed) IFS: Thollot, Zair, Tosan &
// Vandorpe's IFS matrices (§3.2, §4) with flam3's "xaos" semantics (Draves & Reckase): after
// function i the next is j with probability ∝ weight_j · transitions[i][j]. An empty matrix
// means "no restriction" (every transition allowed with the usual weights). Muted functions and
// functions of weight 0 are never picked; the rows and columns of muted functions are ignored.
//
// Everything here is a pure function of its arguments: thread-safe.
#include <cstddef>
#include <functional>
#include <vector>

#include "model/project.h"

namespace gridifs {

/// The indices (in Project::functions) the chaos game can pick: unmuted with weight > 0.
std::vector<std::size_t> activeFunctionIndices(const Project& project);

/// The matrix restricted to `active` (indices into Project::functions), with each entry
/// multiplied by the weight of its column: row r gives the relative probabilities of the next
/// function after active[r]. Empty when the project has no matrix, or when every allowed row
/// is the same multiple of the weights (the chaos game is then unrestricted). Throws
/// ModelError (`transitions[i]`) when a row allows no active function.
std::vector<std::vector<double>> activeTransitionWeights(const Project& project,
                                                         const std::vector<std::size_t>& active);

/// Strongly connected components (Tarjan) of the graph on vertices 0..n-1 with an edge a → b
/// where `edge(a, b)`: each component's vertices ascending, the components in ascending order.
std::vector<std::vector<std::size_t>> stronglyConnectedComponents(
    std::size_t n, const std::function<bool(std::size_t, std::size_t)>& edge);

/// Strongly connected components of the transition graph over the active functions
/// (edge i → j when transitions[i][j] > 0; every edge when there is no matrix). One vector of
/// function indices per component; a single component means the graph is strongly connected.
std::vector<std::vector<std::size_t>> transitionComponents(const Project& project);

/// Function list edits that keep the matrix square: a new function may follow and be followed
/// by every function (weight 1); removing a function removes its row and column; swapping two
/// functions permutes rows and columns.
void insertFunction(Project& project, std::size_t index, Function function);
void eraseFunction(Project& project, std::size_t index);
void swapFunctions(Project& project, std::size_t a, std::size_t b);

}  // namespace gridifs
