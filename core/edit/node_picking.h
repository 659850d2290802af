#pragma once
// Picking grid nodes on screen and turning picked node sets into index-box selections
// (Gröller & Wegenkittl 1994, §4.4: what the UI builds by clicking and box-dragging
// is stored in the same form). Headless and pure; thread-safe.
#include <cstddef>
#include <optional>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include "model/selection.h"

namespace gridifs {

/// Indices (into `nodes`) of the nodes whose projection lies in the pixel rectangle spanned
/// by corners a and b (any order, inclusive). Points behind the camera are never picked.
std::vector<std::size_t> nodesInRect(const std::vector<Vec3>& nodes, const glm::dmat4& viewProjection, double width,
                                     double height, glm::dvec2 a, glm::dvec2 b);

/// The node nearest to `pixel` on screen within `radius` pixels; among nodes at about the
/// same screen distance the one nearest the camera wins. Empty when none is that close.
std::optional<std::size_t> nearestNode(const std::vector<Vec3>& nodes, const glm::dmat4& viewProjection, double width,
                                       double height, glm::dvec2 pixel, double radius);

/// How a picked set changes the current selection.
enum class PickMode { Replace, Add, Remove };

/// The selection after picking `picked` node indices (i + Ni·(j + Nj·k)) with `mode`.
/// The result is compact: runs along i merged over j and k, appended as `or` boxes (Add) or
/// `minus` boxes (Remove); when that would exceed limits::kMaxSelectionBoxes the whole
/// selection is rebuilt from its node mask. Replace with nothing picked gives an empty
/// selection list — which means "every node" for an op, so callers treat it as "none".
Selection applyPick(const Selection& current, const std::vector<std::size_t>& picked, const Index3& resolution,
                    PickMode mode);

/// Compact `or` boxes covering exactly the nodes with mask[n] != 0 (empty for an empty mask).
Selection boxesFromMask(const std::vector<unsigned char>& mask, const Index3& resolution);

/// A selection that selects no node at all (one `minus` box): unlike the empty list,
/// which selects everything.
Selection emptySelection();
/// Whether `selection` selects no node of a grid of `resolution`.
bool selectsNothing(const Selection& selection, const Index3& resolution);

}  // namespace gridifs
