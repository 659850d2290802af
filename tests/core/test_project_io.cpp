// The .gridifs file: round trips, validation with JSON paths, atomic saves.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/project_io.h"
#include "model_error_text.h"
#include "project_samples.h"

using namespace gridifs;
namespace fs = std::filesystem;

namespace {
std::string readFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string errorOf(const std::string& text) {
  return test_support::modelErrorText([&] { parseProject(text); });
}

const char* kMinimal = R"({"format":"gridifs","version":1,"functions":[{"name":"a"}]})";

struct TempDir {
  fs::path path;
  TempDir() {
    path = fs::temp_directory_path() / ("gridifs-test-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
};
}  // namespace

TEST(ProjectIo, RandomProjectsRoundTripExactly) {
  test_support::ProjectSampler sampler(21);
  for (int n = 0; n < 200; ++n) {
    const Project p = sampler.project();
    const std::string text = serializeProject(p);
    const Project back = parseProject(text);
    ASSERT_EQ(back, p) << text;
    ASSERT_EQ(serializeProject(back), text);
  }
}

TEST(ProjectIo, DesignExampleLoads) {
  // The example project of the file-format description, verbatim in its field names.
  const std::string text = R"json({
  "format": "gridifs", "version": 1,
  "camera": {"yaw": 30, "pitch": 20, "distance": 4.0, "target": [0,0,0], "fov": 35, "ortho": false},
  "render": {"width": 1024, "height": 768, "samples": 20000000, "seed": 1, "skip": 20,
             "background": [0,0,0], "depth_cue": 0.6},
  "functions": [
    {"name": "f1", "resolution": [6, 6, 6], "weight": 1, "color": [1, 0.6, 0.2], "palette_index": 0.0,
     "muted": false,
     "placement": {"translate": [0,0,0], "rotate": [0,0,0], "scale": [0.5,0.5,0.5]},
     "ops": [
       {"type": "twist", "axis": "z", "profile": "linear", "k": 1.2, "omega": 1.0,
        "center": "grid", "selection": []},
       {"type": "taper", "axis": "z", "profile": "sine", "k": 0.3, "omega": 3.14159, "center": [0,0,0],
        "selection": [{"i": [0, 2], "j": [0, 5], "k": [0, 5], "op": "or"}]},
       {"type": "bend", "axis": "z", "toward": "y", "k": 0.8, "center": "selection"},
       {"type": "translate", "offset": [0.1, 0, 0]},
       {"type": "rotate", "angles": [0, 0, 30]},
       {"type": "scale", "factors": [1, 1, 0.8]},
       {"type": "magnet", "point": [0.2,0,0], "dmax": 0.8, "strength": 0.5, "falloff": 2},
       {"type": "morph", "pairs": [[[0,0,0],[0.1,0.2,0]]], "strength": 1.0},
       {"type": "calculator", "x": "x*cos(v1*sqrt(x^2+y^2)) - y*sin(v1*sqrt(x^2+y^2))",
        "y": "x*sin(v1*sqrt(x^2+y^2)) + y*cos(v1*sqrt(x^2+y^2))", "z": "z",
        "vars": {"v1": {"value": 0.2, "min": -1, "max": 1}}, "seed": 7},
       {"type": "nodes", "moves": [[1, 2, 3, [0.0, 0.1, 0.0]]]}
     ]}
  ]
})json";
  const Project p = parseProject(text);
  ASSERT_EQ(p.functions.size(), 1u);
  ASSERT_EQ(p.functions[0].ops.size(), 10u);
  EXPECT_EQ(p.functions[0].ops[1].center.kind, Center::Kind::Point);
  EXPECT_EQ(p.functions[0].ops[2].center.kind, Center::Kind::Selection);
  EXPECT_DOUBLE_EQ(std::get<CalculatorOp>(p.functions[0].ops[8].params).vars[0].value, 0.2);
  EXPECT_EQ(std::get<NodesOp>(p.functions[0].ops[9].params).moves[0].index, (Index3{1, 2, 3}));
  EXPECT_EQ(parseProject(serializeProject(p)), p);
}

