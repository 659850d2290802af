// GUI tier for screen sizes: the modeller on its own Xvfb screen of a laptop's, a desktop's and a
// HiDPI monitor's size (the content scale set the way desktops set it, through Xft.dpi), its
// panels on-screen, apart and large enough; and the window's geometry remembered between runs,
// corrected when the saved place is off every monitor, ignored when the file is garbage.
// Set GRIDIFS_GUI_SHOTS to a folder to keep the screenshots. The harness is gui/gui_harness.h.
#include <sys/prctl.h>
#include <sys/wait.h>

#include <array>
#include <memory>

#include "gui/gui_harness.h"

using namespace gridifs::gui_test;

namespace {

/// An Xvfb server of its own, on a free display number, for one test; DISPLAY points at it while
/// it lives (the modeller, xdotool and import started meanwhile all use it).
class XServer {
 public:
  XServer(int width, int height, int dpi = 96) {
    const char* old = std::getenv("DISPLAY");
    if (old) oldDisplay_ = old;
    for (int n = 70 + ::getpid() % 50; n < 400 && pid_ <= 0; n += 7) {
      const std::string name = ":" + std::to_string(n);
      if (fs::exists("/tmp/.X11-unix/X" + std::to_string(n)) || fs::exists("/tmp/.X" + std::to_string(n) + "-lock"))
        continue;
      const std::string screen = std::to_string(width) + "x" + std::to_string(height) + "x24";
      const pid_t pid = ::fork();
      if (pid == 0) {
        ::prctl(PR_SET_PDEATHSIG, SIGTERM);  // a crashed test leaves no server behind
        ::execlp("Xvfb", "Xvfb", name.c_str(), "-screen", "0", screen.c_str(), "-nolisten", "tcp", "-noreset",
                 static_cast<char*>(nullptr));
        ::_exit(127);
      }
      // Ready once a client can connect; a server that exits lost the race for the number.
      for (int attempt = 0; attempt < 100; ++attempt) {
        if (::waitpid(pid, nullptr, WNOHANG) == pid) break;
        if (run("xdpyinfo -display " + name + " >/dev/null 2>&1") == 0) {
          pid_ = pid;
          display_ = name;
          break;
        }
        std::this_thread::sleep_for(50ms);
      }
      if (pid_ <= 0) {
        ::kill(pid, SIGKILL);
        ::waitpid(pid, nullptr, 0);
      }
    }
    if (pid_ <= 0) return;
    ::setenv("DISPLAY", display_.c_str(), 1);
    // GLFW reads the content scale on X11 from the Xft.dpi resource, as desktops set it.
    if (dpi != 96)
      run("xprop -root -f RESOURCE_MANAGER 8s -set RESOURCE_MANAGER 'Xft.dpi:\t" + std::to_string(dpi) + "\n'");
  }
  ~XServer() {
    if (pid_ > 0) {
      ::kill(pid_, SIGTERM);
      ::waitpid(pid_, nullptr, 0);
    }
    if (oldDisplay_.empty())
      ::unsetenv("DISPLAY");
    else
      ::setenv("DISPLAY", oldDisplay_.c_str(), 1);
  }
  XServer(const XServer&) = delete;
  XServer& operator=(const XServer&) = delete;
  bool running() const { return pid_ > 0; }

