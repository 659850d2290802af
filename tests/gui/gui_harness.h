#pragma once
// The GUI tier's harness, shared by every GUI test file: the real modeller as a child process in
// a fresh home (HOME and every XDG folder inside a temporary folder, so no state survives from an
// earlier run or from the machine's user), its --probe file (widget rectangles and state, written
// every frame), real input through xdotool and pixels from the X server through ImageMagick.
//
// Rectangles are read only once they are stable: a popup or an auto-sized window is placed in
// its second frame, so a rectangle taken from its first frame can point beside the widget.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <OpenImageIO/imagebuf.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "io/project_io.h"

namespace gridifs::gui_test {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

inline bool haveDisplay() {
  const char* d = std::getenv("DISPLAY");
  return d && *d;
}

inline int run(const std::string& command) {
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// A fresh folder per test; the modeller started from it sees it as its home and XDG folders.
struct TempFolder {
  fs::path path;
  TempFolder() {
    path = fs::temp_directory_path() / ("gridifs-gui-" + std::to_string(::getpid()) + "-" +
                                        std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
    fs::create_directories(path);
  }
  ~TempFolder() {
    std::error_code ec;
    // A test may leave a folder read-only (for root: immutable) when it fails half-way.
    run("chattr -R -i '" + path.string() + "' 2>/dev/null; chmod -R u+w '" + path.string() + "' 2>/dev/null");
    fs::remove_all(path, ec);
  }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;
};

struct Rect {
  int x = 0, y = 0, w = 0, h = 0;
  bool operator==(const Rect&) const = default;
};

/// A widget's rectangle in screen coordinates (the window sits at the probe's x, y).
inline Rect rectOf(const nlohmann::json& probe, const std::string& name) {
  const auto& r = probe["rects"][name];
  const int wx = probe["window"]["x"], wy = probe["window"]["y"];
  return {wx + int(r[0].get<double>()), wy + int(r[1].get<double>()), int(r[2].get<double>()), int(r[3].get<double>())};
}

/// The modeller as a child process with its --probe file.
class App {
 public:
  App(const TempFolder& home, const std::vector<std::string>& args) : probe_(home.path / "probe.json") {
    pid_ = ::fork();
    if (pid_ == 0) {
      const fs::path h = home.path / "home";
      ::setenv("HOME", h.c_str(), 1);
      ::setenv("XDG_CONFIG_HOME", (home.path / "config").c_str(), 1);
      ::setenv("XDG_STATE_HOME", (home.path / "state").c_str(), 1);
      ::setenv("XDG_DATA_HOME", (h / ".local/share").c_str(), 1);
      ::setenv("XDG_CACHE_HOME", (h / ".cache").c_str(), 1);
      // Leak-checking runs (scripts/sanitize) preload the GL driver into the modeller only: Mesa's
      // GLX unloads it at exit, before LeakSanitizer looks, and blocks the driver still holds from
      // its own globals would then read as lost. The test's own tools (xdotool, import) stay as
      // they are.
      if (const char* preload = std::getenv("GRIDIFS_TEST_APP_PRELOAD"); preload && *preload)
        ::setenv("LD_PRELOAD", preload, 1);
      std::vector<std::string> all{GRIDIFS_EXE};
      all.insert(all.end(), args.begin(), args.end());
      all.push_back("--probe");
      all.push_back(probe_.string());
      std::vector<char*> argv;
      for (auto& a : all) argv.push_back(a.data());
      argv.push_back(nullptr);
      ::execv(GRIDIFS_EXE, argv.data());
      ::_exit(127);
    }
  }
  ~App() {
    if (pid_ > 0 && !exited_) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
  }
  App(const App&) = delete;
  App& operator=(const App&) = delete;

  pid_t pid() const { return pid_; }

  /// The latest probe, once the window has drawn a frame (null if none came within 10 s).
  nlohmann::json probe() const {
    for (int attempt = 0; attempt < 200; ++attempt) {
      std::ifstream in(probe_);
      if (in) {
        try {
          return nlohmann::json::parse(in);
        } catch (const std::exception&) {
        }
      }
      std::this_thread::sleep_for(50ms);
    }
    return {};
  }

  /// Waits until `pred(probe)` holds (or the timeout passes); returns the last probe.
  template <class Pred>
  nlohmann::json waitFor(Pred pred, std::chrono::seconds timeout = 30s) const {
    const auto end = std::chrono::steady_clock::now() + timeout;
    nlohmann::json j;
    while (std::chrono::steady_clock::now() < end) {
      j = probe();
      if (!j.is_null() && pred(j)) return j;
      std::this_thread::sleep_for(100ms);
    }
    return j;
  }

  /// Waits for the preview of the current project to finish and reach the screen.
  nlohmann::json waitForPreview(std::uint64_t afterRestarts = 0, std::chrono::seconds timeout = 90s) const {
    return waitFor(
        [&](const nlohmann::json& j) {
          const auto& p = j["preview"];
          return p["done"].get<bool>() && p["restarts"].get<std::uint64_t>() > afterRestarts &&
                 p["image_generation"] == p["generation"] && !j["modal"].get<bool>();
        },
        timeout);
  }

  /// Waits until widget `name` has the same rectangle in probes of at least two later frames, so
  /// that a popup's or a new window's placement has settled; returns that rectangle, or nullopt.
  std::optional<Rect> waitForStableRect(const std::string& name, std::chrono::seconds timeout = 15s) const {
    const auto end = std::chrono::steady_clock::now() + timeout;
    Rect last;
    std::int64_t lastFrame = -1;
    int agreeing = -1;  // probes of later frames that agree with the first sighting
    while (std::chrono::steady_clock::now() < end) {
      const nlohmann::json j = probe();
      if (!j.is_null() && j["rects"].contains(name)) {
        const Rect r = rectOf(j, name);
        const std::int64_t frame = j["frame"].get<std::int64_t>();
        if (agreeing < 0 || !(r == last))
          agreeing = 0;
        else if (frame != lastFrame)
          ++agreeing;
        last = r;
        lastFrame = frame;
        if (agreeing >= 2) return r;
      } else {
        agreeing = -1;
      }
      std::this_thread::sleep_for(60ms);
    }
    return std::nullopt;
  }

  std::optional<int> waitExit(std::chrono::seconds timeout = 20s) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < end) {
      int status = 0;
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        exited_ = true;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      }
      std::this_thread::sleep_for(100ms);
    }
    return std::nullopt;
  }

