#include "model/shading_settings.h"

namespace gridifs {

bool ShadingSettings::anyShadows() const {
  for (const ShadingLight& l : lights)
    if (l.shadows) return true;
  return false;
}

}  // namespace gridifs