 private:
  pid_t pid_ = -1;
  std::string display_, oldDisplay_;
};

bool haveXvfb() {
  return run("command -v Xvfb >/dev/null && command -v xdpyinfo >/dev/null && command -v xprop >/dev/null") == 0;
}

/// A probe rectangle in window coordinates (unlike rectOf, not moved by the window's position).
Rect local(const nlohmann::json& probe, const std::string& name) {
  const auto& r = probe["rects"][name];
  return {int(std::lround(r[0].get<double>())), int(std::lround(r[1].get<double>())),
          int(std::lround(r[2].get<double>())), int(std::lround(r[3].get<double>()))};
}

bool insideScreen(const Rect& inner, const Rect& outer, int slack = 1) {
  return inner.x >= outer.x - slack && inner.y >= outer.y - slack && inner.x + inner.w <= outer.x + outer.w + slack &&
         inner.y + inner.h <= outer.y + outer.h + slack;
}

int overlapArea(const Rect& a, const Rect& b) {
  const int w = std::min(a.x + a.w, b.x + b.w) - std::max(a.x, b.x);
  const int h = std::min(a.y + a.h, b.y + b.h) - std::max(a.y, b.y);
  return w > 0 && h > 0 ? w * h : 0;
}

std::string str(const Rect& r) {
  return std::to_string(r.x) + "," + std::to_string(r.y) + " " + std::to_string(r.w) + "x" + std::to_string(r.h);
}

const std::array<const char*, 8> kPanels = {"panel.functions", "panel.operations", "panel.parameters", "panel.grids",
                                            "panel.selection", "panel.preview",    "panel.ifs",        "panel.status"};

/// Waits until every panel, the first stack row and the views have been probed in a settled frame.
nlohmann::json settledProbe(const App& app) {
  return app.waitFor(
      [](const nlohmann::json& j) {
        if (j["frame"].get<int>() < 8) return false;
        for (const char* name : kPanels)
          if (!j["rects"].contains(name)) return false;
        return j["rects"].contains("ops.row.0") && j["rects"].contains("preview.image") &&
               j["rects"].contains("view.ifs");
      },
      30s);
}

/// The main panels are on the screen, inside the window, apart from each other and large enough
/// to use at `scale`; the operation stack shows its first rows, the preview keeps a useful size.
void expectUsableLayout(const nlohmann::json& probe, int screenW, int screenH, float scale) {
  const auto& win = probe["window"];
  const Rect window{win["x"].get<int>(), win["y"].get<int>(), win["width"].get<int>(), win["height"].get<int>()};
  EXPECT_TRUE(insideScreen(window, Rect{0, 0, screenW, screenH}, 0))
      << "window " << str(window) << " is off the screen";
  const Rect client{0, 0, window.w, window.h};
  for (std::size_t a = 0; a < kPanels.size(); ++a) {
    const Rect r = local(probe, kPanels[a]);
    EXPECT_TRUE(insideScreen(r, client)) << kPanels[a] << " " << str(r) << " is outside the window " << str(client);
    const bool status = std::string(kPanels[a]) == "panel.status";
    EXPECT_GE(r.w, int(180 * scale)) << kPanels[a] << " is too narrow: " << str(r);
    EXPECT_GE(r.h, int((status ? 18 : 120) * scale)) << kPanels[a] << " is too short: " << str(r);
    for (std::size_t b = a + 1; b < kPanels.size(); ++b) {
      // Neighbouring panels share an edge; a row or column of pixels is not an overlap.
      const Rect o = local(probe, kPanels[b]);
      EXPECT_LE(overlapArea(r, o), std::max(r.w, r.h) + 2)
          << kPanels[a] << " " << str(r) << " overlaps " << kPanels[b] << " " << str(o);
    }
  }
  const Rect status = local(probe, "panel.status");
  EXPECT_EQ(status.y + status.h, window.h) << "the status line is not at the bottom";

  // The operation stack: its list is inside the panel, holds three rows or more, and its first
  // row is in sight (not scrolled or clipped away).
  const Rect ops = local(probe, "panel.operations"), stack = local(probe, "ops.stack"), row = local(probe, "ops.row.0");
  EXPECT_TRUE(insideScreen(stack, ops)) << "the stack " << str(stack) << " is outside its panel " << str(ops);
  // (A selectable row reaches half an item spacing past the list's sides.)
  EXPECT_TRUE(row.y >= stack.y && row.y + row.h <= stack.y + stack.h && row.x >= stack.x && row.x < stack.x + stack.w)
      << "the first operation " << str(row) << " is not in the stack list " << str(stack);
  EXPECT_GE(stack.h, 3 * row.h) << "the stack list shows fewer than three rows";
  EXPECT_TRUE(insideScreen(local(probe, "functions.row.0"), local(probe, "panel.functions")));

  const Rect preview = local(probe, "preview.image");
  EXPECT_TRUE(insideScreen(preview, local(probe, "panel.preview")));
  EXPECT_GE(preview.w, int(320 * scale)) << "preview " << str(preview);
  EXPECT_GE(preview.h, int(200 * scale)) << "preview " << str(preview);
  const Rect ifs = local(probe, "view.ifs");
  EXPECT_TRUE(insideScreen(ifs, local(probe, "panel.ifs")));
  EXPECT_GE(ifs.w, int(240 * scale)) << "IFS view " << str(ifs);
  EXPECT_GE(ifs.h, int(140 * scale)) << "IFS view " << str(ifs);
  for (const char* view : {"view.Top", "view.Side", "view.Front", "view.User"}) {
    const Rect v = local(probe, view);
    EXPECT_TRUE(insideScreen(v, local(probe, "panel.grids"))) << view;
    EXPECT_GE(v.w, int(150 * scale)) << view << " " << str(v);
    EXPECT_GE(v.h, int(120 * scale)) << view << " " << str(v);
  }
}

/// The whole screen as a PNG (kept under $GRIDIFS_GUI_SHOTS when set); checks its size.
void screenshot(const TempFolder& home, const std::string& name, int screenW, int screenH) {
  const fs::path file = home.path / (name + ".png");
  ASSERT_EQ(run("import -window root '" + file.string() + "'"), 0);
  OIIO::ImageBuf image(file.string());
  ASSERT_TRUE(image.init_spec(file.string(), 0, 0)) << image.geterror();
  EXPECT_EQ(image.spec().width, screenW);
  EXPECT_EQ(image.spec().height, screenH);
  if (const char* keep = std::getenv("GRIDIFS_GUI_SHOTS"); keep && *keep) {
    std::error_code ec;
    fs::create_directories(keep, ec);
    fs::copy_file(file, fs::path(keep) / file.filename(), fs::copy_options::overwrite_existing, ec);
  }
}

/// First start on a screen of `width`×`height` at `dpi`: the window fills what the monitor
/// allows (at most 1600×1000 at scale 1), the UI scale follows the monitor, the layout is usable.
void checkScreen(int width, int height, int dpi, int expectW, int expectH) {
  if (!haveXvfb()) GTEST_SKIP() << "Xvfb, xdpyinfo or xprop missing";
  XServer server(width, height, dpi);
  ASSERT_TRUE(server.running()) << "no Xvfb server could start";
  TempFolder home;
  const fs::path project = exampleCopy(home, "default.gridifs", 300'000);
  App app(home, {project.string()});
  const nlohmann::json probe = settledProbe(app);
  ASSERT_FALSE(probe.is_null()) << "the modeller drew no frame";
  const float scale = float(dpi) / 96.0f;
  EXPECT_FLOAT_EQ(probe["ui_scale"].get<float>(), scale) << "the UI scale does not follow the monitor";
  EXPECT_NEAR(probe["font_size"].get<double>(), 15.0 * scale, 0.5);
  EXPECT_EQ(probe["window"]["width"].get<int>(), expectW);
  EXPECT_EQ(probe["window"]["height"].get<int>(), expectH);
  expectUsableLayout(probe, width, height, scale);
  screenshot(home, "screen_" + std::to_string(width) + "x" + std::to_string(height) + (dpi != 96 ? "_scale2" : ""),
             width, height);
}

fs::path geometryFile(const TempFolder& home) { return home.path / "config" / "gridifs" / "window.json"; }

void writeGeometry(const TempFolder& home, const std::string& text) {
  fs::create_directories(geometryFile(home).parent_path());
  std::ofstream(geometryFile(home)) << text;
}

Rect windowOf(const nlohmann::json& probe) {
  const auto& w = probe["window"];
  return {w["x"].get<int>(), w["y"].get<int>(), w["width"].get<int>(), w["height"].get<int>()};
}

/// The modeller on `home`, its earlier probe file removed so that only this run's frames count.
std::unique_ptr<App> start(const TempFolder& home, const std::vector<std::string>& args) {
  std::error_code ec;
  fs::remove(home.path / "probe.json", ec);
  return std::make_unique<App>(home, args);
}

nlohmann::json firstFrame(const App& app) {
  return app.waitFor([](const nlohmann::json& j) { return j["frame"].get<int>() >= 3; }, 20s);
}

}  // namespace

TEST(ScreenSizesGui, LaptopScreen1280x720) { checkScreen(1280, 720, 96, 1280, 720); }

TEST(ScreenSizesGui, DesktopScreen1600x1000) { checkScreen(1600, 1000, 96, 1600, 1000); }

TEST(ScreenSizesGui, HiDpiScreen2560x1440AtScale2) { checkScreen(2560, 1440, 192, 2560, 1440); }

TEST(ScreenSizesGui, FirstWindowIsCappedAndCentredOnALargeScreen) {
  if (!haveXvfb()) GTEST_SKIP() << "Xvfb, xdpyinfo or xprop missing";
  XServer server(2560, 1440);
  ASSERT_TRUE(server.running());
  TempFolder home;
  App app(home, {exampleCopy(home, "default.gridifs", 200'000).string()});
  const nlohmann::json probe = firstFrame(app);
  ASSERT_FALSE(probe.is_null());
  EXPECT_EQ(windowOf(probe), (Rect{480, 220, 1600, 1000})) << str(windowOf(probe));
}

// Where the artist leaves the window is where it opens next time.
TEST(ScreenSizesGui, WindowGeometryIsRemembered) {
  if (!haveXvfb()) GTEST_SKIP() << "Xvfb, xdpyinfo or xprop missing";
  XServer server(1600, 1000);
  ASSERT_TRUE(server.running());
  TempFolder home;
  const std::string project = exampleCopy(home, "default.gridifs", 200'000).string();
  writeGeometry(home, R"({"x": 100, "y": 80, "width": 1000, "height": 700, "maximized": false})");
  {
    auto app = start(home, {project});
    nlohmann::json probe = firstFrame(*app);
    ASSERT_FALSE(probe.is_null());
    EXPECT_EQ(windowOf(probe), (Rect{100, 80, 1000, 700})) << str(windowOf(probe));
    // The artist moves and resizes the window (no window manager here: xdotool does it), quits.
    xdotool("search --name GridIFS windowmove %@ 230 140 windowsize %@ 1200 760");
    probe = app->waitFor([](const nlohmann::json& j) { return windowOf(j) == Rect{230, 140, 1200, 760}; }, 10s);
    EXPECT_EQ(windowOf(probe), (Rect{230, 140, 1200, 760})) << str(windowOf(probe));
    std::this_thread::sleep_for(300ms);                        // a few frames at the new size
    expectUsableLayout(settledProbe(*app), 1600, 1000, 1.0f);  // the panels followed the new size
    pressKeys("ctrl+q");
    ASSERT_EQ(app->waitExit(), 0);
  }
  auto app = start(home, {project});
  const nlohmann::json probe = firstFrame(*app);
  EXPECT_EQ(windowOf(probe), (Rect{230, 140, 1200, 760})) << "not restored: " << str(windowOf(probe));
}

// A window saved on a monitor that is gone (far right and above), larger than this screen, opens
// on this screen, shrunk to it.
TEST(ScreenSizesGui, OffScreenWindowGeometryIsCorrected) {
  if (!haveXvfb()) GTEST_SKIP() << "Xvfb, xdpyinfo or xprop missing";
  XServer server(1600, 1000);
  ASSERT_TRUE(server.running());
  TempFolder home;
  writeGeometry(home, R"({"x": 5200, "y": -3000, "width": 2400, "height": 1500, "maximized": false})");
  auto app = start(home, {exampleCopy(home, "default.gridifs", 200'000).string()});
  const nlohmann::json probe = firstFrame(*app);
  ASSERT_FALSE(probe.is_null());
  const Rect w = windowOf(probe);
  EXPECT_TRUE(insideScreen(w, Rect{0, 0, 1600, 1000}, 0)) << "reopened off-screen: " << str(w);
  EXPECT_EQ(w.w, 1600);
  EXPECT_EQ(w.h, 1000);
  expectUsableLayout(settledProbe(*app), 1600, 1000, 1.0f);
}

// Garbage, hostile numbers and a wrong type: the first-start window, no crash.
TEST(ScreenSizesGui, BadWindowGeometryFileIsIgnored) {
  if (!haveXvfb()) GTEST_SKIP() << "Xvfb, xdpyinfo or xprop missing";
  XServer server(1600, 1000);
  ASSERT_TRUE(server.running());
  TempFolder home;
  for (const char* text :
       {"{\"x\": 1e308, \"y\": 0, \"width\": -5, \"height\": 99999999999}", "not json at all \x01\xff",
        "{\"x\": \"left\", \"y\": 0, \"width\": 800, \"height\": 600}"}) {
    writeGeometry(home, text);
    auto app = start(home, {});
    const nlohmann::json probe = firstFrame(*app);
    ASSERT_FALSE(probe.is_null()) << "no window for " << text;
    EXPECT_EQ(windowOf(probe), (Rect{0, 0, 1600, 1000})) << text;
  }
}

// --size still wins over the remembered size.
TEST(ScreenSizesGui, SizeOptionOverridesTheRememberedSize) {
  if (!haveXvfb()) GTEST_SKIP() << "Xvfb, xdpyinfo or xprop missing";
  XServer server(1600, 1000);
  ASSERT_TRUE(server.running());
  TempFolder home;
  writeGeometry(home, R"({"x": 100, "y": 80, "width": 1000, "height": 700, "maximized": false})");
  App app(home, {"--size", "1280x720"});
  const nlohmann::json probe = firstFrame(app);
  const Rect w = windowOf(probe);
  EXPECT_EQ(w, (Rect{100, 80, 1280, 720})) << "the size is the option's, the place the remembered one: " << str(w);
}