 private:
  fs::path probe_;
  pid_t pid_ = -1;
  bool exited_ = false;
};

inline void xdotool(const std::string& args) { ASSERT_EQ(run("xdotool " + args), 0) << args; }

inline void focusWindow() {
  run("xdotool search --name GridIFS windowfocus >/dev/null 2>&1");
  std::this_thread::sleep_for(200ms);
}

/// Holds keys for a moment, as a person does (ImGui 1.86 has no input queue: a zero-length tap
/// can fall between two frames).
inline void pressKeys(const std::string& combo) {
  focusWindow();
  xdotool("keydown " + combo + " sleep 0.15 keyup " + combo);
  std::this_thread::sleep_for(400ms);
}

inline void clickAt(int x, int y) {
  xdotool("mousemove " + std::to_string(x) + " " + std::to_string(y) + " sleep 0.1 click 1");
  std::this_thread::sleep_for(400ms);
}

inline void clickRect(const Rect& r) { clickAt(r.x + r.w / 2, r.y + r.h / 2); }

/// Opens the modeller's File menu (`probe` gives the window) and clicks `item`.
inline void clickFileMenu(const App& app, const nlohmann::json& probe, const std::string& item) {
  focusWindow();
  clickAt(probe["window"]["x"].get<int>() + 18, probe["window"]["y"].get<int>() + 9);  // File
  const std::optional<Rect> rect = app.waitForStableRect(item);
  ASSERT_TRUE(rect) << "the File menu did not open";
  clickRect(*rect);
}

/// Waits for the preview, then opens File › Render animation… and returns the probe.
inline nlohmann::json openRenderAnimation(const App& app) {
  nlohmann::json probe = app.waitForPreview();
  clickFileMenu(app, probe, "menu.render_animation");
  return probe;
}

/// Presses at (x0, y0), moves to (x1, y1) in `steps` steps, releases.
inline void dragFrom(int x0, int y0, int x1, int y1, int steps = 12) {
  std::string cmd = "mousemove " + std::to_string(x0) + " " + std::to_string(y0) + " sleep 0.15 mousedown 1 sleep 0.15";
  for (int s = 1; s <= steps; ++s)
    cmd += " mousemove " + std::to_string(x0 + (x1 - x0) * s / steps) + " " +
           std::to_string(y0 + (y1 - y0) * s / steps) + " sleep 0.05";
  cmd += " sleep 0.2 mouseup 1";
  xdotool(cmd);
  std::this_thread::sleep_for(400ms);
}

/// The screen as the X server shows it (ImageMagick's import), cropped to `r`, RGB floats.
/// A file's bytes (the tests compare saved projects byte for byte).
inline std::string fileText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// Ctrl+S, then waits until the modeller reports the project saved.
inline void saveAndWait(App& app) {
  pressKeys("ctrl+s");
  app.waitFor([](const nlohmann::json& j) { return !j["dirty"].get<bool>(); });
}

