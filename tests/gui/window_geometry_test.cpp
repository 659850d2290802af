// The window-placement rules without a display: the first window's size from a work area, a
// remembered window fitted to the monitors present (several of them, which Xvfb cannot show), and
// the settings file's round trip and its refusal of anything that is not a plausible geometry.
#include "ui/shell/window_geometry.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

using gridifs::ui::FrameInsets;
using gridifs::ui::ScreenRect;
using gridifs::ui::WindowGeometry;
namespace fs = std::filesystem;

namespace {

bool inside(const ScreenRect& r, const ScreenRect& area) {
  return r.x >= area.x && r.y >= area.y && r.x + r.width <= area.x + area.width &&
         r.y + r.height <= area.y + area.height;
}

struct TempFile {
  fs::path path = fs::temp_directory_path() /
                  ("gridifs-window-" + std::to_string(::getpid()) + "-" +
                   std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()) + ".json");
  ~TempFile() {
    std::error_code ec;
    fs::remove(path, ec);
  }
};

}  // namespace

TEST(WindowGeometry, FirstWindowFitsTheWorkAreaAndIsCapped) {
  using gridifs::ui::firstWindowRect;
  EXPECT_EQ(firstWindowRect({0, 0, 1280, 720}), (ScreenRect{0, 0, 1280, 720}));
  // A laptop panel with a top bar of 32 px: the window stays below it.
  EXPECT_EQ(firstWindowRect({0, 32, 1366, 736}), (ScreenRect{0, 32, 1366, 736}));
  EXPECT_EQ(firstWindowRect({0, 0, 3840, 2160}), (ScreenRect{1120, 580, 1600, 1000}));
  // At scale 2 the cap doubles (it holds what 1600×1000 holds at scale 1), still within the area.
  EXPECT_EQ(firstWindowRect({0, 0, 3840, 2160}, {}, 2.0f), (ScreenRect{320, 80, 3200, 2000}));
  EXPECT_EQ(firstWindowRect({0, 0, 2560, 1440}, {}, 2.0f), (ScreenRect{0, 0, 2560, 1440}));
  // Decorations count against the work area.
  const ScreenRect framed = firstWindowRect({0, 0, 1280, 720}, FrameInsets{2, 30, 2, 2});
  EXPECT_EQ(framed, (ScreenRect{2, 30, 1276, 688}));
}

TEST(WindowGeometry, ARememberedWindowLandsOnAMonitorPresentNow) {
  using gridifs::ui::fitToWorkAreas;
  const std::vector<ScreenRect> monitors{{0, 0, 1920, 1050}, {1920, 0, 2560, 1440}};
  // Fully on the second monitor: unchanged.
  EXPECT_EQ(fitToWorkAreas({2500, 100, 1200, 800}, monitors), (ScreenRect{2500, 100, 1200, 800}));
  // Mostly on the second monitor, hanging off its bottom: pulled up inside it.
  const ScreenRect hanging = fitToWorkAreas({2000, 1000, 1200, 800}, monitors);
  EXPECT_TRUE(inside(hanging, monitors[1]));
  EXPECT_EQ(hanging, (ScreenRect{2000, 640, 1200, 800}));
  // On a monitor that is gone: onto the primary (first) one, shrunk to fit.
  const ScreenRect gone = fitToWorkAreas({6000, -2000, 2400, 1500}, monitors);
  EXPECT_TRUE(inside(gone, monitors[0]));
  EXPECT_EQ(gone.width, 1920);
  EXPECT_EQ(gone.height, 1050);
  // With decorations the whole frame stays inside.
  const FrameInsets frame{4, 28, 4, 4};
  const ScreenRect framed = fitToWorkAreas({0, 0, 800, 600}, monitors, frame);
  EXPECT_EQ(framed.x, 4);
  EXPECT_EQ(framed.y, 28);
  // No monitors known: left alone.
  EXPECT_EQ(fitToWorkAreas({5, 6, 700, 500}, {}), (ScreenRect{5, 6, 700, 500}));
}

TEST(WindowGeometry, SavedGeometryRoundTrips) {
  TempFile file;
  WindowGeometry g;
  g.normal = {-1200, 40, 1024, 700};  // a monitor left of the primary one has negative x
  g.maximized = true;
  g.layoutWidth = 1920;
  g.layoutHeight = 1050;
  ASSERT_TRUE(gridifs::ui::saveWindowGeometry(file.path, g));
  const auto loaded = gridifs::ui::loadWindowGeometry(file.path);
  ASSERT_TRUE(loaded);
  EXPECT_EQ(*loaded, g);
}

TEST(WindowGeometry, ABadSettingsFileIsIgnored) {
  TempFile file;
  EXPECT_FALSE(gridifs::ui::loadWindowGeometry(file.path)) << "a missing file";
  for (const std::string& text :
       {std::string("not json"), std::string("[1, 2]"), std::string("{}"),
        std::string("{\"x\": 0, \"y\": 0, \"width\": 0, \"height\": 600}"),
        std::string("{\"x\": 1e308, \"y\": 0, \"width\": 800, \"height\": 600}"),
        std::string("{\"x\": 0, \"y\": 0, \"width\": 99999999999, \"height\": 600}"),
        std::string("{\"x\": \"0\", \"y\": 0, \"width\": 800, \"height\": 600}"),
        std::string("{\"x\": 0.5, \"y\": 0, \"width\": 800, \"height\": 600}"),
        "{\"x\": 0, \"y\": 0, \"width\": 800, \"height\": 600, \"pad\": \"" + std::string(8000, 'x') + "\"}"}) {
    std::ofstream(file.path, std::ios::trunc) << text;
    EXPECT_FALSE(gridifs::ui::loadWindowGeometry(file.path)) << text.substr(0, 80);
  }
  // A folder where the file should be.
  fs::remove(file.path);
  fs::create_directories(file.path);
  EXPECT_FALSE(gridifs::ui::loadWindowGeometry(file.path));
  fs::remove(file.path);
  // Extra or wrongly typed optional fields do not spoil a good geometry.
  std::ofstream(file.path, std::ios::trunc)
      << R"({"x": 10, "y": 20, "width": 800, "height": 600, "maximized": "yes", "layout_width": -3, "zoom": 2})";
  const auto g = gridifs::ui::loadWindowGeometry(file.path);
  ASSERT_TRUE(g);
  EXPECT_EQ(g->normal, (ScreenRect{10, 20, 800, 600}));
  EXPECT_FALSE(g->maximized);
  EXPECT_EQ(g->layoutWidth, 0);
}
