#include "model/selection.h"

#include <algorithm>

namespace gridifs {

const char* selectionOpName(SelectionOp op) {
  switch (op) {
    case SelectionOp::Or:
      return "or";
    case SelectionOp::And:
      return "and";
    case SelectionOp::Xor:
      return "xor";
    case SelectionOp::Minus:
      return "minus";
  }
  return "or";
}

bool parseSelectionOp(const std::string& text, SelectionOp& out) {
  if (text == "or")
    out = SelectionOp::Or;
  else if (text == "and")
    out = SelectionOp::And;
  else if (text == "xor")
    out = SelectionOp::Xor;
  else if (text == "minus")
    out = SelectionOp::Minus;
  else
    return false;
  return true;
}

std::vector<unsigned char> selectionMask(const Selection& selection, const Index3& resolution) {
  const int ni = resolution[0], nj = resolution[1], nk = resolution[2];
  const std::size_t count = std::size_t(ni) * nj * nk;
  if (selection.empty()) return std::vector<unsigned char>(count, 1);
  std::vector<unsigned char> mask(count, 0);
  auto clampRange = [](std::array<int, 2> r, int n) {
    if (r[0] > r[1]) std::swap(r[0], r[1]);
    return std::array<int, 2>{std::clamp(r[0], 0, n - 1), std::clamp(r[1], 0, n - 1)};
  };
  for (const SelectionBox& box : selection) {
    const auto bi = clampRange(box.i, ni), bj = clampRange(box.j, nj), bk = clampRange(box.k, nk);
    // A box entirely outside the grid selects nothing.
    const bool outside = std::max(box.i[0], box.i[1]) < 0 || std::min(box.i[0], box.i[1]) >= ni ||
                         std::max(box.j[0], box.j[1]) < 0 || std::min(box.j[0], box.j[1]) >= nj ||
                         std::max(box.k[0], box.k[1]) < 0 || std::min(box.k[0], box.k[1]) >= nk;
    for (int k = 0; k < nk; ++k)
      for (int j = 0; j < nj; ++j)
        for (int i = 0; i < ni; ++i) {
          const bool inBox =
              !outside && i >= bi[0] && i <= bi[1] && j >= bj[0] && j <= bj[1] && k >= bk[0] && k <= bk[1];
          unsigned char& m = mask[std::size_t(i) + std::size_t(ni) * (j + std::size_t(nj) * k)];
          switch (box.op) {
            case SelectionOp::Or:
              m = m | inBox;
              break;
            case SelectionOp::And:
              m = m & inBox;
              break;
            case SelectionOp::Xor:
              m = m ^ inBox;
              break;
            case SelectionOp::Minus:
              m = m & !inBox;
              break;
          }
        }
  }
  return mask;
}

}  // namespace gridifs
