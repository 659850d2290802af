#include "ui/shell/panel_layout.h"

#include <algorithm>
#include <cmath>

namespace gridifs::ui {

PanelRects defaultPanelLayout(ImVec2 origin, ImVec2 area, float operationsMinHeight) {
  PanelRects l;
  // Left: what the IFS is made of (functions, their stacks, the node selection); center: the
  // grid views above the active operation's parameters (wide, for calculator expressions);
  // right: the rendered result above the IFS view (InterIFS's three groups of windows).
  const float left = std::round(area.x * 0.215f), center = std::round(area.x * 0.39f);
  const float right = area.x - left - center;
  const float h = area.y;
  // The operation stack is what an artist picks from most: it keeps its first rows on short
  // screens, taken from the Functions panel, while the Selection panel keeps a quarter.
  const float o = std::round(std::min(std::max(h * 0.25f, operationsMinHeight), h * 0.5f));
  const float f = std::round(std::max(std::min(h * 0.47f, h - o - h * 0.25f), h * 0.2f));
  const float g = std::round(h * 0.63f), p = std::round(h * 0.64f);  // the preview holds the timeline too
  auto set = [&](Panel i, float x, float y, float w, float ht) {
    l.posOf(i) = ImVec2(origin.x + x, origin.y + y);
    l.sizeOf(i) = ImVec2(w, ht);
  };
  set(Panel::Functions, 0, 0, left, f);
  set(Panel::Operations, 0, f, left, o);
  set(Panel::Selection, 0, f + o, left, h - f - o);
  set(Panel::Grids, left, 0, center, g);
  set(Panel::Parameters, left, g, center, h - g);
  set(Panel::Preview, left + center, 0, right, p);
  set(Panel::Ifs, left + center, p, right, h - p);
  return l;
}

PanelRects rescalePanelLayout(const PanelRects& rects, ImVec2 fromOrigin, ImVec2 fromArea, ImVec2 toOrigin,
                              ImVec2 toArea) {
  const float sx = fromArea.x > 0.0f ? toArea.x / fromArea.x : 1.0f;
  const float sy = fromArea.y > 0.0f ? toArea.y / fromArea.y : 1.0f;
  PanelRects out;
  for (int i = 0; i < kPanelCount; ++i) {
    // Edges are rounded, not sizes, so that panels that touched still touch.
    const float x0 = std::round(toOrigin.x + (rects.pos[i].x - fromOrigin.x) * sx);
    const float y0 = std::round(toOrigin.y + (rects.pos[i].y - fromOrigin.y) * sy);
    const float x1 = std::round(toOrigin.x + (rects.pos[i].x + rects.size[i].x - fromOrigin.x) * sx);
    const float y1 = std::round(toOrigin.y + (rects.pos[i].y + rects.size[i].y - fromOrigin.y) * sy);
    out.pos[i] = ImVec2(x0, y0);
    out.size[i] = ImVec2(x1 - x0, y1 - y0);
  }
  return out;
}

}  // namespace gridifs::ui
