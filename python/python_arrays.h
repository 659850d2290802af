#pragma once
// The module's results as numpy arrays, each filled once from what the core produced: an image as
// the command line would write it, a point cloud, a density volume, a mesh.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <vector>

#include "mesh/ifs_mesh.h"
#include "render/chaos_renderer.h"
#include "render/image_file.h"
#include "volume/density_volume.h"

namespace gridifs::python {

namespace py = pybind11;

/// The keyword options render() takes, for its message about an unknown one.
inline constexpr const char* kRenderOptionNames =
    "width, height, samples, quality, seed, threads, device, time, mode, palette, density_display, supersample, "
    "hue, filter_radius, estimator_radius, estimator_minimum, estimator_curve, transparent, motion_blur, "
    "motion_fade, resolution, hdr and progress";

/// The pixels and layout of the image file a render would have written (render/image_file.h
/// ImageCapture), kept until they become an array; filled without the GIL.
class CapturedImage {
 public:
  void take(const ImageFileLayout& layout, bool isFloat, const void* pixels);
  /// H×W×4: uint8 from an 8-bit layout (alpha 255 where the file has none), float32 R, G, B, A
  /// from a float one (alpha 1 where the file has none). Needs the GIL.
  py::array toArray(bool hdr) const;

 private:
  ImageFileLayout layout_;
  bool isFloat_ = false, taken_ = false;
  std::vector<std::uint8_t> bytes_;
  std::vector<float> floats_;
};

/// The positions and colours of a point cloud, n×3 float32 each, filled batch by batch without the
/// GIL (the arrays are made before it is released).
class PointArrays {
 public:
  explicit PointArrays(std::int64_t count);
  void append(const PointBatch& batch);
  /// (positions, colours), cut to the points received. Needs the GIL.
  py::tuple take();

 private:
  py::array_t<float> xyz_, rgb_;
  float* xyzData_;
  float* rgbData_;
  std::int64_t capacity_, filled_ = 0;
};

/// R×R×R float32 indexed [z, y, x] (x fastest, as the voxels are stored).
py::array volumeArray(DensityVolume volume);

/// (vertices V×3 float32, faces F×3 int32): the mesh's faces as triangles (fans).
py::tuple meshArrays(const IfsMesh& mesh);

}  // namespace gridifs::python
