#include "edit/set_edits.h"

namespace gridifs {

void SetCondensationSet::apply(Project& project) const { function.in(project).set = set; }

void SetSetShape::apply(Project& project) const {
  CondensationSet& s = function.in(project).set;
  s.shape = shape;
  if (path) s.path = *path;
}

std::string SetSetShape::label() const { return std::string("Set shape: ") + setShapeName(shape); }

void SetSetFile::apply(Project& project) const { function.in(project).set.path = path; }

void SetSetFill::apply(Project& project) const { function.in(project).set.fill = fill; }

std::string SetSetFill::label() const { return fill == SetFill::Surface ? "Fill surface" : "Fill solid"; }

void SetSetGrid::apply(Project& project) const { function.in(project).set.grid = grid; }

void SetMedianAxis::apply(Project& project) const { function.in(project).rotate_axis = axis; }

}  // namespace gridifs
