#include "python/python_arrays.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "python/python_project.h"

namespace gridifs::python {

void CapturedImage::take(const ImageFileLayout& layout, bool isFloat, const void* pixels) {
  layout_ = layout;
  isFloat_ = isFloat;
  taken_ = true;
  const std::size_t values = std::size_t(layout.width) * std::size_t(layout.height) * layout.channels.size();
  if (isFloat) {
    const auto* p = static_cast<const float*>(pixels);
    floats_.assign(p, p + values);
  } else {
    const auto* p = static_cast<const std::uint8_t*>(pixels);
    bytes_.assign(p, p + values);
  }
}

py::array CapturedImage::toArray(bool hdr) const {
  if (!taken_) throw PythonError("the render produced no image.");
  const std::size_t w = std::size_t(layout_.width), h = std::size_t(layout_.height);
  const std::size_t n = w * h, stride = layout_.channels.size();
  // Where R, G, B and A sit in the file's channels (-1: not there).
  int index[4] = {-1, -1, -1, -1};
  const char* names[4] = {"R", "G", "B", "A"};
  for (std::size_t c = 0; c < stride; ++c)
    for (int k = 0; k < 4; ++k)
      if (layout_.channels[c] == names[k]) index[k] = int(c);
  if (hdr) {
    py::array_t<float> out({h, w, std::size_t(4)});
    float* o = out.mutable_data();
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < 4; ++k) {
        const float fallback = k == 3 ? 1.0f : 0.0f;
        if (index[k] < 0)
          o[i * 4 + k] = fallback;
        else if (isFloat_)
          o[i * 4 + k] = floats_[i * stride + std::size_t(index[k])];
        else
          o[i * 4 + k] = bytes_[i * stride + std::size_t(index[k])] / 255.0f;
      }
    return out;
  }
  // 8-bit files hold straight colour: with an alpha channel the image library rounds the
  // premultiplied colour to 8 bits, then divides it by alpha in integers as it writes (PNG's
  // convention), and so does this, so that the array equals the file.
  py::array_t<std::uint8_t> out({h, w, std::size_t(4)});
  std::uint8_t* o = out.mutable_data();
  auto byte = [&](std::size_t i, int channel) -> unsigned {
    if (channel < 0) return 0;
    if (!isFloat_) return bytes_[i * stride + std::size_t(channel)];
    return unsigned(std::lround(std::clamp(floats_[i * stride + std::size_t(channel)], 0.0f, 1.0f) * 255.0f));
  };
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned alpha = index[3] >= 0 ? byte(i, index[3]) : 255u;
    for (int k = 0; k < 3; ++k) {
      const unsigned c = byte(i, index[k]);
      o[i * 4 + k] = std::uint8_t(index[3] >= 0 && alpha > 0 ? std::min(255u, c * 255u / alpha) : c);
    }
    o[i * 4 + 3] = std::uint8_t(alpha);
  }
  return out;
}

PointArrays::PointArrays(std::int64_t count)
    : xyz_({std::size_t(count), std::size_t(3)}),
      rgb_({std::size_t(count), std::size_t(3)}),
      xyzData_(xyz_.mutable_data()),
      rgbData_(rgb_.mutable_data()),
      capacity_(count) {}

void PointArrays::append(const PointBatch& batch) {
  const std::int64_t take = std::min<std::int64_t>(std::int64_t(batch.count), capacity_ - filled_);
  if (take <= 0) return;
  std::memcpy(xyzData_ + filled_ * 3, batch.xyz, std::size_t(take) * 3 * sizeof(float));
  std::memcpy(rgbData_ + filled_ * 3, batch.rgb, std::size_t(take) * 3 * sizeof(float));
  filled_ += take;
}

py::tuple PointArrays::take() {
  if (filled_ < capacity_) {
    const py::slice rows(0, filled_, 1);
    return py::make_tuple(xyz_[rows], rgb_[rows]);
  }
  return py::make_tuple(xyz_, rgb_);
}

py::array volumeArray(DensityVolume volume) {
  const std::size_t r = std::size_t(volume.lattice.n);
  // The array owns the density vector: no copy of a volume that may be 512³ floats.
  auto* owned = new std::vector<float>(std::move(volume.density));
  py::capsule free(owned, [](void* p) { delete static_cast<std::vector<float>*>(p); });
  return py::array_t<float>({r, r, r}, owned->data(), free);
}

py::tuple meshArrays(const IfsMesh& mesh) {
  py::array_t<float> vertices({std::size_t(mesh.n_vertices()), std::size_t(3)});
  float* v = vertices.mutable_data();
  for (auto vh : mesh.vertices()) {
    const auto& p = mesh.point(vh);
    for (int d = 0; d < 3; ++d) v[std::size_t(vh.idx()) * 3 + std::size_t(d)] = float(p[d]);
  }
  std::vector<std::int32_t> triangles;
  triangles.reserve(mesh.n_faces() * 3);
  std::vector<std::int32_t> corners;
  for (auto fh : mesh.faces()) {
    corners.clear();
    for (auto vh : mesh.fv_range(fh)) corners.push_back(vh.idx());
    for (std::size_t k = 1; k + 1 < corners.size(); ++k)
      triangles.insert(triangles.end(), {corners[0], corners[k], corners[k + 1]});
  }
  py::array_t<std::int32_t> faces({triangles.size() / 3, std::size_t(3)});
  std::copy(triangles.begin(), triangles.end(), faces.mutable_data());
  return py::make_tuple(vertices, faces);
}

}  // namespace gridifs::python
