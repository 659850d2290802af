#include "base/types.h"

namespace gridifs {

const char* axisName(Axis axis) {
  switch (axis) {
    case Axis::X:
      return "x";
    case Axis::Y:
      return "y";
    case Axis::Z:
      return "z";
  }
  return "z";
}

const char* profileName(Profile profile) {
  switch (profile) {
    case Profile::Linear:
      return "linear";
    case Profile::Sine:
      return "sine";
    case Profile::PingPong:
      return "pingpong";
  }
  return "linear";
}

bool parseAxis(const std::string& text, Axis& out) {
  if (text == "x")
    out = Axis::X;
  else if (text == "y")
    out = Axis::Y;
  else if (text == "z")
    out = Axis::Z;
  else
    return false;
  return true;
}

bool parseProfile(const std::string& text, Profile& out) {
  if (text == "linear")
    out = Profile::Linear;
  else if (text == "sine")
    out = Profile::Sine;
  else if (text == "pingpong")
    out = Profile::PingPong;
  else
    return false;
  return true;
}

}  // namespace gridifs
