#include "render/volume_raymarch.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <glm/mat4x4.hpp>

#include "base/parallel.h"
#include "render/camera.h"
#include "render/volume_light.h"

namespace gridifs {
namespace {

/// The transfer function at density d: linear between stops, constant beyond the ends.
TransferStop transferAt(const std::vector<TransferStop>& stops, double d) {
  if (d <= stops.front().density) return stops.front();
  if (d >= stops.back().density) return stops.back();
  std::size_t i = 1;
  while (stops[i].density < d) ++i;
  const TransferStop &a = stops[i - 1], &b = stops[i];
  const double w = b.density > a.density ? (d - a.density) / (b.density - a.density) : 1.0;
  TransferStop out;
  out.density = d;
  out.color = a.color + (b.color - a.color) * w;
  out.opacity = a.opacity + (b.opacity - a.opacity) * w;
  return out;
}

/// The palette at density d, read as a texture of 256 entries with linear filtering would be.
void paletteAt(const std::vector<float>& palette, float d, float* rgb) {
  const float x = std::clamp(d, 0.0f, 1.0f) * 255.0f;
  const int i = std::min(int(x), 254);
  const float w = x - float(i);
  for (int c = 0; c < 3; ++c)
    rgb[c] = palette[3 * std::size_t(i) + std::size_t(c)] * (1.0f - w) +
             palette[3 * std::size_t(i + 1) + std::size_t(c)] * w;
}

/// A per-pixel offset of the first step in [0, 1), so the step pattern reads as fine noise instead
/// of bands. An integer hash of the pixel: the same on every machine and thread count.
float jitter(int x, int y) {
  std::uint32_t h = std::uint32_t(x) * 0x8da6b343u ^ std::uint32_t(y) * 0xd8163841u;
  h ^= h >> 16;
  h *= 0x7feb352du;
  h ^= h >> 15;
  h *= 0x846ca68bu;
  h ^= h >> 16;
  return float(h >> 8) * (1.0f / 16777216.0f);
}

struct Sample {
  float r, g, b, e;
};

/// Trilinear r g b e at voxel coordinates (u, v, w) (voxel centres at integers), 0 outside.
inline Sample sampleAt(const ShadedVolume& s, float u, float v, float w) {
  const int n = s.n;
  const float fu = std::floor(u), fv = std::floor(v), fw = std::floor(w);
  const int i = int(fu), j = int(fv), k = int(fw);
  const float tu = u - fu, tv = v - fv, tw = w - fw;
  const float* base = s.voxels.data();
  const std::size_t sx = 4, sy = 4 * std::size_t(n), sz = 4 * std::size_t(n) * std::size_t(n);
  float c[8][4];
  if (i >= 0 && j >= 0 && k >= 0 && i + 1 < n && j + 1 < n && k + 1 < n) {
    const float* p = base + sx * std::size_t(i) + sy * std::size_t(j) + sz * std::size_t(k);
    for (int corner = 0; corner < 8; ++corner) {
      const float* q = p + ((corner & 1) ? sx : 0) + ((corner & 2) ? sy : 0) + ((corner & 4) ? sz : 0);
      for (int ch = 0; ch < 4; ++ch) c[corner][ch] = q[ch];
    }
  } else {
    for (int corner = 0; corner < 8; ++corner) {
      const int a = i + (corner & 1), b = j + ((corner >> 1) & 1), d = k + ((corner >> 2) & 1);
      const bool inside = a >= 0 && b >= 0 && d >= 0 && a < n && b < n && d < n;
      for (int ch = 0; ch < 4; ++ch)
        c[corner][ch] =
            inside ? base[sx * std::size_t(a) + sy * std::size_t(b) + sz * std::size_t(d) + std::size_t(ch)] : 0.0f;
    }
  }
  float out[4];
  for (int ch = 0; ch < 4; ++ch) {
    const float x00 = c[0][ch] + (c[1][ch] - c[0][ch]) * tu, x10 = c[2][ch] + (c[3][ch] - c[2][ch]) * tu;
    const float x01 = c[4][ch] + (c[5][ch] - c[4][ch]) * tu, x11 = c[6][ch] + (c[7][ch] - c[6][ch]) * tu;
    const float y0 = x00 + (x10 - x00) * tv, y1 = x01 + (x11 - x01) * tv;
    out[ch] = y0 + (y1 - y0) * tw;
  }
  return {out[0], out[1], out[2], out[3]};
}

/// One ray's result.
struct RayResult {
  float r = 0, g = 0, b = 0, alpha = 0, depth = kEmptyVolumeDepth;
};

struct Ray {
  double u[3], du[3];  // voxel coordinates at t and per world unit
  double depth0, ddepth;
  double enter, leave;
};

RayResult marchRay(const ShadedVolume& s, const Ray& ray, double step, float offset) {
  RayResult out;
  float transmittance = 1.0f, weight = 0.0f, weightedDepth = 0.0f;
  const int B = kVolumeBlock, nb = s.blocks;
  const double length = ray.leave - ray.enter;
  const std::int64_t steps = std::int64_t(std::ceil(length / step)) + 1;
  for (std::int64_t k = 0; k < steps; ++k) {
    const double t = ray.enter + (double(k) + offset) * step;
    if (t >= ray.leave) break;
    const double u = ray.u[0] + ray.du[0] * t, v = ray.u[1] + ray.du[1] * t, w = ray.u[2] + ray.du[2] * t;
    const int fu = int(std::floor(u)), fv = int(std::floor(v)), fw = int(std::floor(w));
    const int bu = std::clamp(fu < 0 ? -1 : fu / B, 0, nb - 1), bv = std::clamp(fv < 0 ? -1 : fv / B, 0, nb - 1),
              bw = std::clamp(fw < 0 ? -1 : fw / B, 0, nb - 1);
    if (!s.occupied[std::size_t(bu) + std::size_t(nb) * (std::size_t(bv) + std::size_t(nb) * std::size_t(bw))]) {
      // Empty-space skipping: on to the first step past this block's cell.
      const int cell[3] = {bu, bv, bw};
      const double p[3] = {u, v, w};
      double exit = ray.leave;
      for (int a = 0; a < 3; ++a) {
        if (ray.du[a] == 0.0) continue;
        double lo = double(cell[a] * B), hi = double(cell[a] * B + B);
        if (cell[a] == 0) lo = -1e30;  // the first and last blocks reach out to the volume's edges
        if (cell[a] == nb - 1) hi = 1e30;
        const double bound = ray.du[a] > 0.0 ? hi : lo;
        exit = std::min(exit, t + (bound - p[a]) / ray.du[a]);
      }
      const std::int64_t next = std::int64_t(std::ceil((exit - ray.enter) / step - double(offset)));
      k = std::max(k, next - 1);
      continue;
    }
    const Sample x = sampleAt(s, float(u), float(v), float(w));
    if (x.e <= 0.0f) continue;
    const float alpha = 1.0f - std::exp(-x.e * float(step));
    const float contribution = transmittance * alpha, toColor = contribution / x.e;
    out.r += toColor * x.r;
    out.g += toColor * x.g;
    out.b += toColor * x.b;
    weight += contribution;
    weightedDepth += contribution * float(ray.depth0 + ray.ddepth * t);
    transmittance *= 1.0f - alpha;
    if (transmittance < 0.004f) break;  // what lies behind is invisible
  }
  out.alpha = 1.0f - transmittance;
  if (weight > 0.0f) out.depth = weightedDepth / weight;
  return out;
}

}  // namespace

VolumeLook volumeLookOf(const Project& project) {
  VolumeLook look;
  look.settings = project.render.volume.value_or(VolumeRenderSettings{});
  const auto& lights = project.render.shading.lights;
  // The key light of the shading settings, so the volume and the shaded display agree.
  const ShadingLight key = lights.empty() ? ShadingLight{} : lights[0];
  look.towardLight = key.direction;
  look.lightColor = lights.empty() ? Vec3(1.0) : key.color * key.intensity;
  look.ambient = project.render.shading.ambient;
  look.background = project.render.background;
  return look;
}

ClassifiedVolume classifyVolume(const VolumeSource& source, const VolumeLook& look, int threads) {
  ClassifiedVolume out;
  out.n = source.n;
  const std::size_t count = std::size_t(source.n) * std::size_t(source.n) * std::size_t(source.n);
  if (source.n <= 0 || source.density.size() != count) return out;
  out.albedo.assign(count * 3, 1.0f);
  out.opacity.assign(count, 0.0f);
  const auto& transfer = look.settings.transfer;
  const bool hasColor = source.color.size() == count * 3, hasPalette = look.palette.size() == 256 * 3;
  parallelFor(count, threads, 1 << 15, [&](std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v) {
      const float d = source.density[v];
      // Unvisited voxels stay empty whatever the transfer function says: it shapes the measure
      // attractor's cloud, it does not fill X.
      if (!(d > 0.0f)) continue;
      float* albedo = &out.albedo[3 * v];
      if (!transfer.empty()) {
        const TransferStop t = transferAt(transfer, d);
        out.opacity[v] = float(std::clamp(t.opacity, 0.0, 1.0));
        for (int c = 0; c < 3; ++c) albedo[c] = float(t.color[c]);
      } else {
        out.opacity[v] = std::min(d, 1.0f);
        if (hasColor)
          for (int c = 0; c < 3; ++c) albedo[c] = source.color[3 * v + std::size_t(c)];
        else if (hasPalette)
          paletteAt(look.palette, d, albedo);
      }
    }
  });
  out.lightDepth = lightOpticalDepth(out.opacity, out.n, look.towardLight, threads);
  return out;
}

