// The modeller's headless view cameras and node picking (core/view_camera.h, core/node_picking.h).
#include <gtest/gtest.h>

#include <random>

#include "edit/node_picking.h"
#include "edit/view_camera.h"
#include "io/project_io.h"
#include "model/grid.h"
#include "render/camera.h"

using namespace gridifs;

namespace {

glm::dvec2 pixel(const ViewCamera& cam, const Vec3& p, double w = 400, double h = 300) {
  glm::dvec2 out;
  EXPECT_TRUE(projectToPixel(cam.viewProjection(w, h), w, h, p, out));
  return out;
}

}  // namespace

TEST(ViewCamera, AxisViewsLookAlongTheirAxes) {
  for (ViewAxis axis : {ViewAxis::Top, ViewAxis::Side, ViewAxis::Front}) {
    ViewCamera cam{axis, Camera{}};
    const glm::dvec2 c = pixel(cam, Vec3(0.0));
    EXPECT_NEAR(c.x, 200.0, 1e-9);
    EXPECT_NEAR(c.y, 150.0, 1e-9);
  }
  ViewCamera top{ViewAxis::Top, Camera{}};
  EXPECT_GT(pixel(top, {0.5, 0, 0}).x, 200.0);  // +x to the right
  EXPECT_LT(pixel(top, {0, 0.5, 0}).y, 150.0);  // +y up (pixel y grows downward)
  ViewCamera front{ViewAxis::Front, Camera{}};
  EXPECT_LT(pixel(front, {0, 0, 0.5}).y, 150.0);  // +z up
  EXPECT_GT(pixel(front, {0.5, 0, 0}).x, 200.0);
  ViewCamera side{ViewAxis::Side, Camera{}};
  EXPECT_GT(pixel(side, {0, 0.5, 0}).x, 200.0);  // +y to the right
}

TEST(ViewCamera, DragDeltaFollowsTheMouseInOrthographicViews) {
  for (ViewAxis axis : {ViewAxis::Top, ViewAxis::Side, ViewAxis::Front}) {
    ViewCamera cam{axis, Camera{}};
    const Vec3 p{0.2, -0.3, 0.1};
    const glm::dvec2 a = pixel(cam, p);
    const glm::dvec2 b = pixel(cam, p + cam.dragDelta(17.0, -9.0, p, 300.0));
    EXPECT_NEAR(b.x - a.x, 17.0, 1e-6);
    EXPECT_NEAR(b.y - a.y, -9.0, 1e-6);
  }
}

TEST(ViewCamera, UserViewMatchesTheRenderersCamera) {
  Camera c;
  c.yaw = 40;
  c.pitch = 25;
  c.distance = 3.5;
  ViewCamera user{ViewAxis::User, c};
  const OrbitCamera orbit(c, 400, 300);
  for (const Vec3& p : {Vec3(0.3, -0.2, 0.5), Vec3(-0.8, 0.1, -0.4)}) {
    const ProjectedPoint q = orbit.project(p);
    const glm::dvec2 px = pixel(user, p);
    EXPECT_NEAR(px.x, q.x, 1e-6);
    EXPECT_NEAR(px.y, q.y, 1e-6);
  }
}

TEST(ViewCamera, FramingKeepsTheBoxInView) {
  for (ViewAxis axis : {ViewAxis::Top, ViewAxis::Side, ViewAxis::Front, ViewAxis::User}) {
    ViewCamera cam{axis, Camera{}};
    const Vec3 lo{-3, -1, -2}, hi{1, 2, 0.5};
    cam.frame(lo, hi, 400, 300);
    for (int corner = 0; corner < 8; ++corner) {
      const Vec3 p{corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y, corner & 4 ? hi.z : lo.z};
      const glm::dvec2 px = pixel(cam, p);
      EXPECT_GE(px.x, 0.0) << viewAxisName(axis);
      EXPECT_LE(px.x, 400.0) << viewAxisName(axis);
      EXPECT_GE(px.y, 0.0) << viewAxisName(axis);
      EXPECT_LE(px.y, 300.0) << viewAxisName(axis);
    }
  }
}

TEST(NodePicking, RectangleAndNearestNode) {
  const Grid grid({3, 3, 3});
  ViewCamera top{ViewAxis::Top, Camera{}};
  const glm::dmat4 vp = top.viewProjection(300, 300);
  // The whole image picks all 27 nodes; the right third only the nine with x = 1.
  EXPECT_EQ(nodesInRect(grid.nodes(), vp, 300, 300, {0, 0}, {300, 300}).size(), 27u);
  glm::dvec2 right;
  ASSERT_TRUE(projectToPixel(vp, 300, 300, {1, 0, 0}, right));
  const auto picked = nodesInRect(grid.nodes(), vp, 300, 300, {right.x - 2, 0}, {300, 300});
  EXPECT_EQ(picked.size(), 9u);
  for (std::size_t n : picked) EXPECT_EQ(grid.nodes()[n].x, 1.0);
  // Nodes stacked along the view axis: the one nearest the camera (top: largest z) wins.
  const auto nearest = nearestNode(grid.nodes(), vp, 300, 300, right, 5.0);
  ASSERT_TRUE(nearest.has_value());
  EXPECT_EQ(grid.nodes()[*nearest], Vec3(1, 0, 1));
  EXPECT_FALSE(nearestNode(grid.nodes(), vp, 300, 300, {-50, -50}, 5.0).has_value());
}

TEST(NodePicking, BoxesReproduceAnyMask) {
  std::mt19937 rng(7);
  const Index3 res{5, 4, 6};
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<unsigned char> mask(std::size_t(res[0]) * res[1] * res[2]);
    for (auto& m : mask) m = (rng() % 3) == 0;
    const Selection boxes = boxesFromMask(mask, res);
    if (std::count(mask.begin(), mask.end(), 1) == 0) {
      EXPECT_TRUE(boxes.empty());
      continue;
    }
    EXPECT_EQ(selectionMask(boxes, res), mask);
  }
  // A full grid is one box.
  std::vector<unsigned char> all(std::size_t(res[0]) * res[1] * res[2], 1);
  EXPECT_EQ(boxesFromMask(all, res).size(), 1u);
}

TEST(NodePicking, AddRemoveReplace) {
  const Index3 res{4, 4, 4};
  auto count = [&](const Selection& s) {
    const auto m = selectionMask(s, res);
    return std::count(m.begin(), m.end(), 1);
  };
  Selection s = applyPick({}, {0, 1, 2}, res, PickMode::Replace);
  EXPECT_EQ(count(s), 3);
  s = applyPick(s, {5}, res, PickMode::Add);
  EXPECT_EQ(count(s), 4);
  s = applyPick(s, {1}, res, PickMode::Remove);
  EXPECT_EQ(count(s), 3);
  s = applyPick(s, {}, res, PickMode::Replace);
  EXPECT_TRUE(selectsNothing(s, res));
  // "Nothing" is a legal file entry (unlike negative indices).
  Project p = defaultNewProject();
  Operation op;
  op.params = TranslateOp{Vec3(0.1, 0, 0)};
  op.selection = emptySelection();
  p.functions[0].ops.push_back(op);
  EXPECT_NO_THROW(validateProject(p));
  EXPECT_EQ(parseProject(serializeProject(p)), p);
}
