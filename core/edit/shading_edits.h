#pragma once
// Named edits of the shaded display's lights, fog colour and depth of field (render.shading). The
// numbers with sliders go through SetParameter (edit/parameter_edit.h). Each edit is a plain
// value gathered in ProjectEdit (edit/project_edit.h).
//
// Thread-safety: plain values; apply() touches only the project given. apply() throws ModelError
// when the light it names is not in the project.
#include <string>

#include "model/project.h"

namespace gridifs {

/// Appends a fill light: from the upper left, at 0.4 of the key light's intensity, casting no
/// shadows, so a second light softens the first rather than competing with it.
struct AddLight {
  void apply(Project& project) const;
  std::string label() const { return "Add light"; }
};

struct RemoveLight {
  std::size_t index = 0;
  void apply(Project& project) const;
  std::string label() const { return "Remove light"; }
};

/// Where light `index` comes from (any non-zero direction).
struct SetLightDirection {
  std::size_t index = 0;
  Vec3 direction{0.0, 0.0, 1.0};
  void apply(Project& project) const;
  std::string label() const { return "Light direction"; }
};

struct SetLightColor {
  std::size_t index = 0;
  Vec3 color{1.0};
  void apply(Project& project) const;
  /// The light table's label of "color".
  std::string label() const;
};

struct SetLightShadows {
  std::size_t index = 0;
  bool shadows = true;
  void apply(Project& project) const;
  /// "Light casts shadows" or "Light casts no shadows".
  std::string label() const;
};

struct SetFogColor {
  Vec3 color{0.0};
  void apply(Project& project) const;
  /// The fog table's label of "color".
  std::string label() const;
};

/// The depth of field's aperture with its focus distance: an aperture needs one, and the first is
/// the camera's distance to its target.
struct SetAperture {
  double aperture = 0.0;
  double focus = 4.0;
  void apply(Project& project) const;
  /// The depth-of-field table's label of "aperture".
  std::string label() const;
};

}  // namespace gridifs
