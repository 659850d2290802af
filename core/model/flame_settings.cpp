#include "model/flame_settings.h"

namespace gridifs {

const char* displayModeName(DisplayMode mode) { return mode == DisplayMode::Flame ? "flame" : "zbuffer"; }

bool parseDisplayMode(const std::string& text, DisplayMode& out) {
  if (text == "zbuffer") out = DisplayMode::ZBuffer;
  else if (text == "flame") out = DisplayMode::Flame;
  else return false;
  return true;
}

}  // namespace gridifs
