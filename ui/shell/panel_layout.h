#pragma once
// Where the modeller's seven panels sit: a default tiling of the window (first start, View >
// Reset layout, a new UI scale) whose proportions adapt to the window's size, and the artist's
// own arrangement carried over proportionally when the window is resized.
#include <imgui.h>

#include <array>

namespace gridifs::ui {

enum class Panel { Functions, Operations, Parameters, Grids, Selection, Preview, Ifs };
inline constexpr int kPanelCount = 7;

struct PanelRects {
  std::array<ImVec2, kPanelCount> pos{}, size{};
  ImVec2& posOf(Panel p) { return pos[std::size_t(p)]; }
  ImVec2& sizeOf(Panel p) { return size[std::size_t(p)]; }
};

/// Three columns that tile `area` (below the menu bar, above the status line) without overlap.
/// `operationsMinHeight` is what the Operations panel needs to show its toolbar and the first
/// rows of the stack; the Functions and Selection panels give way to it (they scroll).
PanelRects defaultPanelLayout(ImVec2 origin, ImVec2 area, float operationsMinHeight);

/// `rects`, laid out for `fromArea` at `fromOrigin`, stretched to `toArea` at `toOrigin`.
PanelRects rescalePanelLayout(const PanelRects& rects, ImVec2 fromOrigin, ImVec2 fromArea, ImVec2 toOrigin,
                              ImVec2 toArea);

}  // namespace gridifs::ui