/// With GRIDIFS_GUI_SHOTS set to a folder, the screen as `name` in it, for a person to look at (the
/// tests do not read it); nothing otherwise.
inline void keepShot(const TempFolder& home, const std::string& name) {
  if (const char* keep = std::getenv("GRIDIFS_GUI_SHOTS")) {
    run("import -window root '" + (home.path / name).string() + "'");
    fs::copy_file(home.path / name, fs::path(keep) / name, fs::copy_options::overwrite_existing);
  }
}

inline std::vector<float> grabScreen(const TempFolder& home, const Rect& r) {
  const fs::path file = home.path / "grab.png";
  EXPECT_EQ(run("import -window root '" + file.string() + "'"), 0);
  OIIO::ImageBuf buf(file.string());
  std::vector<float> pixels(std::size_t(r.w) * r.h * 3);
  buf.get_pixels(OIIO::ROI(r.x, r.x + r.w, r.y, r.y + r.h, 0, 1, 0, 3), OIIO::TypeDesc::FLOAT, pixels.data());
  return pixels;
}

inline double meanAbsDifference(const std::vector<float>& a, const std::vector<float>& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += std::abs(double(a[i]) - double(b[i]));
  return a.empty() ? 0.0 : sum / double(a.size()) * 255.0;
}

/// Grabs `r` until two grabs in a row agree (or `tries` run out): a picture that has settled, not
/// one caught between a frame's probe and its buffer swap.
inline std::vector<float> grabSettled(const TempFolder& home, const Rect& r, int tries = 8) {
  std::vector<float> last = grabScreen(home, r);
  for (int i = 1; i < tries; ++i) {
    std::this_thread::sleep_for(250ms);
    std::vector<float> next = grabScreen(home, r);
    const bool same = meanAbsDifference(last, next) < 0.05;
    last = std::move(next);
    if (same) break;
  }
  return last;
}

/// Where two grabs of `r` differ: the count of changed pixels and their bounding box in screen
/// coordinates, so a failing comparison says what changed.
inline std::string describeDifference(const std::vector<float>& a, const std::vector<float>& b, const Rect& r) {
  int x0 = r.w, y0 = r.h, x1 = -1, y1 = -1;
  std::size_t changed = 0;
  for (int y = 0; y < r.h; ++y)
    for (int x = 0; x < r.w; ++x) {
      const std::size_t i = (std::size_t(y) * r.w + x) * 3;
      if (i + 2 >= a.size() || i + 2 >= b.size()) continue;
      const float d = std::abs(a[i] - b[i]) + std::abs(a[i + 1] - b[i + 1]) + std::abs(a[i + 2] - b[i + 2]);
      if (d < 0.1f) continue;
      ++changed;
      x0 = std::min(x0, x);
      y0 = std::min(y0, y);
      x1 = std::max(x1, x);
      y1 = std::max(y1, y);
    }
  if (changed == 0) return "no pixel differs by more than 0.1";
  return std::to_string(changed) + " of " + std::to_string(std::size_t(r.w) * r.h) + " pixels differ, within x " +
         std::to_string(r.x + x0) + ".." + std::to_string(r.x + x1) + ", y " + std::to_string(r.y + y0) + ".." +
         std::to_string(r.y + y1);
}

/// Fraction of pixels brighter than a dark background.
inline double litFraction(const std::vector<float>& px) {
  std::size_t lit = 0;
  for (std::size_t i = 0; i < px.size(); i += 3)
    if (px[i] + px[i + 1] + px[i + 2] > 0.3f) ++lit;
  return px.empty() ? 0.0 : double(lit) / double(px.size() / 3);
}

/// Reads the rendered frame `file` of `width` × `height` into `px` (RGB floats) and checks that it
/// is not empty (more than 1% of its pixels lit). Its failure to read the file is fatal: callers
/// wrap it in ASSERT_NO_FATAL_FAILURE.
inline void readLitFrame(const fs::path& file, int width, int height, std::vector<float>& px) {
  OIIO::ImageBuf image(file.string());
  ASSERT_TRUE(image.init_spec(file.string(), 0, 0)) << image.geterror();
  EXPECT_EQ(image.spec().width, width);
  EXPECT_EQ(image.spec().height, height);
  px.assign(std::size_t(width) * height * 3, 0.0f);
  image.get_pixels(OIIO::ROI(0, width, 0, height, 0, 1, 0, 3), OIIO::TypeDesc::FLOAT, px.data());
  EXPECT_GT(litFraction(px), 0.01) << file.filename().string() << " is empty";
}

/// A copy of an example with a small sample budget, so previews finish quickly.
inline fs::path exampleCopy(const TempFolder& home, const std::string& name, std::int64_t samples = 1'000'000) {
  Project p = loadProject(fs::path(GRIDIFS_ASSETS) / name);
  p.render.samples = samples;
  const fs::path file = home.path / name;
  saveProject(p, file);
  return file;
}

}  // namespace gridifs::gui_test
