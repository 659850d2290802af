#include "model/project.h"

namespace gridifs {

Project defaultNewProject() {
  Project p;
  Function f;
  f.name = "f1";
  f.placement.scale = Vec3{0.5};
  f.color = {1.0, 0.6, 0.2};
  p.functions.push_back(f);
  return p;
}

}  // namespace gridifs
