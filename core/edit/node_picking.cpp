#include "edit/node_picking.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "edit/view_camera.h"

namespace gridifs {

std::vector<std::size_t> nodesInRect(const std::vector<Vec3>& nodes, const glm::dmat4& viewProjection, double width,
                                     double height, glm::dvec2 a, glm::dvec2 b) {
  const glm::dvec2 lo = glm::min(a, b), hi = glm::max(a, b);
  std::vector<std::size_t> out;
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    glm::dvec2 p;
    if (!projectToPixel(viewProjection, width, height, nodes[n], p)) continue;
    if (p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y) out.push_back(n);
  }
  return out;
}

std::optional<std::size_t> nearestNode(const std::vector<Vec3>& nodes, const glm::dmat4& viewProjection, double width,
                                       double height, glm::dvec2 pixel, double radius) {
  std::optional<std::size_t> best;
  double bestDistance = radius, bestDepth = 0.0;
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    const glm::dvec4 c = viewProjection * glm::dvec4(nodes[n], 1.0);
    if (c.w <= 1e-9) continue;
    const glm::dvec2 p{(c.x / c.w * 0.5 + 0.5) * width, (0.5 - c.y / c.w * 0.5) * height};
    const double d = glm::length(p - pixel), depth = c.z / c.w;
    // Nodes that overlap on screen (within half a pixel) are told apart by depth.
    if (d > radius) continue;
    if (!best || d < bestDistance - 0.5 || (std::abs(d - bestDistance) <= 0.5 && depth < bestDepth)) {
      best = n;
      bestDistance = d;
      bestDepth = depth;
    }
  }
  return best;
}

Selection boxesFromMask(const std::vector<unsigned char>& mask, const Index3& resolution) {
  const int ni = resolution[0], nj = resolution[1], nk = resolution[2];
  // Runs along i for each (j, k) ...
  struct Box {
    int i0, i1, j0, j1, k0, k1;
  };
  std::vector<Box> rows;
  for (int k = 0; k < nk; ++k)
    for (int j = 0; j < nj; ++j)
      for (int i = 0; i < ni;) {
        if (!mask[std::size_t(i) + std::size_t(ni) * (j + std::size_t(nj) * k)]) {
          ++i;
          continue;
        }
        int end = i;
        while (end + 1 < ni && mask[std::size_t(end + 1) + std::size_t(ni) * (j + std::size_t(nj) * k)]) ++end;
        rows.push_back({i, end, j, j, k, k});
        i = end + 1;
      }
  // ... merged over consecutive j with the same i range (same k) ...
  std::vector<Box> slabs;
  for (const Box& r : rows) {
    bool merged = false;
    for (Box& s : slabs)
      if (s.k0 == r.k0 && s.i0 == r.i0 && s.i1 == r.i1 && s.j1 + 1 == r.j0) {
        s.j1 = r.j1;
        merged = true;
        break;
      }
    if (!merged) slabs.push_back(r);
  }
  // ... and over consecutive k with the same i and j ranges.
  std::vector<Box> boxes;
  for (const Box& s : slabs) {
    bool merged = false;
    for (Box& b : boxes)
      if (b.i0 == s.i0 && b.i1 == s.i1 && b.j0 == s.j0 && b.j1 == s.j1 && b.k1 + 1 == s.k0) {
        b.k1 = s.k1;
        merged = true;
        break;
      }
    if (!merged) boxes.push_back(s);
  }
  Selection out;
  for (const Box& b : boxes) out.push_back({{b.i0, b.i1}, {b.j0, b.j1}, {b.k0, b.k1}, SelectionOp::Or});
  return out;
}

Selection emptySelection() {
  // Starting from the empty set, removing a box leaves nothing (and stays a valid file entry).
  return {SelectionBox{{0, 0}, {0, 0}, {0, 0}, SelectionOp::Minus}};
}

bool selectsNothing(const Selection& selection, const Index3& resolution) {
  if (selection.empty()) return false;
  const auto mask = selectionMask(selection, resolution);
  return std::none_of(mask.begin(), mask.end(), [](unsigned char m) { return m != 0; });
}

Selection applyPick(const Selection& current, const std::vector<std::size_t>& picked, const Index3& resolution,
                    PickMode mode) {
  const std::size_t count = std::size_t(resolution[0]) * resolution[1] * resolution[2];
  std::vector<unsigned char> pickedMask(count, 0);
  for (std::size_t n : picked)
    if (n < count) pickedMask[n] = 1;
  Selection pickedBoxes = boxesFromMask(pickedMask, resolution);

  // The current selection as a node set ("every node" is not a meaningful base to add to:
  // an op without selection moves everything, but a UI selection starts empty).
  const bool currentIsNone = current.empty() || selectsNothing(current, resolution);
  Selection result;
  switch (mode) {
    case PickMode::Replace:
      result = pickedBoxes.empty() ? emptySelection() : pickedBoxes;
      break;
    case PickMode::Add:
      if (currentIsNone) {
        result = pickedBoxes.empty() ? emptySelection() : pickedBoxes;
      } else {
        result = current;
        result.insert(result.end(), pickedBoxes.begin(), pickedBoxes.end());
      }
      break;
    case PickMode::Remove:
      if (currentIsNone) return current.empty() ? emptySelection() : current;
      result = current;
      for (SelectionBox b : pickedBoxes) {
        b.op = SelectionOp::Minus;
        result.push_back(b);
      }
      break;
  }
  if (int(result.size()) > limits::kMaxSelectionBoxes) {
    result = boxesFromMask(selectionMask(result, resolution), resolution);
    if (result.empty()) result = emptySelection();
  }
  // Still too many (a scattered pick on a huge grid): keep what fits, in order.
  if (int(result.size()) > limits::kMaxSelectionBoxes) result.resize(std::size_t(limits::kMaxSelectionBoxes));
  return result;
}

}  // namespace gridifs
