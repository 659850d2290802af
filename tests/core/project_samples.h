#pragma once
// Random but valid projects for round-trip and undo tests.
#include <random>

#include "model/project.h"

namespace gridifs::test_support {

class ProjectSampler {
 public:
  explicit ProjectSampler(unsigned seed) : rng_(seed) {}

  double real(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  Vec3 vec(double lo, double hi) { return {real(lo, hi), real(lo, hi), real(lo, hi)}; }

  Operation operation() {
    Operation op;
    switch (integer(0, 9)) {
      case 0:
        op.params = TranslateOp{vec(-0.2, 0.2)};
        break;
      case 1:
        op.params = RotateOp{vec(-90, 90)};
        break;
      case 2:
        op.params = ScaleOp{vec(0.5, 1.2)};
        break;
      case 3:
        op.params = TaperOp{Axis(integer(0, 2)), Profile(integer(0, 2)), real(-0.5, 0.5), real(0.5, 4)};
        break;
      case 4:
        op.params = TwistOp{Axis(integer(0, 2)), Profile(integer(0, 2)), real(-2, 2), real(0.5, 4)};
        break;
      case 5:
        op.params = BendOp{Axis::Z, Axis(integer(0, 1)), real(-1, 1)};
        break;
      case 6:
        op.params = MagnetOp{vec(-1, 1), real(0.1, 1), real(-0.5, 0.5), real(0.5, 3)};
        break;
      case 7:
        op.params = MorphOp{{{vec(-1, -0.5), vec(-1, 1)}, {vec(0.5, 1), vec(-1, 1)}}, real(0, 1)};
        break;
      case 8: {
        CalculatorOp c;
        c.x = "x + v1*sin(3*y)";
        c.y = "y*(1 + v2*z)";
        c.z = "z + 0.01*rand()";
        c.vars = {CalculatorVar{real(-1, 1), -1, 1}, CalculatorVar{real(-0.5, 0.5), -0.5, 0.5}, CalculatorVar{}};
        c.seed = std::uint64_t(integer(0, 1 << 30)) * 977;
        op.params = c;
        break;
      }
      default:
        op.params = NodesOp{{{{integer(0, 3), integer(0, 3), integer(0, 3)}, vec(-0.1, 0.1)}}};
        break;
    }
    const int centerKind = integer(0, 2);
    op.center.kind = Center::Kind(centerKind);
    if (centerKind == 2) op.center.point = vec(-1, 1);
    for (int b = integer(0, 2); b > 0; --b)
      op.selection.push_back({{integer(0, 5), integer(0, 5)},
                              {integer(0, 5), integer(0, 5)},
                              {integer(0, 5), integer(0, 5)},
                              SelectionOp(integer(0, 3))});
    op.muted = integer(0, 9) == 0;
    return op;
  }

  Function function(int index) {
    Function f;
    f.name = "f" + std::to_string(index) + (integer(0, 1) ? " ünïcode \"quoted\"" : "");
    f.resolution = {integer(2, 6), integer(2, 6), integer(2, 6)};
    f.weight = real(0.1, 3);
    f.color = vec(0, 1);
    f.palette_index = real(0, 1);
    f.color_speed = real(0, 1);
    f.placement = {vec(-0.5, 0.5), vec(-45, 45), vec(0.2, 0.5)};
    for (int o = integer(0, 4); o > 0; --o) f.ops.push_back(operation());
    return f;
  }

  Project project() {
    Project p;
    p.camera = {real(-180, 180), real(-89, 89), real(1, 10), vec(-1, 1), real(10, 90), CameraProjection::Perspective,
                std::nullopt};
    // Every projection; panoramic ones reach past 170°, some cameras see in stereo.
    p.camera.projection = CameraProjection(integer(0, 3));
    if (p.camera.panoramic()) p.camera.fov = real(10, 360);
    if (!p.camera.orthographic() && integer(0, 3) == 0)
      p.camera.stereo = StereoSettings{real(0, 0.5), StereoLayout(integer(0, 1)), real(0.5, 20)};
    p.render.width = integer(16, 2048);
    p.render.height = integer(16, 2048);
    p.render.samples = integer(1, 1 << 30);
    p.render.seed = std::uint64_t(integer(0, 1 << 30)) << 20;
    p.render.skip = integer(0, 100);
    p.render.background = vec(0, 1);
    p.render.depth_cue = real(0, 1);
    for (int f = integer(1, 4); f > 0; --f) p.functions.push_back(function(f));
    if (integer(0, 2) == 0) p.final_function = function(99);
    return p;
  }

 private:
  std::mt19937 rng_;
};

}  // namespace gridifs::test_support
