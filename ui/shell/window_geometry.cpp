#include "ui/shell/window_geometry.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <nlohmann/json.hpp>

namespace gridifs::ui {
namespace fs = std::filesystem;

namespace {

constexpr int kMaxFirstWidth = 1600, kMaxFirstHeight = 1000;
constexpr int kMinSize = 320;          // below this no panel is usable; matches --size's minimum width
constexpr int kMaxCoordinate = 65536;  // X11 and Wayland coordinates are 16-bit; larger is corrupt

std::int64_t overlap(const ScreenRect& a, const ScreenRect& b) {
  const std::int64_t w =
      std::min<std::int64_t>(std::int64_t(a.x) + a.width, std::int64_t(b.x) + b.width) - std::max(a.x, b.x);
  const std::int64_t h =
      std::min<std::int64_t>(std::int64_t(a.y) + a.height, std::int64_t(b.y) + b.height) - std::max(a.y, b.y);
  return w > 0 && h > 0 ? w * h : 0;
}

}  // namespace

ScreenRect firstWindowRect(const ScreenRect& workArea, const FrameInsets& frame, float scale) {
  scale = std::clamp(scale, 1.0f, 4.0f);
  const int availW = std::max(1, workArea.width - frame.left - frame.right);
  const int availH = std::max(1, workArea.height - frame.top - frame.bottom);
  ScreenRect r;
  r.width = std::min(int(std::lround(float(kMaxFirstWidth) * scale)), availW);
  r.height = std::min(int(std::lround(float(kMaxFirstHeight) * scale)), availH);
  r.x = workArea.x + frame.left + (availW - r.width) / 2;
  r.y = workArea.y + frame.top + (availH - r.height) / 2;
  return r;
}

std::size_t workAreaFor(const ScreenRect& window, const std::vector<ScreenRect>& workAreas) {
  std::size_t best = 0;
  std::int64_t bestOverlap = 0;
  for (std::size_t a = 0; a < workAreas.size(); ++a)
    if (const std::int64_t o = overlap(window, workAreas[a]); o > bestOverlap) {
      bestOverlap = o;
      best = a;
    }
  return best;
}

ScreenRect fitToWorkAreas(const ScreenRect& wanted, const std::vector<ScreenRect>& workAreas,
                          const FrameInsets& frame) {
  if (workAreas.empty()) return wanted;
  const ScreenRect outer{wanted.x - frame.left, wanted.y - frame.top, wanted.width + frame.left + frame.right,
                         wanted.height + frame.top + frame.bottom};
  const ScreenRect& area = workAreas[workAreaFor(outer, workAreas)];
  const int availW = std::max(1, area.width - frame.left - frame.right);
  const int availH = std::max(1, area.height - frame.top - frame.bottom);
  ScreenRect r = wanted;
  r.width = std::clamp(wanted.width, std::min(kMinSize, availW), availW);
  r.height = std::clamp(wanted.height, std::min(kMinSize, availH), availH);
  const int minX = area.x + frame.left, minY = area.y + frame.top;
  r.x = std::clamp(wanted.x, minX, minX + availW - r.width);
  r.y = std::clamp(wanted.y, minY, minY + availH - r.height);
  return r;
}

std::optional<WindowGeometry> loadWindowGeometry(const fs::path& file) {
  std::error_code ec;
  // A settings file is a few hundred bytes; anything large is not ours.
  if (!fs::is_regular_file(file, ec) || fs::file_size(file, ec) > 4096 || ec) return std::nullopt;
  std::ifstream in(file);
  if (!in) return std::nullopt;
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (!j.is_object()) return std::nullopt;
  auto integer = [&](const char* key, int min, int max) -> std::optional<int> {
    const auto it = j.find(key);
    if (it == j.end() || !it->is_number_integer()) return std::nullopt;
    const std::int64_t v = it->get<std::int64_t>();
    if (v < min || v > max) return std::nullopt;
    return int(v);
  };
  const auto x = integer("x", -kMaxCoordinate, kMaxCoordinate), y = integer("y", -kMaxCoordinate, kMaxCoordinate);
  const auto w = integer("width", 1, kMaxCoordinate), h = integer("height", 1, kMaxCoordinate);
  if (!x || !y || !w || !h) return std::nullopt;
  WindowGeometry g;
  g.normal = {*x, *y, *w, *h};
  if (const auto it = j.find("maximized"); it != j.end() && it->is_boolean()) g.maximized = it->get<bool>();
  const auto lw = integer("layout_width", 1, kMaxCoordinate), lh = integer("layout_height", 1, kMaxCoordinate);
  if (lw && lh) {
    g.layoutWidth = *lw;
    g.layoutHeight = *lh;
  }
  return g;
}

bool saveWindowGeometry(const fs::path& file, const WindowGeometry& g) {
  nlohmann::json j = {{"x", g.normal.x},
                      {"y", g.normal.y},
                      {"width", g.normal.width},
                      {"height", g.normal.height},
                      {"maximized", g.maximized},
                      {"layout_width", g.layoutWidth},
                      {"layout_height", g.layoutHeight}};
  std::error_code ec;
  fs::create_directories(file.parent_path(), ec);
  const fs::path tmp = file.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    if (!out) return false;
    out << j.dump(1) << "\n";
    if (!out.flush()) return false;
  }
  fs::rename(tmp, file, ec);
  if (!ec) return true;
  fs::remove(tmp, ec);
  return false;
}

}  // namespace gridifs::ui
