#pragma once
// A GridIFS project as a flame genome (the .flame XML of flam3 and Apophysis; Draves & Reckase):
// each function becomes an xform holding its least-squares affine fit in the z = 0 plane (exact
// for affine grids), with weight, palette index, color speed, transitions as `chaos`, the final
// function as `finalxform`, the palette as <color> entries and the flame display settings.
// Pure functions apart from reading palette files: thread-safe.
#include <filesystem>
#include <string>
#include <vector>

#include "model/grid.h"
#include "model/grid_affine_fit.h"
#include "model/project.h"
#include "variations/flame_variations.h"

namespace gridifs {

struct FlameExport {
  std::string xml;
  std::vector<std::string> warnings;  // non-affine functions, dropped 3D content, palette problems
};

/// Builds the .flame text. `projectFolder` anchors relative palette files. Throws ModelError
/// (with a JSON path) when a stack fails to evaluate.
FlameExport exportFlame(const Project& project, const std::filesystem::path& projectFolder, const std::string& name);

}  // namespace gridifs
