#pragma once
// Scenes with known attractors for the renderer tests, and a wait on a condition.
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <thread>
#include <vector>

#include "model/project.h"

namespace gridifs::test {

/// The corners of a regular tetrahedron inscribed in X.
inline const std::array<Vec3, 4> kTetraCorners = {Vec3{1, 1, 1}, Vec3{1, -1, -1}, Vec3{-1, 1, -1}, Vec3{-1, -1, 1}};

/// The Sierpinski tetrahedron: f_i(p) = p/2 + v_i/2 for the 4 corners (2×2×2 grids are affine).
inline Project sierpinskiTetrahedron() {
  Project p;
  p.camera.yaw = 30;
  p.camera.pitch = 20;
  p.camera.distance = 4.5;
  p.render.width = 160;
  p.render.height = 120;
  p.render.samples = 200'000;
  const Vec3 colors[4] = {{1, 0.5, 0.1}, {0.2, 0.8, 0.3}, {0.2, 0.4, 1}, {0.9, 0.9, 0.9}};
  for (int i = 0; i < 4; ++i) {
    Function f;
    f.name = "corner" + std::to_string(i);
    f.resolution = {2, 2, 2};
    f.placement.scale = Vec3{0.5};
    f.placement.translate = 0.5 * kTetraCorners[i];
    f.color = colors[i];
    f.palette_index = i / 3.0;
    p.functions.push_back(f);
  }
  return p;
}

/// Whether p lies in the closed tetrahedron (with slack eps in the face equations).
inline bool inTetrahedron(const Vec3& p, double eps) {
  return p.x + p.y + p.z >= -1 - eps && p.x - p.y - p.z >= -1 - eps && -p.x + p.y - p.z >= -1 - eps &&
         -p.x - p.y + p.z >= -1 - eps;
}

/// Whether p lies within the level-`level` approximation of the Sierpinski tetrahedron: some
/// address i1..iL with p ∈ f_i1∘…∘f_iL(T). Inverse maps scale errors by 2 per level, so eps is
/// the tolerance at level 0 (i.e. eps / 2^level in world units).
inline bool inSierpinski(const Vec3& p, int level, double eps) {
  if (!inTetrahedron(p, eps)) return false;
  if (level == 0) return true;
  for (const Vec3& v : kTetraCorners)
    if (inSierpinski(2.0 * p - v, level - 1, eps)) return true;
  return false;
}

/// The first level-`level` address (base 4) whose sub-tetrahedron contains p, or -1.
inline int sierpinskiAddress(Vec3 p, int level, double eps) {
  int address = 0;
  for (int l = 0; l < level; ++l) {
    int found = -1;
    for (int i = 0; i < 4 && found < 0; ++i)
      if (inTetrahedron(2.0 * p - kTetraCorners[i], eps)) found = i;
    if (found < 0) return -1;
    address = address * 4 + found;
    p = 2.0 * p - kTetraCorners[found];
  }
  return address;
}

/// Two square layers at x = +0.5 (red, half the size) and x = -0.5 (blue, full size), each made of
/// four functions that flatten x (scale 0) and tile their square; color_speed 1 makes every point
/// carry its layer's colour. Seen along -x (yaw 0, pitch 0, ortho) the red layer is in front.
/// A one-function IFS whose attractor is the single point `at` (a function of scale 0 moved
/// there), seen by a perspective camera at (4, 0, 0) looking at the origin, 160×160 pixels.
inline Project onePoint(const Vec3& at) {
  Project p;
  p.camera.yaw = 0;
  p.camera.pitch = 0;
  p.camera.distance = 4.0;
  p.camera.fov = 40;
  p.render.width = 160;
  p.render.height = 160;
  p.render.samples = 400'000;
  Function f;
  f.name = "point";
  f.resolution = {2, 2, 2};
  f.placement.scale = Vec3{0.0};
  f.placement.translate = at;
  p.functions.push_back(f);
  return p;
}

/// How the hits of a blurred point spread about `centre` (frame pixels): the hits' mean distance
/// from it, the largest distance of a hit, and the share of hits within `halfReach`.
struct PointSpread {
  double meanDistance = 0.0, farthest = 0.0, innerShare = 0.0;
  std::uint64_t hits = 0;
};
inline PointSpread pointSpread(const std::vector<std::uint32_t>& density, int width, double centreX, double centreY,
                               double halfReach) {
  PointSpread s;
  double sum = 0.0, inner = 0.0;
  for (std::size_t i = 0; i < density.size(); ++i) {
    if (!density[i]) continue;
    const double d =
        std::hypot(double(i % std::size_t(width)) + 0.5 - centreX, double(i / std::size_t(width)) + 0.5 - centreY);
    sum += d * density[i];
    if (d < halfReach) inner += density[i];
    s.hits += density[i];
    s.farthest = std::max(s.farthest, d);
  }
  if (s.hits) {
    s.meanDistance = sum / double(s.hits);
    s.innerShare = inner / double(s.hits);
  }
  return s;
}

/// A point blurred by a uniform angle and a uniform distance up to `reach` pixels (flam3's
/// cam_dof): mean distance reach/2, half the hits within reach/2, none beyond it (a uniform point
/// of the disc would give 2·reach/3 and a quarter).
inline void expectUniformDistanceSpread(const std::vector<std::uint32_t>& density, int width, double centreX,
                                        double centreY, double reach) {
  const PointSpread s = pointSpread(density, width, centreX, centreY, reach / 2.0);
  EXPECT_GT(s.hits, 300'000u);
  EXPECT_NEAR(s.meanDistance, reach / 2.0, 0.03 * reach);
  EXPECT_NEAR(s.innerShare, 0.5, 0.03);
  EXPECT_LE(s.farthest, reach + 1.0);
  EXPECT_GE(s.farthest, reach - 1.5);
}

inline Project twoLayers() {
  Project p;
  p.camera.yaw = 0;
  p.camera.pitch = 0;
  p.camera.distance = 4.0;
  p.camera.projection = CameraProjection::Orthographic;
  p.camera.fov = 35;
  p.render.width = 64;
  p.render.height = 64;
  p.render.samples = 400'000;
  p.render.depth_cue = 0.0;
  for (int layer = 0; layer < 2; ++layer) {
    const double x = layer == 0 ? 0.5 : -0.5, half = layer == 0 ? 0.25 : 0.5;
    for (int q = 0; q < 4; ++q) {
      Function f;
      f.name = (layer == 0 ? "front" : "back") + std::to_string(q);
      f.resolution = {2, 2, 2};
      f.placement.scale = Vec3{0.0, half, half};
      f.placement.translate = Vec3{x, (q & 1 ? 1 : -1) * half, (q & 2 ? 1 : -1) * half};
      f.color = layer == 0 ? Vec3{1, 0, 0} : Vec3{0, 0, 1};
      f.color_speed = 1.0;
      // The back layer's corners are only reached by repeated back maps: weight it up so that
      // every back pixel gets points.
      f.weight = layer == 0 ? 1.0 : 4.0;
      p.functions.push_back(f);
    }
  }
  return p;
}

// Polls `condition` until it holds; false after a generous limit (a hung renderer fails the test
// instead of hanging it). No timing is asserted: on a loaded machine the wait is simply longer.
template <class Condition>
inline bool waitUntil(Condition condition) {
  const auto limit = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!condition()) {
    if (std::chrono::steady_clock::now() > limit) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));  // poll; the condition decides
  }
  return true;
}

}  // namespace gridifs::test
