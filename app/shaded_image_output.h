#pragma once
// Writing the shaded display (core/render/shaded_image.h) through OpenImageIO: PNG/TIFF as 8-bit
// RGB over the background; EXR as float R G B A (linear, premultiplied) + Z + the compositing
// channels N.x N.y N.z (world-space normal), AO (ambient light that reaches the pixel) and
// shadow (light visibility), P (world position) and the camera's OpenEXR matrices.
#include <filesystem>
#include <string>

#include "render/shaded_image.h"

namespace gridifs::cli {

/// Writes atomically (a temporary file renamed over `out`). An EXR also carries P (the world
/// position each pixel's centre sees) and `camera`'s matrices (render/camera.h). Throws
/// CliError(1) when the file cannot be written.
void writeShadedImage(const ShadedImage& image, const RenderImage& snapshot, const Camera& camera,
                      const std::filesystem::path& out, const std::string& description);

}  // namespace gridifs::cli
