// View › Explore driven as an artist drives it: open it with E, Mutate, wait for the thumbnails,
// adopt one with a click (one undo step), undo back to the file byte for byte; pin two and Breed;
// and the first start without a file opens on a living project.
#include <gtest/gtest.h>

#include "io/project_io.h"
#include "tests/gui/gui_harness.h"

using namespace gridifs::gui_test;

namespace {

bool allShown(const nlohmann::json& j, std::size_t generations) {
  const auto& e = j["explore"];
  if (e["generations"].get<std::size_t>() < generations || e["busy"].get<bool>()) return false;
  for (const auto& slot : e["slots"])
    if (!slot["ready"].get<bool>() || (slot["error"].get<std::string>().empty() && !slot["shown"].get<bool>()))
      return false;
  return !e["slots"].empty();
}

}  // namespace

TEST(ExploreGui, MutateAdoptAndUndoBackToTheFile) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "default.gridifs", 300'000);
  const std::string original = gridifs::serializeProject(gridifs::loadProject(project));
  App app(home, {project.string()});
  nlohmann::json probe = app.waitForPreview();
  pressKeys("e");
  // Opening draws a first generation of mutations; the thumbnails fill in the background.
  probe = app.waitFor([](const nlohmann::json& j) { return allShown(j, 1); }, 120s);
  ASSERT_TRUE(allShown(probe, 1)) << probe["explore"].dump();
  std::size_t shown = 0;
  for (const auto& slot : probe["explore"]["slots"]) shown += slot["shown"].get<bool>() ? 1 : 0;
  EXPECT_GE(shown, 7u) << "most variants should be worth looking at";

  // Mutate again: a second generation.
  clickRect(rectOf(probe, "explore.mutate"));
  probe = app.waitFor([](const nlohmann::json& j) { return allShown(j, 2); }, 120s);
  ASSERT_TRUE(allShown(probe, 2)) << probe["explore"].dump();
  EXPECT_EQ(probe["explore"]["current"], 1);

  // Adopt the first shown variant: one undo step.
  std::size_t pick = 0;
  while (!probe["explore"]["slots"][pick]["shown"].get<bool>()) ++pick;
  clickRect(rectOf(probe, "explore.slot" + std::to_string(pick)));
  probe = app.waitFor([](const nlohmann::json& j) { return j["undo"] == "Adopt variant"; });
  EXPECT_EQ(probe["undo"], "Adopt variant");
  EXPECT_TRUE(probe["dirty"].get<bool>());

  // Back shows the first generation again, still drawn.
  clickRect(rectOf(probe, "explore.back"));
  probe = app.waitFor([](const nlohmann::json& j) { return j["explore"]["current"] == 0; });
  EXPECT_EQ(probe["explore"]["current"], 0);

  // Undo brings the file's project back; saving writes the same bytes.
  pressKeys("ctrl+z");
  probe = app.waitFor([](const nlohmann::json& j) { return !j["dirty"].get<bool>(); });
  EXPECT_FALSE(probe["dirty"].get<bool>());
  pressKeys("ctrl+s");
  EXPECT_EQ(gridifs::serializeProject(gridifs::loadProject(project)), original);
}

TEST(ExploreGui, PinTwoAndBreed) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "tapered_functions.gridifs", 300'000);
  App app(home, {project.string()});
  nlohmann::json probe = app.waitForPreview();
  pressKeys("e");
  probe = app.waitFor([](const nlohmann::json& j) { return allShown(j, 1); }, 120s);
  ASSERT_TRUE(allShown(probe, 1));
  std::vector<std::size_t> pins;
  for (std::size_t i = 0; i < probe["explore"]["slots"].size() && pins.size() < 2; ++i)
    if (probe["explore"]["slots"][i]["shown"].get<bool>()) pins.push_back(i);
  ASSERT_EQ(pins.size(), 2u);
  for (std::size_t i : pins) clickRect(rectOf(probe, "explore.pin" + std::to_string(i)));
  probe = app.waitFor([&](const nlohmann::json& j) {
    return j["explore"]["slots"][pins[0]]["pinned"].get<bool>() && j["explore"]["slots"][pins[1]]["pinned"].get<bool>();
  });
  clickRect(rectOf(probe, "explore.breed"));
  probe = app.waitFor([](const nlohmann::json& j) { return allShown(j, 2); }, 120s);
  ASSERT_TRUE(allShown(probe, 2)) << probe["explore"].dump();
}

TEST(ExploreGui, ABareStartOpensOnSomethingAlive) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  App app(home, {});
  const nlohmann::json probe = app.waitForPreview();
  EXPECT_GT(probe["functions"].get<std::size_t>(), 1u) << "not the one-grid project";
  EXPECT_GT(probe["preview"]["hit_pixels"].get<std::int64_t>(), 2000) << "not a one-dot preview";
  EXPECT_FALSE(probe["dirty"].get<bool>());
}

TEST(ExploreGui, ThumbnailsRenderOnTheGpuWhenThePreviewDoes) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display (run under xvfb-run)";
  TempFolder home;
  const fs::path project = exampleCopy(home, "default.gridifs", 300'000);
  // Mesa's llvmpipe offers OpenGL 4.3 compute here, so --device gpu runs the compute renderer.
  App app(home, {project.string(), "--device", "gpu"});
  nlohmann::json probe = app.waitForPreview();
  ASSERT_EQ(probe["preview"]["device"].get<std::string>().rfind("gpu", 0), 0u) << probe["preview"]["device"];
  pressKeys("e");
  probe = app.waitFor([](const nlohmann::json& j) { return allShown(j, 1); }, 180s);
  ASSERT_TRUE(allShown(probe, 1)) << probe["explore"].dump();
  EXPECT_EQ(probe["explore"]["device"], "gpu");
}
