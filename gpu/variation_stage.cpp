#include "gpu/variation_stage.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>

#include "base/hash.h"
#include "gpu/headless_gl_context.h"

namespace gridifs::gpu {
namespace {

constexpr std::uint32_t kNoStage = 0xFFFFFFFFu;
constexpr std::size_t kTermParams = 8;  // two uvec4 words a term
constexpr std::uint32_t kWritesZ = 1, kPre = 2, kFlatten = 4, kRandom = 8;

std::uint32_t bits(double v) { return std::bit_cast<std::uint32_t>(float(v)); }

void packStage(const CompiledVariations& v, std::vector<std::uint32_t>& out) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) out.push_back(bits(v.post[r][c]));
  out.insert(out.end(), {bits(v.coefs.a), bits(v.coefs.b), bits(v.coefs.c), bits(v.coefs.d)});
  out.insert(out.end(), {bits(v.coefs.e), bits(v.coefs.f), 0u, 0u});
  const auto& table = flameVariations();
  for (std::size_t i = 0; i < v.variationIds.size(); ++i) {
    const FlameVariation& var = table[std::size_t(v.variationIds[i])];
    if (var.params.size() > kTermParams)
      throw GpuUnavailable(std::string("the GPU renderer cannot hold the parameters of variation ") + var.name +
                           "; the CPU renderer can");
    if (var.pre && std::strcmp(var.name, "pre_blur") != 0)
      throw GpuUnavailable(std::string("the GPU renderer does not run pre-variation ") + var.name +
                           "; the CPU renderer does");
    const std::uint32_t flags = (var.writesZ ? kWritesZ : 0u) | (var.pre ? kPre : 0u) |
                                (std::strcmp(var.name, "flatten") == 0 ? kFlatten : 0u) | (var.random ? kRandom : 0u);
    out.insert(out.end(), {std::uint32_t(v.variationIds[i]), bits(v.terms[i].weight), flags, 0u});
    for (std::size_t k = 0; k < kTermParams; ++k)
      out.push_back(k < var.params.size() ? bits(v.params[v.paramOffsets[i] + k]) : 0u);
  }
}

}  // namespace

std::string usedVariations(const CompiledIfs& ifs) {
  std::string used(flameVariations().size(), '0');
  auto mark = [&](const CompiledFunction& f) {
    if (f.variations)
      for (int id : f.variations->variationIds) used[std::size_t(id)] = '1';
  };
  for (const CompiledFunction& f : ifs.functions) mark(f);
  if (ifs.finalFunction) mark(*ifs.finalFunction);
  return used;
}

std::string variationDefines(const std::string& used) {
  std::string out;
  const auto& table = flameVariations();
  for (std::size_t i = 0; i < table.size(); ++i) {
    const std::string name = table[i].name;
    out += "#define V_" + name + " " + std::to_string(i) + "u\n#define USE_" + name + " " +
           (i < used.size() && used[i] == '1' ? "1" : "0") + "\n";
  }
  return out;
}

std::vector<std::uint32_t> packVariationStages(const CompiledIfs& ifs) {
  std::vector<const CompiledFunction*> functions;
  for (const CompiledFunction& f : ifs.functions) functions.push_back(&f);
  if (ifs.finalFunction) functions.push_back(&*ifs.finalFunction);
  std::vector<std::uint32_t> out(functions.size() * 4, 0u);
  for (std::size_t i = 0; i < functions.size(); ++i) {
    const CompiledVariations* v = functions[i]->variations.get();
    out[4 * i] = v ? std::uint32_t(out.size() / 4) : kNoStage;
    if (!v) continue;
    out[4 * i + 1] = std::uint32_t(v->variationIds.size());
    packStage(*v, out);
  }
  return out;
}

bool variationDepthRange(const CompiledIfs& ifs, const OrbitCamera& camera, int skip, float& lo, float& hi) {
  constexpr int kChains = 256, kSteps = 64;
  const OrbitCamera::PixelRows rows = camera.pixelRows();
  const float width = float(camera.width()), height = float(camera.height()), nearPlane = float(camera.nearPlane());
  std::uint64_t counter = 0, random = 0x243F6A8885A308D3ull;
  auto next = [&] { return splitmix64(++counter); };
  auto signedUnit = [](std::uint64_t b) { return float(b >> 40) * (2.0f / 16777216.0f) - 1.0f; };
  auto row = [](const float* r, const std::array<float, 3>& q) {
    return r[0] * q[0] + r[1] * q[1] + r[2] * q[2] + r[3];
  };
  std::vector<float> depths;
  for (int c = 0; c < kChains; ++c) {
    std::array<float, 3> p{signedUnit(next()), signedUnit(next()), signedUnit(next())};
    for (int k = 0; k < skip + kSteps; ++k) {
      p = ifs.functions[ifs.choose(next())].evaluateMap(p, random);
      if (!std::all_of(p.begin(), p.end(), [](float v) { return std::fabs(v) <= 1e10f; })) break;  // NaN too
      if (k < skip) continue;
      const std::array<float, 3> q = ifs.finalFunction ? ifs.finalFunction->evaluateMap(p, random) : p;
      if (camera.panoramic() || camera.eyes() == 2) {
        const ProjectedPoint projected = camera.project(glm::dvec3(q[0], q[1], q[2]), int(k & 1));
        const EyeRegion r = camera.eyeRegion(int(k & 1));
        if (projected.inFront && projected.x >= r.x && projected.x < r.x + r.width && projected.y >= r.y &&
            projected.y < r.y + r.height)
          depths.push_back(float(projected.depth));
        continue;
      }
      const float depth = row(rows.rowD, q), w = row(rows.rowW, q);
      const float x = row(rows.rowX, q) / w, y = row(rows.rowY, q) / w;
      if (depth > nearPlane && x >= 0.0f && x < width && y >= 0.0f && y < height) depths.push_back(depth);
    }
  }
  if (depths.size() < 64) return false;
  std::sort(depths.begin(), depths.end());
  const std::size_t cut = depths.size() / 1000;
  lo = depths[cut];
  hi = depths[depths.size() - 1 - cut];
  const float margin = 0.05f * (hi - lo);
  lo = std::max(lo - margin, nearPlane);
  hi += margin;
  return hi > lo;
}

}  // namespace gridifs::gpu
