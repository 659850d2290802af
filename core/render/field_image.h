#pragma once
// A fractal field as a picture (Colonna, "Animation of fractal objects", fig. 2: the field over a
// square, 256 colours): each field plane is a size×size grid of values over [-1, 1]²; one plane is
// colour-mapped through a palette from its lowest value (the palette's first colour) to its
// highest (the last), so partial sums M_1, M_1 + M_2, … each use the whole palette. Several planes
// make a scene seen from above (his fig. 6): the first plane that is not a cloud is the ground,
// coloured as above, and each cloud plane lays white over it with opacity clamp(strength·G, 0, 1).
// EXR files keep the raw values instead, one float channel per plane.
//
// Thread-safety: pure functions; writeFieldImage writes only its file.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "model/volume_settings.h"
#include "tone/palette.h"

namespace gridifs {

struct FieldPlane {
  std::vector<double> values;  // size², row-major, row 0 at y = −1 (schema/field_layer.h's plane)
  FieldRole role = FieldRole::Density;
  double strength = 1.0;
  std::string name;  // the EXR channel's name
};

/// 8-bit RGB pixels, size² · 3, row 0 at the top (y = +1). Expects at least one plane of size² values.
std::vector<std::uint8_t> colourFieldPlanes(const std::vector<FieldPlane>& planes, int size, const Palette& palette);

/// Whether `file` keeps raw values (an .exr) rather than colours.
bool isRawFieldImage(const std::filesystem::path& file);

/// Writes the planes as colours, or raw values for an EXR (render/image_file.h: atomically; throws
/// IoError naming the file).
void writeFieldImage(const std::filesystem::path& file, const std::vector<FieldPlane>& planes, int size,
                     const Palette& palette);

}  // namespace gridifs