TEST(ProjectIo, ErrorsNameTheJsonPath) {
  auto withOp = [](const std::string& op) {
    return R"({"format":"gridifs","version":1,"functions":[{"name":"a"},{"name":"b","ops":[)" + op + "]}]}";
  };
  EXPECT_EQ(errorOf(withOp(R"({"type":"taper","k":"big"})")),
            "functions[1].ops[0].k: expected a number, found a string");
  EXPECT_NE(errorOf(withOp(R"({"type":"warp"})")).find("functions[1].ops[0].type: unknown operation \"warp\""),
            std::string::npos);
  EXPECT_NE(errorOf(withOp(R"({"type":"calculator","x":"x+"})")).find("functions[1].ops[0].x:"), std::string::npos);
  EXPECT_NE(errorOf(withOp(R"({"type":"calculator","y":"q*2"})")).find("functions[1].ops[0].y:"), std::string::npos);
  EXPECT_NE(errorOf(withOp(R"({"type":"morph","pairs":[[[0,0,0],[1,0,0]],[[0,0,0],[0,1,0]]]})"))
                .find("functions[1].ops[0].pairs:"),
            std::string::npos);
  EXPECT_NE(errorOf(withOp(R"({"type":"bend","axis":"y","toward":"y"})")).find("functions[1].ops[0].toward"),
            std::string::npos);
  EXPECT_NE(errorOf(withOp(R"({"type":"scale","factors":[1,1]})")).find("functions[1].ops[0].factors"),
            std::string::npos);
  EXPECT_NE(
      errorOf(withOp(R"({"type":"twist","selection":[{"i":[0,-1]}]})")).find("functions[1].ops[0].selection[0].i[1]"),
      std::string::npos);
}

TEST(ProjectIo, RejectsHostileTopLevels) {
  EXPECT_NE(errorOf("").find("empty"), std::string::npos);
  EXPECT_NE(errorOf("not json").find("not valid JSON"), std::string::npos);
  EXPECT_NE(errorOf(R"({"format":"gridifs","version":1,"functions":[{"na)").find("truncated"), std::string::npos);
  EXPECT_NE(errorOf(R"({"format":"gridifs","version":7,"functions":[]})").find("unsupported version 7"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"format":"other","version":1})").find("format"), std::string::npos);
  EXPECT_NE(errorOf(R"({"format":"gridifs","version":1,"functions":[{"resolution":[1,4,4]}]})")
                .find("functions[0].resolution[0]"),
            std::string::npos);
  EXPECT_NE(
      errorOf(R"({"format":"gridifs","version":1,"functions":[{"resolution":[100000,4,4]}]})").find("resolution[0]"),
      std::string::npos);
  EXPECT_NE(errorOf(R"({"format":"gridifs","version":1,"functions":[{"weight":-1}]})").find("functions[0].weight"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"format":"gridifs","version":1,"functions":[{"weight":0},{"weight":0}]})").find("weight"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"format":"gridifs","version":1,"functions":[{"weight":1e999}]})").find("too large"),
            std::string::npos);
  std::string deep = R"({"format":"gridifs","version":1,"functions":[{"name":"a","x":)" + std::string(100000, '[') +
                     std::string(100000, ']') + "}]}";
  EXPECT_NE(errorOf(deep).find("nested"), std::string::npos);
  std::string longName =
      R"({"format":"gridifs","version":1,"functions":[{"name":")" + std::string(1 << 20, 'a') + "\"}]}";
  EXPECT_NE(errorOf(longName).find("functions[0].name"), std::string::npos);
  std::string many = R"({"format":"gridifs","version":1,"functions":[)";
  for (int i = 0; i < 100000; ++i) many += (i ? ",{}" : "{}");
  many += "]}";
  EXPECT_NE(errorOf(many).find("more than 64 functions"), std::string::npos);
  std::string heavy = R"({"format":"gridifs","version":1,"functions":[)";
  for (int i = 0; i < 3; ++i) heavy += std::string(i ? "," : "") + R"({"resolution":[128,128,128]})";
  heavy += "]}";
  EXPECT_NE(errorOf(heavy).find("nodes in all"), std::string::npos);
}

TEST(ProjectIo, SaveIsAtomicAndKeepsABackup) {
  TempDir dir;
  const fs::path file = dir.path / "p.gridifs";
  test_support::ProjectSampler sampler(5);
  const Project first = sampler.project(), second = sampler.project();
  saveProject(first, file);
  EXPECT_FALSE(fs::exists(dir.path / "p.gridifs~"));
  saveProject(second, file);
  EXPECT_EQ(loadProject(file), second);
  EXPECT_EQ(parseProject(readFile(dir.path / "p.gridifs~")), first);
  for (const auto& entry : fs::directory_iterator(dir.path))  // no temporaries left behind
    EXPECT_TRUE(entry.path().filename() == "p.gridifs" || entry.path().filename() == "p.gridifs~") << entry.path();
}

TEST(ProjectIo, InvalidProjectsAreNeverWritten) {
  TempDir dir;
  const fs::path file = dir.path / "p.gridifs";
  saveProject(parseProject(kMinimal), file);
  const std::string before = readFile(file);
  Project bad = parseProject(kMinimal);
  bad.functions[0].weight = 0;
  EXPECT_THROW(saveProject(bad, file), ModelError);
  EXPECT_EQ(readFile(file), before);
}

