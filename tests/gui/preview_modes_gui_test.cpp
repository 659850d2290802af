// GUI tier for issues 5 and 6 in the modeller: the flame display mode (no chaos-game restart),
// the deterministic mesh preview F^n(A), and File > Export mesh… through the real window with
// xdotool, the file checked by loading it back with OpenMesh. Same conventions as
// modeller_gui_test.cpp (probe file for widget rectangles, pixels from the X server).
#include <OpenImageIO/imagebuf.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "mesh/mesh_io.h"
#include "io/project_io.h"

namespace fs = std::filesystem;
using namespace std::chrono_literals;

namespace {

bool haveDisplay() {
  const char* d = std::getenv("DISPLAY");
  return d && *d;
}

struct TempFolder {
  fs::path path;
  TempFolder() {
    path = fs::temp_directory_path() / ("gridifs-gui-modes-" + std::to_string(::getpid()) + "-" +
                                        std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
    fs::create_directories(path);
  }
  ~TempFolder() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

int run(const std::string& command) {
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

class App {
 public:
  App(const TempFolder& home, const std::vector<std::string>& args) : probe_(home.path / "probe.json") {
    pid_ = ::fork();
    if (pid_ == 0) {
      ::setenv("XDG_CONFIG_HOME", (home.path / "config").c_str(), 1);
      ::setenv("XDG_STATE_HOME", (home.path / "state").c_str(), 1);
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
    if (pid_ > 0) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
  }
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

 private:
  fs::path probe_;
  pid_t pid_ = -1;
};

struct Rect {
  int x = 0, y = 0, w = 0, h = 0;
};

Rect rectOf(const nlohmann::json& probe, const std::string& name) {
  const auto& r = probe["rects"][name];
  const int wx = probe["window"]["x"], wy = probe["window"]["y"];
  return {wx + int(r[0].get<double>()), wy + int(r[1].get<double>()), int(r[2].get<double>()), int(r[3].get<double>())};
}

void xdotool(const std::string& args) { ASSERT_EQ(run("xdotool " + args), 0) << args; }

void clickAt(int x, int y) {
  xdotool("mousemove " + std::to_string(x) + " " + std::to_string(y) + " sleep 0.1 click 1");
  std::this_thread::sleep_for(300ms);
}

void clickRect(const Rect& r) { clickAt(r.x + r.w / 2, r.y + r.h / 2); }

std::vector<float> grabScreen(const TempFolder& home, const Rect& r) {
  const fs::path file = home.path / "grab.png";
  EXPECT_EQ(run("import -window root '" + file.string() + "'"), 0);
  OIIO::ImageBuf buf(file.string());
  std::vector<float> pixels(std::size_t(r.w) * r.h * 3);
  buf.get_pixels(OIIO::ROI(r.x, r.x + r.w, r.y, r.y + r.h, 0, 1, 0, 3), OIIO::TypeDesc::FLOAT, pixels.data());
  return pixels;
}

double meanAbsDifference(const std::vector<float>& a, const std::vector<float>& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += std::abs(double(a[i]) - double(b[i]));
  return a.empty() ? 0.0 : sum / double(a.size()) * 255.0;
}

/// Fraction of pixels brighter than a dark background.
double litFraction(const std::vector<float>& px) {
  std::size_t lit = 0;
  for (std::size_t i = 0; i < px.size(); i += 3)
    if (px[i] + px[i + 1] + px[i + 2] > 0.3f) ++lit;
  return px.empty() ? 0.0 : double(lit) / double(px.size() / 3);
}

fs::path exampleCopy(const TempFolder& home, const std::string& name, std::int64_t samples) {
  gridifs::Project p = gridifs::loadProject(fs::path(GRIDIFS_ASSETS) / name);
  p.render.samples = samples;
  const fs::path file = home.path / name;
  gridifs::saveProject(p, file);
  return file;
}

bool previewDone(const nlohmann::json& j) {
  const auto& p = j["preview"];
  return p["done"].get<bool>() && p["restarts"].get<std::uint64_t>() > 0 && p["image_generation"] == p["generation"];
}

}  // namespace

// Issue 6 §6: the flame display is a second picture of the same chaos game: switching shows a
// different, non-empty image without restarting the renderer, and the choice is one undo step.
TEST(PreviewModesGui, FlameModeShowsADifferentPictureWithoutRestart) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "sierpinski_tetrahedron.gridifs", 1'000'000);
  App app(home, {project.string()});
  nlohmann::json probe = app.waitFor(previewDone, 90s);  // niced workers: slow on a busy machine
  ASSERT_TRUE(previewDone(probe));
  const Rect image = rectOf(probe, "preview.image");
  const auto zbuffer = grabScreen(home, image);
  const std::uint64_t restarts = probe["preview"]["restarts"];

  clickRect(rectOf(probe, "preview.mode.flame"));
  probe = app.waitFor(
      [](const nlohmann::json& j) {
        return j["preview_modes"]["mode"] == "flame" && j["preview_modes"]["flame_developed"].get<int>() >= 1 &&
               j["preview"]["done"].get<bool>();
      },
      90s);
  ASSERT_EQ(probe["preview_modes"]["mode"], "flame");
  std::this_thread::sleep_for(500ms);  // the last develop after the budget is reached
  probe = app.probe();
  EXPECT_EQ(probe["preview"]["restarts"].get<std::uint64_t>(), restarts) << "the mode switch restarted the chaos game";
  EXPECT_EQ(probe["undo"], "Flame display");
  EXPECT_EQ(probe["preview_modes"]["flame_error"], "");
  const auto flame = grabScreen(home, image);
  EXPECT_GT(litFraction(flame), 0.02) << "the flame picture looks empty";
  EXPECT_GT(meanAbsDifference(zbuffer, flame), 2.0) << "the flame picture is the z-buffer picture";

  // Tone mapping: one brightness drag is one undo step, re-develops the picture, no restart.
  clickRect(rectOf(probe, "flame.tone"));
  probe = app.waitFor([](const nlohmann::json& j) { return j["rects"].contains("flame.Brightness"); }, 10s);
  ASSERT_TRUE(probe["rects"].contains("flame.Brightness"));
  const Rect slider = rectOf(probe, "flame.Brightness");
  const int developed = probe["preview_modes"]["flame_developed"];
  const int y = slider.y + slider.h / 2, x0 = slider.x + slider.w / 2;
  std::string drag = "mousemove " + std::to_string(x0) + " " + std::to_string(y) + " sleep 0.15 mousedown 1 sleep 0.15";
  for (int k = 1; k <= 8; ++k)
    drag += " mousemove " + std::to_string(x0 + k * slider.w / 20) + " " + std::to_string(y) + " sleep 0.05";
  xdotool(drag + " sleep 0.2 mouseup 1");
  probe = app.waitFor([&](const nlohmann::json& j) {
    return j["undo"] == "Brightness" && j["preview_modes"]["flame_developed"].get<int>() > developed &&
           j["preview_modes"]["flame_busy"] == false;
  });
  EXPECT_EQ(probe["undo"], "Brightness");
  EXPECT_EQ(probe["preview"]["restarts"].get<std::uint64_t>(), restarts) << "tone mapping restarted the chaos game";
  EXPECT_GT(probe["preview_modes"]["flame_developed"].get<int>(), developed);
  xdotool("keydown Escape sleep 0.15 keyup Escape");  // close the popup (held: ImGui 1.86 has no input queue)
  std::this_thread::sleep_for(500ms);
  const auto brighter = grabScreen(home, image);
  EXPECT_GT(meanAbsDifference(flame, brighter), 1.0) << "the brightness drag did not change the picture";

  // Back to the z-buffer: the same picture as before, still without a restart.
  clickRect(rectOf(probe, "preview.mode.zbuffer"));
  probe = app.waitFor([](const nlohmann::json& j) { return j["preview_modes"]["mode"] == "zbuffer"; }, 10s);
  ASSERT_EQ(probe["preview_modes"]["mode"], "zbuffer");
  std::this_thread::sleep_for(400ms);
  EXPECT_LT(meanAbsDifference(zbuffer, grabScreen(home, image)), 0.5);
  EXPECT_EQ(app.probe()["preview"]["restarts"].get<std::uint64_t>(), restarts);
}

// Issue 5 §3: the deterministic preview draws F^n(A) as a lit mesh (many shades, not a flat fill).
TEST(PreviewModesGui, MeshModeDrawsTheDeterministicMesh) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "sierpinski_tetrahedron.gridifs", 200'000);
  App app(home, {project.string()});
  nlohmann::json probe = app.waitFor(previewDone, 90s);  // niced workers: slow on a busy machine
  ASSERT_TRUE(previewDone(probe));
  clickRect(rectOf(probe, "preview.mode.mesh"));
  probe = app.waitFor([](const nlohmann::json& j) {
    const auto& m = j["preview_modes"];
    return m["mode"] == "mesh" && m["mesh_faces"].get<std::uint64_t>() > 0 && !m["mesh_building"].get<bool>();
  });
  const auto& m = probe["preview_modes"];
  ASSERT_EQ(m["mesh_error"], "");
  ASSERT_GT(m["mesh_faces"].get<std::uint64_t>(), 0u);
  // 4 functions, the cube subdivided once (24 quads): 4^n × 24 faces.
  const int depth = m["mesh_depth"];
  EXPECT_EQ(m["mesh_faces"].get<std::uint64_t>(), std::uint64_t(std::pow(4.0, depth)) * 24u);
  std::this_thread::sleep_for(400ms);
  const auto px = grabScreen(home, rectOf(probe, "preview.image"));
  EXPECT_GT(litFraction(px), 0.02) << "no mesh in the preview";
  std::set<int> shades;  // lit faces: many distinct intensities
  for (std::size_t i = 0; i < px.size(); i += 3)
    if (px[i] + px[i + 1] + px[i + 2] > 0.3f) shades.insert(int((px[i] + px[i + 1] + px[i + 2]) * 40.0f));
  EXPECT_GT(shades.size(), 10u) << "the mesh is not shaded";
}

// Issue 5 §3: File > Export mesh… with real input: type the output path, export, and the PLY
// loads back through OpenMesh with the planned face count and vertex colors.
TEST(PreviewModesGui, ExportMeshThroughTheMenuWritesAPlyThatLoadsBack) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "sierpinski_tetrahedron.gridifs", 200'000);
  const fs::path out = home.path / "exported.ply";
  App app(home, {project.string()});
  nlohmann::json probe = app.waitFor(previewDone, 90s);  // niced workers: slow on a busy machine
  ASSERT_TRUE(previewDone(probe));
  // The File menu is the first entry of the main menu bar.
  const int wx = probe["window"]["x"], wy = probe["window"]["y"];
  clickAt(wx + 18, wy + 9);
  probe = app.waitFor([](const nlohmann::json& j) { return j["rects"].contains("menu.export_mesh"); }, 10s);
  ASSERT_TRUE(probe["rects"].contains("menu.export_mesh"));
  clickRect(rectOf(probe, "menu.export_mesh"));
  probe = app.waitFor([](const nlohmann::json& j) { return j["rects"].contains("export.output"); }, 10s);
  ASSERT_TRUE(probe["rects"].contains("export.output"));
  std::this_thread::sleep_for(500ms);  // the dialog sizes itself to its contents in its first frames
  clickRect(rectOf(app.probe(), "export.output"));
  run("xdotool search --name GridIFS windowfocus >/dev/null 2>&1");
  // Held for a moment: ImGui 1.86 has no input queue, a tap can fall between two frames.
  xdotool("keydown ctrl+a sleep 0.15 keyup ctrl+a");
  std::this_thread::sleep_for(200ms);
  xdotool("type --delay 15 '" + out.string() + "'");
  std::this_thread::sleep_for(300ms);
  clickRect(rectOf(app.probe(), "export.run"));
  probe = app.waitFor([](const nlohmann::json& j) {
    const std::string phase = j["export"]["phase"];
    return phase == "done" || phase == "failed";
  });
  ASSERT_EQ(probe["export"]["phase"], "done") << probe["export"]["message"];
  ASSERT_TRUE(fs::exists(out)) << probe["export"]["message"];
  gridifs::IfsMesh mesh;
  mesh.request_vertex_colors();
  OpenMesh::IO::Options options = OpenMesh::IO::Options::VertexColor;
  ASSERT_TRUE(OpenMesh::IO::read_mesh(mesh, out.string(), options));
  EXPECT_EQ(mesh.n_faces(), 4u * 4u * 4u * 6u);  // depth 3 of a 4-map IFS on the cube
  EXPECT_EQ(mesh.n_vertices(), 4u * 4u * 4u * 8u);
  EXPECT_TRUE(options.check(OpenMesh::IO::Options::VertexColor));
  std::set<std::tuple<float, float, float>> colors;  // the functions' structural colors
  for (auto vh : mesh.vertices()) colors.insert({mesh.color(vh)[0], mesh.color(vh)[1], mesh.color(vh)[2]});
  EXPECT_GT(colors.size(), 1u);
  for (const auto& entry : fs::directory_iterator(home.path))  // no temporary left behind
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
}
