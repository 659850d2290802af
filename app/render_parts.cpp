#include "app/render_parts.h"

#include <cstdio>

#include "app/cli.h"

namespace gridifs::cli {
namespace {

/// The largest buffers a part may hold (a 16384² image; a 1024³ volume), so that a damaged count
/// cannot ask for absurd memory.
constexpr std::size_t kMaxPixels = std::size_t(16384) * 16384;
constexpr std::size_t kMaxVoxels = std::size_t(1024) * 1024 * 1024;

}  // namespace

RenderPart parsePart(const std::string& text) {
  long long k = -1, n = -1;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%lld/%lld%c", &k, &n, &extra) != 2 || n < 1 || n > kMaxRenderParts || k < 0 || k >= n)
    throw CliError(kBadInput, "--part must be K/N with 0 ≤ K < N ≤ " + std::to_string(kMaxRenderParts) +
                                  " (e.g. 3/16), not \"" + text + "\"");
  return RenderPart{k, n};
}

std::string partDigest(const std::string& kind, const std::string& project, const std::string& options,
                       std::int64_t parts, const std::string& device, std::optional<std::int64_t> frame) {
  return renderDigest(kind + '\n' + project + '\n' + options + '\n' + std::to_string(parts) + '\n' + device + '\n' +
                      (frame ? std::to_string(*frame) : std::string("-")));
}

void writeImagePart(const std::filesystem::path& out, const RenderPartHeader& header,
                    const std::vector<Accumulation>& timeSamples) {
  RenderPartWriter writer(out, header);
  const std::vector<std::uint32_t> shape = {std::uint32_t(timeSamples.size())};
  writer.buffer("time_samples", shape);
  for (const Accumulation& a : timeSamples) {
    const std::vector<std::int64_t> meta = {a.width, a.height, a.samples, a.badSamples, a.plotted};
    const std::vector<float> quant = {a.depthMin, a.depthScale};
    writer.buffer("meta", meta);
    writer.buffer("depth_quant", quant);
    writer.buffer("keys", a.keys);
    writer.buffer("keys32", a.keys32);
    writer.buffer("density", a.density);
    writer.buffer("color_sums", a.colorSums);
    const std::vector<std::uint32_t> lights = {std::uint32_t(a.lightDepth.size())};
    writer.buffer("lights", lights);
    for (std::size_t l = 0; l < a.lightDepth.size(); ++l) {
      const LightView& v = a.lightViews[l];
      std::vector<double> view;
      for (const glm::dvec3* axis : {&v.direction(), &v.right(), &v.up(), &v.bounds().center})
        view.insert(view.end(), {axis->x, axis->y, axis->z});
      view.insert(view.end(), {v.bounds().radius, double(v.size())});
      writer.buffer("light_view", view);
      writer.buffer("light_depth", a.lightDepth[l]);
    }
  }
  writer.commit();
}

void readImagePart(RenderPartReader& reader, std::vector<Accumulation>& timeSamples) {
  std::vector<std::uint32_t> shape;
  reader.buffer("time_samples", shape, 1);
  const std::size_t count = shape.empty() ? 0 : shape[0];
  if (count == 0 || count > 4096) throw PartFileError("a part has no time samples");
  timeSamples.resize(count);
  for (std::size_t t = 0; t < count; ++t) {
    Accumulation& a = timeSamples[t];
    std::vector<std::int64_t> meta;
    std::vector<float> quant;
    reader.buffer("meta", meta, 5);
    reader.buffer("depth_quant", quant, 2);
    if (meta.size() != 5 || quant.size() != 2 || meta[0] < 1 || meta[1] < 1 ||
        std::size_t(meta[0]) * std::size_t(meta[1]) > kMaxPixels)
      throw PartFileError("a part's image size is damaged");
    a.width = int(meta[0]);
    a.height = int(meta[1]);
    a.samples = meta[2];
    a.badSamples = meta[3];
    a.plotted = meta[4];
    a.depthMin = quant[0];
    a.depthScale = quant[1];
    const std::size_t n = std::size_t(a.width) * std::size_t(a.height);
    reader.buffer("keys", a.keys, n);
    reader.buffer("keys32", a.keys32, n);
    reader.buffer("density", a.density, n);
    reader.buffer("color_sums", a.colorSums, 4 * n);
    std::vector<std::uint32_t> lights;
    reader.buffer("lights", lights, 1);
    const std::size_t lightCount = lights.empty() ? 0 : lights[0];
    if (lightCount > 3) throw PartFileError("a part's light count is damaged");
    a.lightDepth.resize(lightCount);
    a.lightViews.resize(lightCount);
    for (std::size_t l = 0; l < lightCount; ++l) {
      std::vector<double> v;
      reader.buffer("light_view", v, 14);
      if (v.size() != 14 || !(v[13] >= 16 && v[13] <= 8192)) throw PartFileError("a part's light view is damaged");
      a.lightViews[l] = LightView::restore({v[0], v[1], v[2]}, {v[3], v[4], v[5]}, {v[6], v[7], v[8]},
                                           BoundingSphere{{v[9], v[10], v[11]}, v[12]}, int(v[13]));
      reader.buffer("light_depth", a.lightDepth[l], std::size_t(v[13]) * std::size_t(v[13]));
      if (a.lightDepth[l].size() != std::size_t(v[13]) * std::size_t(v[13]))
        throw PartFileError("a part's light depth buffer does not match its size");
    }
    if (a.density.size() != n || (!a.keys.empty() && a.keys.size() != n) ||
        (!a.keys32.empty() && a.keys32.size() != n) || (!a.colorSums.empty() && a.colorSums.size() != 4 * n))
      throw PartFileError("a part's buffers do not match its image size");
  }
}

void addImageParts(std::vector<Accumulation>& sums, const std::vector<Accumulation>& part) {
  if (sums.size() != part.size()) throw PartFileError("the parts have different motion blur");
  for (std::size_t t = 0; t < part.size(); ++t) {
    if (const std::string why = sums[t].mismatch(part[t]); !why.empty()) throw PartFileError(why);
    sums[t].add(part[t]);
  }
}

void writeVolumePart(const std::filesystem::path& out, const RenderPartHeader& header, const VoxelAccumulation& acc) {
  RenderPartWriter writer(out, header);
  const std::vector<std::int64_t> meta = {acc.resolution, acc.samples};
  writer.buffer("meta", meta);
  writer.buffer("counts", acc.counts);
  writer.buffer("color_sums", acc.colorSums);
  writer.commit();
}

void addVolumePart(RenderPartReader& reader, VoxelAccumulation& sum, bool first) {
  VoxelAccumulation part;
  VoxelAccumulation& a = first ? sum : part;
  std::vector<std::int64_t> meta;
  reader.buffer("meta", meta, 2);
  if (meta.size() != 2 || meta[0] < 1 || meta[0] > 1024) throw PartFileError("a volume part's resolution is damaged");
  a.resolution = int(meta[0]);
  a.samples = meta[1];
  const std::size_t n = std::size_t(a.resolution) * std::size_t(a.resolution) * std::size_t(a.resolution);
  reader.buffer("counts", a.counts, std::min(n, kMaxVoxels));
  reader.buffer("color_sums", a.colorSums, 3 * n);
  if (a.counts.size() != n || (!a.colorSums.empty() && a.colorSums.size() != 3 * n))
    throw PartFileError("a volume part's buffers do not match its resolution");
  if (!first) {
    try {
      sum.add(part);
    } catch (const std::invalid_argument& e) {
      throw PartFileError(e.what());
    }
  }
}

}  // namespace gridifs::cli
