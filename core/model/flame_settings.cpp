#include "model/flame_settings.h"

namespace gridifs {

const char* displayModeName(DisplayMode mode) {
  switch (mode) {
    case DisplayMode::Flame:
      return "flame";
    case DisplayMode::Shaded:
      return "shaded";
    default:
      return "zbuffer";
  }
}

bool parseDisplayMode(const std::string& text, DisplayMode& out) {
  if (text == "zbuffer") out = DisplayMode::ZBuffer;
  else if (text == "flame") out = DisplayMode::Flame;
  else if (text == "shaded") out = DisplayMode::Shaded;
  else return false;
  return true;
}

}  // namespace gridifs
