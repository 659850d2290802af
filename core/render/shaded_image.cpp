#include "render/shaded_image.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <limits>

#include "base/color_space.h"
#include "base/parallel.h"
#include "render/camera.h"

namespace gridifs {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr int kSmoothRadius = 2;
constexpr float kSmoothWeights[kSmoothRadius + 1] = {3.0f, 2.0f, 1.0f};
/// A neighbour belongs to the same surface when its depth differs by less than this many pixel
/// footprints per pixel of distance (a surface tilted by 80° steps about 5.7 footprints a pixel).
constexpr float kEdgeFootprints = 6.0f;
constexpr int kAoSteps = 4;
/// Occlusion below this sine of elevation above the tangent plane is ignored, so that the
/// remaining depth noise of a flat surface does not darken it (Bavoil et al.'s angle bias).
constexpr float kAoAngleBias = 0.15f;
constexpr int kPattern = 4;  // 4×4 interleaved rotations and step offsets of the occlusion rays

struct Vec3f {
  float x, y, z;
};
inline Vec3f operator-(Vec3f a, Vec3f b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline float dot(Vec3f a, Vec3f b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3f cross(Vec3f a, Vec3f b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline Vec3f normalized(Vec3f a) {
  const float l = std::sqrt(dot(a, a));
  return l > 0.0f ? Vec3f{a.x / l, a.y / l, a.z / l} : Vec3f{0.0f, 0.0f, 1.0f};
}

/// Pixel → view-space position (the camera looks down −z): x = ndc_x · sx · k(d), k = d for a
/// perspective camera and 1 for an orthographic one.
struct Unproject {
  float ax, bx, ay, by;  // ndc = a·pixel + b (pixel centres)
  float sx, sy;
  bool perspective;
  float footA, footB;  // world units per pixel at depth d: footA·d + footB
  /// Panoramic and stereo cameras: each pixel's view-space ray (origin xyz, step xyz), the
  /// point at depth d being origin + step·d (OrbitCamera::rayThrough); empty for one flat eye.
  std::vector<std::array<float, 6>> rays;
  int width = 0;
  Vec3f at(int px, int py, float d) const {
    if (!rays.empty()) {
      const std::array<float, 6>& r = rays[std::size_t(py) * std::size_t(width) + std::size_t(px)];
      return {r[0] + r[3] * d, r[1] + r[4] * d, r[2] + r[5] * d};
    }
    const float k = perspective ? d : 1.0f;
    return {(ax * float(px) + bx) * sx * k, (ay * float(py) + by) * sy * k, -d};
  }
  /// The unit vector from the point seen at pixel (px, py) towards the eye.
  Vec3f towardsEye(int px, int py, Vec3f p) const {
    if (!rays.empty()) {
      const std::array<float, 6>& r = rays[std::size_t(py) * std::size_t(width) + std::size_t(px)];
      return normalized(Vec3f{-r[3], -r[4], -r[5]});
    }
    return perspective ? normalized(Vec3f{-p.x, -p.y, -p.z}) : Vec3f{0.0f, 0.0f, 1.0f};
  }
  float footprint(float d) const { return footA * d + footB; }
};

struct ShadowLight {
  std::size_t settingsIndex;
  const std::vector<float>* depth;
  int size;
  float texel;
  float rowU[4], rowV[4], rowD[4];  // view space → (u, v, light depth)
};

struct DevelopContext {
  int width, height;
  Unproject un;
  const float* depth;  // smoothed
  const std::uint8_t* albedo;
  std::array<float, 256> srgbLut;
  struct Light {
    Vec3f direction;  // view space, unit
    Vec3f half;       // Blinn's half vector (view direction approximated per pixel below)
    float r, g, b;    // linear colour × intensity
    int shadow = -1;  // index into shadows, or -1
  };
  std::vector<Light> lights;
  std::vector<ShadowLight> shadows;
  float shadowWeight = 0.0f;  // Σ intensity of the shadowed lights
  float ambient, specular, shininess;
  float aoRadius, aoStrength;
  int aoDirections;
  /// Pixel offsets of the occlusion samples: kPattern² patterns × directions × kAoSteps.
  std::vector<std::array<int, 2>> aoOffsets;
  std::array<float, 3>* viewNormals = nullptr;  // per pixel (valid where covered)
  int blocksX = 0, blocksY = 0;                 // 2×2 blocks of the occlusion
  float* blockAo = nullptr;                     // per block: occlusion
  float* blockDepth = nullptr;                  // per block: the depth it was computed at
  std::array<float, 1025> specularTable;        // x^shininess over [0, 1]
  float fogR, fogG, fogB, fogDensity;
  std::uint8_t bgBytes[4];  // the background's display colour, alpha 0
  float viewToWorld[3][3];
};

float shadowVisibility(const ShadowLight& s, Vec3f p, float bias) {
  const float u = s.rowU[0] * p.x + s.rowU[1] * p.y + s.rowU[2] * p.z + s.rowU[3];
  const float v = s.rowV[0] * p.x + s.rowV[1] * p.y + s.rowV[2] * p.z + s.rowV[3];
  const float d = s.rowD[0] * p.x + s.rowD[1] * p.y + s.rowD[2] * p.z + s.rowD[3] - bias;
  const int iu = int(std::floor(u)), iv = int(std::floor(v));
  const float* map = s.depth->data();
  if (iu >= 1 && iv >= 1 && iu < s.size - 1 && iv < s.size - 1) {
    // Inside the map (nearly every lookup): all nine taps, no bounds tests.
    const float* row = map + std::size_t(iv - 1) * std::size_t(s.size) + std::size_t(iu - 1);
    int lit = 0;
    for (int dv = 0; dv < 3; ++dv, row += s.size) lit += int(row[0] >= d) + int(row[1] >= d) + int(row[2] >= d);
    return float(lit) * (1.0f / 9.0f);
  }
  int lit = 0, taps = 0;
  for (int dv = -1; dv <= 1; ++dv) {
    const int y = iv + dv;
    if (y < 0 || y >= s.size) continue;
    for (int du = -1; du <= 1; ++du) {
      const int x = iu + du;
      if (x < 0 || x >= s.size) continue;
      ++taps;
      lit += map[std::size_t(y) * std::size_t(s.size) + std::size_t(x)] >= d;
    }
  }
  return taps ? float(lit) / float(taps) : 1.0f;
}

/// Edge-aware smoothing along one axis: a weighted mean of the neighbours on the same surface.
void smoothPass(const float* in, float* out, int width, int height, const Unproject& un, bool vertical,
                std::size_t rowBegin, std::size_t rowEnd) {
  for (std::size_t y = rowBegin; y < rowEnd; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t i = y * std::size_t(width) + std::size_t(x);
      const float d = in[i];
      if (d == kInf) {
        out[i] = kInf;
        continue;
      }
      const float tolerance = kEdgeFootprints * un.footprint(d);
      float sum = d * kSmoothWeights[0], weight = kSmoothWeights[0];
      for (int o = 1; o <= kSmoothRadius; ++o)
        for (int sign = -1; sign <= 1; sign += 2) {
          const int nx = vertical ? x : x + sign * o, ny = vertical ? int(y) + sign * o : int(y);
          if (nx < 0 || nx >= width || ny < 0 || ny >= height) continue;
          const float n = in[std::size_t(ny) * std::size_t(width) + std::size_t(nx)];
          if (!(std::abs(n - d) <= tolerance * float(o))) continue;  // other surface or empty
          sum += n * kSmoothWeights[o];
          weight += kSmoothWeights[o];
        }
      out[i] = sum / weight;
    }
}

/// The screen-space difference along one axis: the neighbour on the same surface with the smaller
/// depth step (forward or backward), as a vector pointing in the +axis direction; false when neither
/// side is on the surface.
bool difference(const DevelopContext& c, int x, int y, int dx, int dy, float d, Vec3f p, float tolerance, Vec3f& out) {
  float best = tolerance;
  bool found = false;
  for (int sign = -1; sign <= 1; sign += 2) {
    const int nx = x + sign * dx, ny = y + sign * dy;
    if (nx < 0 || nx >= c.width || ny < 0 || ny >= c.height) continue;
    const float n = c.depth[std::size_t(ny) * std::size_t(c.width) + std::size_t(nx)];
    const float step = std::abs(n - d);
    if (!(step <= best)) continue;
    best = step;
    found = true;
    const Vec3f q = c.un.at(nx, ny, n);
    out = sign > 0 ? q - p : p - q;
  }
  return found;
}

float ambientOcclusion(const DevelopContext& c, int x, int y, Vec3f p, Vec3f n, float d) {
  const float worldRadius = c.aoRadius * c.un.footprint(d);
  const float r2 = worldRadius * worldRadius, inverseR2 = 1.0f / r2;
  const int pattern = (y % kPattern) * kPattern + (x % kPattern);
  const std::array<int, 2>* offsets = &c.aoOffsets[std::size_t(pattern) * std::size_t(c.aoDirections * kAoSteps)];
  float sum = 0.0f;
  for (int k = 0; k < c.aoDirections; ++k) {
    float horizon = 0.0f;
    for (int s = 0; s < kAoSteps; ++s) {
      const std::array<int, 2> o = offsets[k * kAoSteps + s];
      const int sx = x + o[0], sy = y + o[1];
      if (unsigned(sx) >= unsigned(c.width) || unsigned(sy) >= unsigned(c.height)) break;
      // Branch-free over the sample's cases (empty, beyond the radius, below the tangent plane):
      // they alternate unpredictably on a speckled attractor. An empty pixel's +inf depth makes
      // l2 infinite or NaN, which fails the test below.
      const float sd = c.depth[std::size_t(sy) * std::size_t(c.width) + std::size_t(sx)];
      const Vec3f v = c.un.at(sx, sy, sd) - p;
      const float l2 = dot(v, v), vn = dot(v, n);
      // Sine of the elevation of the sample above the tangent plane, fading out with distance.
      const float rise = (vn / std::sqrt(l2) - kAoAngleBias) * (1.0f - l2 * inverseR2);
      const bool counts = (l2 < r2) & (vn > 0.0f) & (rise > horizon);
      horizon = counts ? rise : horizon;
    }
    sum += horizon;
  }
  return std::clamp(1.0f - c.aoStrength * sum / float(c.aoDirections), 0.0f, 1.0f);
}

/// Linear light → 8-bit sRGB through a table over [0, 1] (4096 steps: finer than the 8-bit
/// output's steps everywhere but the darkest few codes, where the curve is linear anyway).
constexpr int kDisplaySteps = 4096;
struct DisplayTable {
  std::array<std::uint8_t, kDisplaySteps + 1> code;
  DisplayTable() {
    for (int i = 0; i <= kDisplaySteps; ++i) {
      const double v = double(i) / kDisplaySteps;
      const double s = v <= 0.0031308 ? v * 12.92 : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
      code[std::size_t(i)] = std::uint8_t(s * 255.0 + 0.5);
    }
  }
};
const DisplayTable kDisplay;

inline std::uint8_t toDisplay8(float linear) {
  const float v = linear > 0.0f ? (linear < 1.0f ? linear : 1.0f) : 0.0f;  // NaN → 0
  return kDisplay.code[std::size_t(v * float(kDisplaySteps) + 0.5f)];
}

/// The view-space normal of pixel (x, y) at smoothed depth d (facing the camera).
Vec3f viewNormal(const DevelopContext& c, int x, int y, float d) {
  const Vec3f p = c.un.at(x, y, d);
  const float tolerance = kEdgeFootprints * c.un.footprint(d);
  Vec3f dx{}, dy{}, n{0.0f, 0.0f, 1.0f};
  // Rows go down the image, so the upward difference is the negative of the +y one.
  if (difference(c, x, y, 1, 0, d, p, tolerance, dx) && difference(c, x, y, 0, 1, d, p, tolerance, dy))
    n = normalized(cross(dx, Vec3f{-dy.x, -dy.y, -dy.z}));
  const bool away = dot(n, c.un.towardsEye(x, y, p)) < 0.0f;
  return away ? Vec3f{-n.x, -n.y, -n.z} : n;
}

void normalRows(DevelopContext& c, std::size_t rowBegin, std::size_t rowEnd) {
  for (std::size_t y = rowBegin; y < rowEnd; ++y)
    for (int x = 0; x < c.width; ++x) {
      const std::size_t i = y * std::size_t(c.width) + std::size_t(x);
      if (c.depth[i] == kInf) continue;
      const Vec3f n = viewNormal(c, x, int(y), c.depth[i]);
      c.viewNormals[i] = {n.x, n.y, n.z};
    }
}

/// Occlusion changes slowly across a surface: it is computed once per 2×2 block (at the block's
/// first covered pixel) and the block's other pixels on the same surface reuse it.
void blockOcclusionRows(DevelopContext& c, std::size_t blockRowBegin, std::size_t blockRowEnd) {
  for (std::size_t by = blockRowBegin; by < blockRowEnd; ++by)
    for (int bx = 0; bx < c.blocksX; ++bx) {
      const std::size_t block = by * std::size_t(c.blocksX) + std::size_t(bx);
      c.blockDepth[block] = kInf;
      c.blockAo[block] = 1.0f;
      for (int k = 0; k < 4; ++k) {
        const int x = 2 * bx + (k & 1), y = 2 * int(by) + (k >> 1);
        if (x >= c.width || y >= c.height) continue;
        const std::size_t i = std::size_t(y) * std::size_t(c.width) + std::size_t(x);
        const float d = c.depth[i];
        if (d == kInf) continue;
        c.blockDepth[block] = d;
        const std::array<float, 3>& n = c.viewNormals[i];
        c.blockAo[block] = ambientOcclusion(c, x, y, c.un.at(x, y, d), Vec3f{n[0], n[1], n[2]}, d);
        break;
      }
    }
}

template <bool kCompositing>
void shadeRows(const DevelopContext& c, ShadedImage& out, std::size_t rowBegin, std::size_t rowEnd) {
  // Raw pointers held in locals: byte stores through out.rgba would otherwise make the compiler
  // reload every vector's data pointer after each store.
  std::uint8_t* const rgba = out.rgba.data();
  float* const linear = out.linear.data();
  float* const normals = out.normals.data();
  float* const occlusion = out.occlusion.data();
  float* const shadow = out.shadow.data();
  for (std::size_t yy = rowBegin; yy < rowEnd; ++yy) {
    const int y = int(yy);
    for (int x = 0; x < c.width; ++x) {
      const std::size_t i = yy * std::size_t(c.width) + std::size_t(x);
      const float d = c.depth[i];
      if (d == kInf) {
        std::memcpy(rgba + i * 4, c.bgBytes, 4);
        if constexpr (kCompositing) {
          for (int k = 0; k < 4; ++k) linear[i * 4 + std::size_t(k)] = 0.0f;
          for (int k = 0; k < 3; ++k) normals[i * 3 + std::size_t(k)] = 0.0f;
          occlusion[i] = 1.0f;
          shadow[i] = 1.0f;
        }
        continue;
      }
      const Vec3f p = c.un.at(x, y, d);
      const float foot = c.un.footprint(d);
      const Vec3f n{c.viewNormals[i][0], c.viewNormals[i][1], c.viewNormals[i][2]};
      const Vec3f view = c.un.towardsEye(x, int(y), p);
      float ao = 1.0f;
      if (c.aoStrength > 0.0f && c.aoRadius > 0.0f) {
        // The block's occlusion where this pixel lies on the block's surface; its own at edges.
        const std::size_t block = std::size_t(y / 2) * std::size_t(c.blocksX) + std::size_t(x / 2);
        ao = std::abs(c.blockDepth[block] - d) <= kEdgeFootprints * foot ? c.blockAo[block]
                                                                         : ambientOcclusion(c, x, y, p, n, d);
      }
      const float ar = c.srgbLut[c.albedo[i * 4 + 0]], ag = c.srgbLut[c.albedo[i * 4 + 1]],
                  ab = c.srgbLut[c.albedo[i * 4 + 2]];
      float diffR = c.ambient * ao, diffG = diffR, diffB = diffR;
      float specR = 0.0f, specG = 0.0f, specB = 0.0f;
      float visibility = 0.0f;
      for (const DevelopContext::Light& light : c.lights) {
        const float lambert = dot(n, light.direction);
        float lit = lambert > 0.0f ? 1.0f : 0.0f;
        if (light.shadow >= 0) {
          const ShadowLight& s = c.shadows[std::size_t(light.shadow)];
          if (lambert > 0.0f) {
            // The light's nearest sample in a texel can be nearer than this point by the texel's
            // width times the slope; plus the camera's own footprint.
            const float cosine = std::clamp(lambert, 0.2f, 1.0f);  // a unit dot product can round above 1
            const float slope = std::sqrt(std::max(0.0f, 1.0f - cosine * cosine)) / cosine;
            lit = shadowVisibility(s, p, s.texel * (1.5f + 1.5f * slope) + 2.0f * foot);
          }
          visibility += lit * (light.r + light.g + light.b);
        }
        if (lambert <= 0.0f || lit <= 0.0f) continue;
        const float diffuse = lambert * lit;
        diffR += light.r * diffuse;
        diffG += light.g * diffuse;
        diffB += light.b * diffuse;
        if (c.specular > 0.0f) {
          const Vec3f h =
              normalized(Vec3f{light.direction.x + view.x, light.direction.y + view.y, light.direction.z + view.z});
          const float nh = dot(n, h);
          if (nh > 0.0f) {
            const float t = nh * 1024.0f;
            const int k = std::min(int(t), 1023);
            const float power =
                c.specularTable[std::size_t(k)] +
                (c.specularTable[std::size_t(k) + 1] - c.specularTable[std::size_t(k)]) * (t - float(k));
            const float sp = c.specular * power * lit;
            specR += light.r * sp;
            specG += light.g * sp;
            specB += light.b * sp;
          }
        }
      }
      float r = ar * diffR + specR, g = ag * diffG + specG, b = ab * diffB + specB;
      if (c.fogDensity > 0.0f) {
        const float keep = std::exp(-c.fogDensity * d);
        r = c.fogR + (r - c.fogR) * keep;
        g = c.fogG + (g - c.fogG) * keep;
        b = c.fogB + (b - c.fogB) * keep;
      }
      rgba[i * 4 + 0] = toDisplay8(r);
      rgba[i * 4 + 1] = toDisplay8(g);
      rgba[i * 4 + 2] = toDisplay8(b);
      rgba[i * 4 + 3] = 255;
      if constexpr (kCompositing) {
        linear[i * 4 + 0] = r;
        linear[i * 4 + 1] = g;
        linear[i * 4 + 2] = b;
        linear[i * 4 + 3] = 1.0f;
        for (int row = 0; row < 3; ++row)
          normals[i * 3 + std::size_t(row)] =
              c.viewToWorld[row][0] * n.x + c.viewToWorld[row][1] * n.y + c.viewToWorld[row][2] * n.z;
        occlusion[i] = ao;
        shadow[i] = c.shadowWeight > 0.0f ? visibility / c.shadowWeight : 1.0f;
      }
    }
  }
}

}  // namespace

DisplaySettings shadedDisplaySettings(const Project& project) {
  return DisplaySettings{project.render.background, 0.0};
}

// Half the longer side: the 3×3 percentage-closer lookup softens a shadow's edge over a few texels
// anyway, and a 512² map of 16-bit depths (512 KiB at 1024²) stays in a core's L2 cache while
// every sample writes to a random texel of it.
int shadowMapSize(int width, int height) { return std::clamp(std::max(width, height) / 2, 256, 2048); }

RenderJob shadedRenderJob(const RenderJob& job, const ShadingSettings& settings, const CompiledIfs& ifs) {
  RenderJob out = job;
  out.shadowLights.clear();
  const BoundingSphere bounds = attractorBounds(ifs);
  const int size = shadowMapSize(job.width, job.height);
  for (std::size_t l = 0; l < settings.lights.size(); ++l)
    if (settings.lights[l].shadows) {
      try {
        out.shadowLights.emplace_back(settings.lights[l].direction, bounds, size);
      } catch (const ModelError& e) {
        throw e.under("render.shading.lights[" + std::to_string(l) + "]");
      }
    }
  out.dofAperture = settings.dof.focus ? settings.dof.aperture : 0.0;
  out.dofFocus = settings.dof.focus.value_or(0.0);
  return out;
}

void developShaded(const RenderImage& snapshot, const ShadingSettings& settings, const Camera& camera,
                   const Vec3& background, int threads, ShadedImage& out, ShadedChannels channels) {
  const int width = snapshot.width, height = snapshot.height;
  const std::size_t n = std::size_t(width) * std::size_t(height);
  out.width = width;
  out.height = height;
  const bool compositing = channels == ShadedChannels::All;
  out.rgba.resize(n * 4);
  out.linear.resize(compositing ? n * 4 : 0);
  out.normals.resize(compositing ? n * 3 : 0);
  out.occlusion.resize(compositing ? n : 0);
  out.shadow.resize(compositing ? n : 0);
  if (n == 0) return;
  if (snapshot.depth.size() != n || snapshot.rgba.size() != n * 4)
    throw ModelError("", "the snapshot's buffers do not match its size");

  const OrbitCamera orbit(camera, width, height);
  DevelopContext c{};
  c.width = width;
  c.height = height;
  const glm::dmat4& proj = orbit.projection();
  c.un.ax = 2.0f / float(width);
  c.un.bx = 1.0f / float(width) - 1.0f;
  c.un.ay = -2.0f / float(height);
  c.un.by = 1.0f - 1.0f / float(height);
  c.un.sx = float(1.0 / proj[0][0]);
  c.un.sy = float(1.0 / proj[1][1]);
  c.un.perspective = !camera.orthographic();
  c.un.footA = c.un.perspective ? 2.0f * c.un.sy / float(orbit.eyeRegion(0).height) : 0.0f;
  c.un.footB = c.un.perspective ? 0.0f : 2.0f * c.un.sy / float(orbit.eyeRegion(0).height);
  if (orbit.panoramic() || orbit.eyes() == 2) {
    if (orbit.panoramic()) c.un.footA = float(1.0 / orbit.pixelsPerRadian());
    c.un.width = width;
    c.un.rays.resize(n);
    const glm::dmat4& toView = orbit.view();
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const PixelRay ray = orbit.rayThrough(x + 0.5, y + 0.5);
        const glm::dvec3 origin(toView * glm::dvec4(ray.origin, 1.0)), step(toView * glm::dvec4(ray.step, 0.0));
        c.un.rays[std::size_t(y) * std::size_t(width) + std::size_t(x)] = {
            float(origin.x), float(origin.y), float(origin.z), float(step.x), float(step.y), float(step.z)};
      }
  }
  for (int v = 0; v < 256; ++v) c.srgbLut[std::size_t(v)] = srgbToLinear(float(v) / 255.0f);
  c.albedo = snapshot.rgba.data();

  const glm::dmat4& view = orbit.view();
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) c.viewToWorld[row][col] = float(view[row][col]);  // transpose of the rotation
  auto toView = [&](const Vec3& w) {
    const glm::dvec4 v = view * glm::dvec4(w, 0.0);
    return normalized(Vec3f{float(v.x), float(v.y), float(v.z)});
  };
  const glm::dmat4 viewToWorld = glm::inverse(view);
  std::size_t nextShadowBuffer = 0;
  for (std::size_t l = 0; l < settings.lights.size(); ++l) {
    const ShadingLight& light = settings.lights[l];
    DevelopContext::Light dl;
    dl.direction = toView(light.direction);
    dl.r = srgbToLinear(float(light.color.x)) * float(light.intensity);
    dl.g = srgbToLinear(float(light.color.y)) * float(light.intensity);
    dl.b = srgbToLinear(float(light.color.z)) * float(light.intensity);
    if (light.shadows && nextShadowBuffer < snapshot.lightDepth.size() &&
        nextShadowBuffer < snapshot.lightViews.size()) {
      const LightView& lv = snapshot.lightViews[nextShadowBuffer];
      ShadowLight s{};
      s.settingsIndex = l;
      s.depth = &snapshot.lightDepth[nextShadowBuffer];
      s.size = lv.size();
      s.texel = float(lv.texelSize());
      if (s.depth->size() == std::size_t(s.size) * std::size_t(s.size)) {
        // Light rows composed with view → world, so a pixel's view-space position goes straight to
        // the light's texel and depth.
        const LightView::Rows rows = lv.rows();
        const float* src[3] = {rows.rowU, rows.rowV, rows.rowD};
        float* dst[3] = {s.rowU, s.rowV, s.rowD};
        for (int r = 0; r < 3; ++r)
          for (int col = 0; col < 4; ++col) {
            double v = col == 3 ? double(src[r][3]) : 0.0;
            for (int k = 0; k < 3; ++k) v += double(src[r][k]) * viewToWorld[col][k];
            dst[r][col] = float(v);
          }
        dl.shadow = int(c.shadows.size());
        c.shadows.push_back(s);
        c.shadowWeight += dl.r + dl.g + dl.b;
      }
      ++nextShadowBuffer;
    } else if (light.shadows) {
      ++nextShadowBuffer;
    }
    c.lights.push_back(dl);
  }
  c.ambient = float(settings.ambient);
  c.specular = float(settings.specular);
  c.shininess = float(settings.shininess);
  c.aoRadius = float(settings.ao.radius);
  c.aoStrength = float(settings.ao.strength);
  c.aoDirections = std::max(1, settings.ao.directions);
  for (int pattern = 0; pattern < kPattern * kPattern; ++pattern) {
    // Interleaved rotations and step offsets: neighbouring pixels look along different directions
    // at different distances, so the sampling pattern does not show as streaks or rings.
    const double jitter = (double(pattern) + 0.5) / double(kPattern * kPattern);
    for (int k = 0; k < c.aoDirections; ++k) {
      const double angle = 2.0 * M_PI * (double(k) + double((pattern * 7) % 16) / 16.0) / double(c.aoDirections);
      for (int step = 0; step < kAoSteps; ++step) {
        const double t = (double(step) + jitter) / double(kAoSteps) * double(c.aoRadius) + 1.0;
        c.aoOffsets.push_back({int(std::lround(std::cos(angle) * t)), int(std::lround(std::sin(angle) * t))});
      }
    }
  }
  c.fogR = srgbToLinear(float(settings.fog.color.x));
  c.fogG = srgbToLinear(float(settings.fog.color.y));
  c.fogB = srgbToLinear(float(settings.fog.color.z));
  c.fogDensity = float(settings.fog.density);
  for (int k = 0; k < 3; ++k) c.bgBytes[k] = std::uint8_t(std::lround(std::clamp(background[k], 0.0, 1.0) * 255.0));
  c.bgBytes[3] = 0;

  // Empty pixels: the snapshot's alpha is 0 there (its depth is +inf as well).
  // The snapshot's depth is +inf where no point was plotted (RenderImage), which the passes below
  // treat as empty.
  ShadedImage::Workspace& w = out.workspace;
  w.horizontal.resize(n);
  w.smooth.resize(n);
  w.viewNormals.resize(n);
  const std::size_t grain = 16;
  parallelFor(std::size_t(height), threads, grain, [&](std::size_t b, std::size_t e) {
    smoothPass(snapshot.depth.data(), w.horizontal.data(), width, height, c.un, false, b, e);
  });
  parallelFor(std::size_t(height), threads, grain, [&](std::size_t b, std::size_t e) {
    smoothPass(w.horizontal.data(), w.smooth.data(), width, height, c.un, true, b, e);
  });
  c.depth = w.smooth.data();
  for (int k = 0; k <= 1024; ++k) c.specularTable[std::size_t(k)] = std::pow(float(k) / 1024.0f, c.shininess);
  c.viewNormals = w.viewNormals.data();
  parallelFor(std::size_t(height), threads, grain, [&](std::size_t b, std::size_t e) { normalRows(c, b, e); });
  if (c.aoStrength > 0.0f && c.aoRadius > 0.0f) {
    c.blocksX = (width + 1) / 2;
    c.blocksY = (height + 1) / 2;
    w.blockAo.resize(std::size_t(c.blocksX) * std::size_t(c.blocksY));
    w.blockDepth.resize(w.blockAo.size());
    c.blockAo = w.blockAo.data();
    c.blockDepth = w.blockDepth.data();
    parallelFor(std::size_t(c.blocksY), threads, grain / 2,
                [&](std::size_t b, std::size_t e) { blockOcclusionRows(c, b, e); });
  }
  parallelFor(std::size_t(height), threads, grain, [&](std::size_t b, std::size_t e) {
    if (compositing)
      shadeRows<true>(c, out, b, e);
    else
      shadeRows<false>(c, out, b, e);
  });
}

}  // namespace gridifs
