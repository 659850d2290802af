#pragma once
// Scenes of flat squares for the shaded display's tests: each square is tiled by four affine
// functions that flatten one axis, so the attractor is exactly the union of the squares.
#include <memory>

#include "model/project.h"
#include "render/compiled_ifs.h"
#include "render/shaded_image.h"

namespace gridifs::test {

/// Adds the four functions whose attractor is the square centred at `center`, of half size
/// `half`, perpendicular to `flatAxis` (0 x, 1 y, 2 z): each maps X onto one quadrant of the
/// square, p ↦ (half/2)·p + center ± half/2 in the plane. The quadrants are filled when the whole
/// attractor's projection on the plane's axes is [-1, 1]² — true when a square of half size 1
/// centred on the origin shares those axes, as in every scene here.
inline void addSquare(Project& p, const Vec3& center, double half, int flatAxis, const Vec3& color,
                      double weight = 1.0) {
  const int a = (flatAxis + 1) % 3, b = (flatAxis + 2) % 3;
  for (int q = 0; q < 4; ++q) {
    Function f;
    f.name = "square" + std::to_string(p.functions.size());
    f.resolution = {2, 2, 2};
    Vec3 scale{half / 2.0};
    scale[flatAxis] = 0.0;
    f.placement.scale = scale;
    Vec3 t = center;
    t[a] += (q & 1 ? 0.5 : -0.5) * half;
    t[b] += (q & 2 ? 0.5 : -0.5) * half;
    f.placement.translate = t;
    f.color = color;
    f.color_speed = 1.0;
    f.weight = weight;
    p.functions.push_back(f);
  }
}

/// Makes every square nearly its own IFS: after a function of one square the same square's
/// functions follow with 20 times the probability of another square's (a transition matrix,
/// Thollot et al.), so each square is filled almost uniformly instead of mostly with images of
/// the other squares, and every chain still visits every square.
inline void separateSquares(Project& p) {
  const std::size_t n = p.functions.size();
  p.transitions.assign(n, std::vector<double>(n, 0.0));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) p.transitions[i][j] = i / 4 == j / 4 ? 1.0 : 0.05;
}

/// A project in the shaded mode with no functions yet: ambient 0.2, one light, no occlusion.
inline Project shadedBase(int size, std::int64_t samples) {
  Project p;
  p.render.mode = DisplayMode::Shaded;
  p.render.width = size;
  p.render.height = size;
  p.render.samples = samples;
  p.render.seed = 7;
  p.render.shading.ambient = 0.2;
  p.render.shading.specular = 0.0;
  p.render.shading.ao.strength = 0.0;
  return p;
}

/// Renders and develops `p` in the shaded display on `threads` workers.
inline ShadedImage renderShaded(Project p, int threads, RenderImage* snapshot = nullptr) {
  if (p.functions.size() > 4 && p.transitions.empty()) separateSquares(p);
  const auto ifs = compileIfs(p);
  const RenderJob job = shadedRenderJob(RenderJob::fromProject(p, threads), p.render.shading, *ifs);
  RenderImage image = renderToCompletion(ifs, job, shadedDisplaySettings(p));
  ShadedImage out;
  developShaded(image, p.render.shading, p.camera, p.render.background, threads, out);
  if (snapshot) *snapshot = std::move(image);
  return out;
}

}  // namespace gridifs::test
