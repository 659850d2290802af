#pragma once
// Index-box selections (Gröller & Wegenkittl 1994, §4.4).
#include <vector>

#include "base/types.h"

namespace gridifs {

enum class SelectionOp { Or, And, Xor, Minus };
const char* selectionOpName(SelectionOp op);
bool parseSelectionOp(const std::string& text, SelectionOp& out);

/// One inclusive index box combined into the running selection with `op`.
struct SelectionBox {
  std::array<int, 2> i{0, 0}, j{0, 0}, k{0, 0};
  SelectionOp op = SelectionOp::Or;
  bool operator==(const SelectionBox&) const = default;
};

/// An ordered list of boxes combined left to right starting from the empty set.
/// An empty list means "every node" (an op with no selection moves the whole grid).
using Selection = std::vector<SelectionBox>;

/// Per-node membership (1 = selected) for a grid of `resolution`, node index
/// i + ni*(j + nj*k). Box bounds are clamped to the grid so a selection survives a
/// resolution change; reversed bounds are swapped.
std::vector<unsigned char> selectionMask(const Selection& selection, const Index3& resolution);

}  // namespace gridifs