ShadedVolume shadeVolume(const ClassifiedVolume& c, const VolumeLook& look, int threads) {
  ShadedVolume out;
  out.n = c.n;
  const int n = c.n;
  const std::size_t count = std::size_t(n) * std::size_t(n) * std::size_t(n);
  if (n <= 0 || c.opacity.size() != count) return out;
  out.voxels.assign(count * 4, 0.0f);
  const float sigma = float(look.settings.density_scale), ambient = float(look.ambient);
  const bool lit = look.settings.display == VolumeDisplay::Lit;
  const glm::vec3 light(look.lightColor);
  parallelFor(count, threads, 1 << 15, [&](std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v) {
      if (!(c.opacity[v] > 0.0f)) continue;
      float* o = &out.voxels[4 * v];
      const float extinction = sigma * c.opacity[v];
      // Emission is stored weighted by the extinction, so that interpolation between a voxel and
      // an empty neighbour keeps the voxel's colour (no dark fringe); the march divides it out.
      if (lit) {
        // Beer–Lambert self-shadowing: the light reaching the voxel is exp(-σ · depth).
        const float shadow = std::exp(-sigma * c.lightDepth[v]);
        for (int ch = 0; ch < 3; ++ch)
          o[ch] = extinction * c.albedo[3 * v + std::size_t(ch)] * (ambient + light[ch] * shadow);
      } else {
        o[0] = o[1] = o[2] = extinction;  // X-ray: what is left is 1 - exp(-σ ∫ opacity ds), grey
      }
      o[3] = extinction;
    }
  });
  // Occupied blocks (with a one-voxel apron: a sample reads the next voxel too) and the bounds.
  const int B = kVolumeBlock;
  out.blocks = std::max(1, (n + B - 1) / B);
  const int nb = out.blocks;
  out.occupied.assign(std::size_t(nb) * nb * nb, 0);
  for (int a = 0; a < 3; ++a) out.lo[a] = n, out.hi[a] = -1;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        if (!(out.voxels[4 * (std::size_t(i) + std::size_t(n) * (std::size_t(j) + std::size_t(n) * std::size_t(k))) +
                         3] > 0.0f))
          continue;
        const int idx[3] = {i, j, k};
        for (int a = 0; a < 3; ++a) {
          out.lo[a] = std::min(out.lo[a], idx[a]);
          out.hi[a] = std::max(out.hi[a], idx[a]);
        }
        for (int dk = -1; dk <= 0; ++dk)
          for (int dj = -1; dj <= 0; ++dj)
            for (int di = -1; di <= 0; ++di) {
              // Voxel (i, j, k) is read by samples whose lower corner is (i + di, …).
              const int a = i + di, b = j + dj, d = k + dk;
              const int ba = std::clamp(a < 0 ? 0 : a / B, 0, nb - 1), bb = std::clamp(b < 0 ? 0 : b / B, 0, nb - 1),
                        bd = std::clamp(d < 0 ? 0 : d / B, 0, nb - 1);
              out.occupied[std::size_t(ba) + std::size_t(nb) * (std::size_t(bb) + std::size_t(nb) * std::size_t(bd))] =
                  1;
            }
      }
  return out;
}

