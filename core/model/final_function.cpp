#include "model/final_function.h"

#include <iterator>

namespace gridifs {

Function identityFinalFunction() {
  Function f;
  f.name = "final";
  f.resolution = {6, 6, 6};
  // The renderers blend a point's colour towards the final function's by its color_speed
  // (flam3's final xform); 0 keeps every point's colour, so the identity changes nothing.
  f.color_speed = 0.0;
  return f;
}

void removeFinalFunction(Project& project) {
  project.final_function.reset();
  for (auto it = project.tracks.begin(); it != project.tracks.end();) {
    const std::string& path = it->first;
    const bool onFinal = path.rfind("final", 0) == 0 && (path.size() == 5 || path[5] == '.' || path[5] == '[');
    it = onFinal ? project.tracks.erase(it) : std::next(it);
  }
}

}  // namespace gridifs
