#pragma once
// The flame scene the flame-render tests share: the Sierpinski triangle in the z = 0 plane.
#include <string>

#include "model/project.h"

namespace gridifs::test_support {

/// The Sierpinski triangle in the z = 0 plane, seen from straight above with an ortho camera.
inline Project sierpinskiFlame(int size) {
  Project p;
  p.functions.clear();
  const Vec3 corners[3] = {{-0.5, -0.5, 0}, {0.5, -0.5, 0}, {0.0, 0.5, 0}};
  for (int i = 0; i < 3; ++i) {
    Function f;
    f.name = "f" + std::to_string(i + 1);
    f.resolution = {2, 2, 2};
    f.placement.scale = {0.5, 0.5, 0.0};
    f.placement.translate = corners[i] * 0.5 + Vec3{0.0, 0.0, 0.0};
    f.palette_index = i / 2.0;
    p.functions.push_back(f);
  }
  p.camera.pitch = 90.0;
  p.camera.yaw = -90.0;
  p.camera.projection = CameraProjection::Orthographic;
  p.camera.distance = 2.0;
  p.camera.fov = 45.0;
  p.render.width = p.render.height = size;
  p.render.samples = 200000;
  p.render.mode = DisplayMode::Flame;
  return p;
}

}  // namespace gridifs::test_support