std::vector<std::uint8_t> VolumeImage::composited(const Vec3& background) const {
  const std::size_t count = std::size_t(width) * std::size_t(height);
  std::vector<std::uint8_t> out(count * 4, 255);
  for (std::size_t p = 0; p < count; ++p) {
    const float t = 1.0f - rgba[4 * p + 3];
    for (int c = 0; c < 3; ++c) {
      const float value = rgba[4 * p + std::size_t(c)] + t * float(background[c]);
      out[4 * p + std::size_t(c)] = std::uint8_t(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f));
    }
  }
  return out;
}

VolumeImage marchVolume(const ShadedVolume& s, const VolumeLook& look, const Camera& camera, int width, int height,
                        int threads) {
  (void)look;
  const OrbitCamera cam(camera, width, height);
  VolumeImage image;
  image.width = width;
  image.height = height;
  image.rgba.assign(std::size_t(width) * std::size_t(height) * 4, 0.0f);
  image.depth.assign(std::size_t(width) * std::size_t(height), kEmptyVolumeDepth);
  const int n = s.n;
  if (n <= 0 || s.hi[0] < s.lo[0]) return image;
  const glm::dmat4 inverse = glm::inverse(cam.projection() * cam.view());
  const glm::dmat4& view = cam.view();
  // Panoramic cameras and stereo eyes take each pixel's ray from the camera; one flat eye keeps
  // the matrix inverse (the same rays, the images as before).
  const bool viaRays = cam.panoramic() || cam.eyes() == 2;
  // The box a sample can see extinction in: the occupied voxels' centres ± one voxel (trilinear
  // support), in world coordinates.
  double boxLo[3], boxHi[3];
  for (int a = 0; a < 3; ++a) {
    boxLo[a] = std::max(-1.0, -1.0 + (2.0 * s.lo[a] + 1.0) / n - 2.0 / n);
    boxHi[a] = std::min(1.0, -1.0 + (2.0 * s.hi[a] + 1.0) / n + 2.0 / n);
  }
  // Half a voxel per step: with trilinear interpolation the ray sees every voxel it crosses.
  const double step = 1.0 / double(n);
  const double toVoxel = double(n) / 2.0;
  parallelFor(std::size_t(height), threads, 1, [&](std::size_t rowBegin, std::size_t rowEnd) {
    for (std::size_t row = rowBegin; row < rowEnd; ++row) {
      for (int x = 0; x < width; ++x) {
        glm::dvec3 origin, direction;
        double depth0 = 0.0, ddepth = 1.0;  // panoramic and stereo: the distance along the ray
        if (viaRays) {
          const PixelRay pixel = cam.rayThrough(x + 0.5, double(row) + 0.5);
          if (!pixel.valid) continue;
          origin = pixel.origin;
          direction = glm::normalize(pixel.step);
          if (!cam.panoramic()) {
            depth0 = -(view * glm::dvec4(origin, 1.0)).z;
            ddepth = -(view * glm::dvec4(direction, 0.0)).z;
          }
        } else {
          const double nx = 2.0 * (x + 0.5) / width - 1.0, ny = 1.0 - 2.0 * (double(row) + 0.5) / height;
          const glm::dvec4 a = inverse * glm::dvec4(nx, ny, -1.0, 1.0), b = inverse * glm::dvec4(nx, ny, 1.0, 1.0);
          origin = glm::dvec3(a) / a.w;
          direction = glm::normalize(glm::dvec3(b) / b.w - origin);
          // View depth: -z of view space, linear along the ray.
          depth0 = -(view * glm::dvec4(origin, 1.0)).z;
          ddepth = -(view * glm::dvec4(direction, 0.0)).z;
        }
        double enter = 0.0, leave = 1e300;
        bool hit = true;
        for (int ax = 0; ax < 3 && hit; ++ax) {
          if (direction[ax] == 0.0) {
            hit = origin[ax] >= boxLo[ax] && origin[ax] <= boxHi[ax];
            continue;
          }
          double t0 = (boxLo[ax] - origin[ax]) / direction[ax], t1 = (boxHi[ax] - origin[ax]) / direction[ax];
          if (t0 > t1) std::swap(t0, t1);
          enter = std::max(enter, t0);
          leave = std::min(leave, t1);
          hit = leave > enter;
        }
        if (!hit) continue;
        Ray ray;
        for (int ax = 0; ax < 3; ++ax) {
          ray.u[ax] = (origin[ax] + 1.0) * toVoxel - 0.5;
          ray.du[ax] = direction[ax] * toVoxel;
        }
        ray.depth0 = depth0;
        ray.ddepth = ddepth;
        ray.enter = enter;
        ray.leave = leave;
        const RayResult r = marchRay(s, ray, step, jitter(x, int(row)));
        const std::size_t p = row * std::size_t(width) + std::size_t(x);
        image.rgba[4 * p + 0] = r.r;
        image.rgba[4 * p + 1] = r.g;
        image.rgba[4 * p + 2] = r.b;
        image.rgba[4 * p + 3] = r.alpha;
        image.depth[p] = r.depth;
      }
    }
  });
  return image;
}

VolumeImage renderVolumeImage(const VolumeSource& source, const VolumeLook& look, const Camera& camera, int width,
                              int height, int threads) {
  ShadedVolume shaded;
  {
    const ClassifiedVolume classified = classifyVolume(source, look, threads);
    shaded = shadeVolume(classified, look, threads);
  }
  return marchVolume(shaded, look, camera, width, height, threads);
}

}  // namespace gridifs
