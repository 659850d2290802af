#pragma once
// The canonical benchmark scene, shared by bench_chaos and bench_gpu: three 16³ functions placed
// like a Sierpinski triangle in 3D, each with twist, taper and bend, 1024×1024, perspective.
#include "edit/document.h"

namespace gridifs {

inline Operation op(OpParams params) {
  Operation o;
  o.params = std::move(params);
  return o;
}

/// Three 16³ functions placed like a Sierpinski triangle in 3D, each with a different distortion.
inline Project canonicalScene() {
  Project p;
  p.camera.yaw = 35;
  p.camera.pitch = 25;
  p.camera.distance = 4.0;
  p.camera.fov = 40;
  p.render.width = 1024;
  p.render.height = 1024;
  p.render.skip = 20;
  const Vec3 corners[3] = {{0.5, 0.0, -0.3}, {-0.25, 0.43, -0.3}, {-0.25, -0.43, 0.3}};
  const Vec3 colors[3] = {{1, 0.5, 0.1}, {0.2, 0.7, 1.0}, {0.9, 0.9, 0.3}};
  for (int i = 0; i < 3; ++i) {
    Function f;
    f.name = "f" + std::to_string(i + 1);
    f.resolution = {16, 16, 16};
    f.placement.scale = Vec3{0.5};
    f.placement.translate = corners[i];
    f.placement.rotate = {10.0 * i, 20.0, 30.0 * i};
    f.color = colors[i];
    f.palette_index = i / 2.0;
    TwistOp twist;
    twist.axis = Axis::Z;
    twist.k = 0.8 + 0.3 * i;
    f.ops.push_back(op(twist));
    TaperOp taper;
    taper.axis = Axis::X;
    taper.profile = Profile::Sine;
    taper.k = 0.25;
    taper.omega = 3.0;
    f.ops.push_back(op(taper));
    BendOp bend;
    bend.axis = Axis::Z;
    bend.toward = Axis::Y;
    bend.k = 0.4;
    f.ops.push_back(op(bend));
    p.functions.push_back(f);
  }
  return p;
}

}  // namespace gridifs
