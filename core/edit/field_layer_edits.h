#pragma once
// Edits of the volume's fractal field layers ("volume.field", model/volume_settings.h): layer 0
// is `field`, layer i > 0 is `more_fields[i − 1]`. Each is one undo step (a slider drag is one
// gesture of SetFieldLayer).
//
// Thread-safety: plain values. apply throws ModelError for a layer the project does not have.
#include <cstddef>
#include <string>

#include "model/project.h"

namespace gridifs {

/// Appends a layer of `role` (the first one creates "volume" with its defaults if needed).
struct AddFieldLayer {
  FieldRole role = FieldRole::Density;
  void apply(Project& project) const;
  std::string label() const;
};

/// Removes layer `layer` and its keyframe tracks; the next ones move up with theirs. Tracks are
/// renamed as the file spells the layers (volume.field.KEY for one, volume.field[i].KEY for a list),
/// also by AddFieldLayer.
struct RemoveFieldLayer {
  std::size_t layer = 0;
  void apply(Project& project) const;
  std::string label() const { return "Remove field layer"; }
};

/// Replaces layer `layer` (the panel's edited copy).
struct SetFieldLayer {
  std::size_t layer = 0;
  VolumeDensityField value;
  void apply(Project& project) const;
  std::string label() const { return "Edit field layer"; }
};

/// The number of layers and layer `index` of a project (null when it has no such layer).
std::size_t fieldLayerCount(const Project& project);
const VolumeDensityField* fieldLayerAt(const Project& project, std::size_t index);

}  // namespace gridifs