TEST(ProjectIo, UnwritableFolderLeavesTheOldFileIntact) {
  if (::geteuid() == 0) GTEST_SKIP() << "root ignores folder permissions";
  TempDir dir;
  const fs::path file = dir.path / "p.gridifs";
  saveProject(parseProject(kMinimal), file);
  const std::string before = readFile(file);
  fs::permissions(dir.path, fs::perms::owner_read | fs::perms::owner_exec);
  Project changed = parseProject(kMinimal);
  changed.functions[0].name = "changed";
  EXPECT_THROW(saveProject(changed, file), IoError);
  fs::permissions(dir.path, fs::perms::owner_all);
  EXPECT_EQ(readFile(file), before);
}

TEST(ProjectIo, FullDiskLeavesTheOldFileIntact) {
  // A tiny tmpfs stands in for a full disk (needs root; skipped where mounting is not allowed).
  TempDir dir;
  const fs::path mountPoint = dir.path / "disk";
  fs::create_directories(mountPoint);
  if (::geteuid() != 0 ||
      std::system(("mount -t tmpfs -o size=64k tmpfs '" + mountPoint.string() + "' 2>/dev/null").c_str()) != 0)
    GTEST_SKIP() << "cannot mount a small tmpfs here";
  const fs::path file = mountPoint / "p.gridifs";
  saveProject(parseProject(kMinimal), file);
  const std::string before = readFile(file);
  {
    std::ofstream fill(mountPoint / "filler", std::ios::binary);
    std::string block(4096, 'x');
    for (int i = 0; i < 64; ++i) fill << block;
  }
  Project big = parseProject(kMinimal);
  big.functions[0].name = std::string(200, 'n');
  for (int i = 0; i < 200; ++i) {
    Operation op;
    op.params = TranslateOp{Vec3{0.001 * i, 0, 0}};
    big.functions[0].ops.push_back(op);
  }
  EXPECT_THROW(saveProject(big, file), IoError);
  EXPECT_EQ(readFile(file), before);
  int leftovers = 0;
  for (const auto& entry : fs::directory_iterator(mountPoint))
    leftovers += entry.path().filename().string().find(".tmp") != std::string::npos;
  EXPECT_EQ(leftovers, 0);
  std::system(("umount '" + mountPoint.string() + "'").c_str());
}

TEST(ProjectIo, FailedLoadDoesNotTouchTheFile) {
  TempDir dir;
  const fs::path file = dir.path / "broken.gridifs";
  { std::ofstream(file) << R"({"format":"gridifs","version":1,"functions":[{"weight":"x"}]})"; }
  const auto stamp = fs::last_write_time(file);
  const std::string before = readFile(file);
  EXPECT_THROW(loadProject(file), ModelError);
  EXPECT_EQ(readFile(file), before);
  EXPECT_EQ(fs::last_write_time(file), stamp);
  EXPECT_THROW(loadProject(dir.path / "missing.gridifs"), IoError);
}

TEST(ProjectIo, EveryExampleLoadsAndEvaluates) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(GRIDIFS_ASSETS)) {
    if (entry.path().extension() != ".gridifs") continue;
    ++count;
    SCOPED_TRACE(entry.path().string());
    const Project p = loadProject(entry.path());
    EXPECT_GE(p.functions.size(), 1u);
    EXPECT_LE(p.functions.size(), 5u);  // "an IFS of up to 5 functions" (Gröller & Wegenkittl 1994, §5)
    EXPECT_EQ(parseProject(serializeProject(p)), p);
  }
  EXPECT_GE(count, 9);
}

// The file format is a contract: every shipped project (assets/ and its subfolders, the
// projects of tests/data/flame) is saved exactly as tests/data/saved holds it (the bytes GridIFS
// has always written for it; a project GridIFS wrote itself is its own saved form), and a saved
// file is saved again unchanged.
TEST(ProjectIo, EveryShippedProjectSavesAsItAlwaysHas) {
  const fs::path saved = fs::path(GRIDIFS_TEST_DATA) / "saved";
  int count = 0;
  for (const auto& [root, tag] :
       {std::pair<fs::path, std::string>{GRIDIFS_ASSETS, "assets"}, {fs::path(GRIDIFS_TEST_DATA) / "flame", "flame"}}) {
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
      if (entry.path().extension() != ".gridifs") continue;
      ++count;
      SCOPED_TRACE(entry.path().string());
      // A project written by GridIFS (the imported flame in assets/flames) is its own saved form.
      const fs::path savedFile = saved / tag / fs::relative(entry.path(), root);
      const std::string expected = readFile(fs::exists(savedFile) ? savedFile : entry.path());
      EXPECT_EQ(serializeProject(loadProject(entry.path())), expected);
      EXPECT_EQ(serializeProject(parseProject(expected)), expected);
    }
  }
  EXPECT_GE(count, 13);
}
