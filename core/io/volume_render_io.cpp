#include "io/volume_render_io.h"

#include "io/json_read.h"
#include "model/volume_settings.h"

namespace gridifs::volume_render_io {

using namespace json_read;

namespace {

TransferStop readStop(const json& j, const std::string& path) {
  requireObject(j, path);
  TransferStop stop;
  if (auto it = j.find("density"); it != j.end()) stop.density = readNumber(*it, join(path, "density"), 0.0, 1.0);
  if (auto it = j.find("color"); it != j.end()) stop.color = readVec3(*it, join(path, "color"), 0.0, 1000.0);
  if (auto it = j.find("opacity"); it != j.end()) stop.opacity = readNumber(*it, join(path, "opacity"), 0.0, 1.0);
  return stop;
}

bool inRange(double v, double lo, double hi) { return v >= lo && v <= hi; }

}  // namespace

const char* previewModeName(StoredPreviewMode mode) {
  switch (mode) {
    case StoredPreviewMode::Flame:
      return "flame";
    case StoredPreviewMode::Shaded:
      return "shaded";
    case StoredPreviewMode::Mesh:
      return "mesh";
    case StoredPreviewMode::Volume:
      return "volume";
    default:
      return "zbuffer";
  }
}

const char* volumeDisplayName(VolumeDisplay display) { return display == VolumeDisplay::Xray ? "xray" : "lit"; }

void validateVolumeRender(const VolumeRenderSettings& s, const std::string& path) {
  if (s.resolution < kMinVolumeResolution || s.resolution > kMaxVolumeResolution)
    fail(join(path, "resolution"), "expected an integer between " + std::to_string(kMinVolumeResolution) + " and " +
                                       std::to_string(kMaxVolumeResolution) + ", found " +
                                       std::to_string(s.resolution));
  if (!inRange(s.density_scale, kMinVolumeDensityScale, kMaxVolumeDensityScale))
    fail(join(path, "density_scale"), "expected a number between 0.01 and 10000");
  if (s.transfer.size() > std::size_t(kMaxTransferStops))
    fail(join(path, "transfer"), "more than " + std::to_string(kMaxTransferStops) + " stops");
  for (std::size_t i = 0; i < s.transfer.size(); ++i) {
    const TransferStop& t = s.transfer[i];
    const std::string p = item(join(path, "transfer"), i);
    if (!inRange(t.density, 0.0, 1.0)) fail(join(p, "density"), "expected a number between 0 and 1");
    if (!inRange(t.opacity, 0.0, 1.0)) fail(join(p, "opacity"), "expected a number between 0 and 1");
    for (int c = 0; c < 3; ++c)
      if (!inRange(t.color[c], 0.0, 1000.0)) fail(join(p, "color"), "expected 3 numbers between 0 and 1000");
    if (i > 0 && !(t.density > s.transfer[i - 1].density))
      fail(join(p, "density"), "the stops must be sorted by increasing density");
  }
}

VolumeRenderSettings readVolumeRender(const json& object, const std::string& path) {
  requireObject(object, path);
  VolumeRenderSettings s;
  if (auto it = object.find("resolution"); it != object.end())
    s.resolution = int(readInteger(*it, join(path, "resolution"), kMinVolumeResolution, kMaxVolumeResolution));
  if (auto it = object.find("density_scale"); it != object.end())
    s.density_scale = readNumber(*it, join(path, "density_scale"), kMinVolumeDensityScale, kMaxVolumeDensityScale);
  if (auto it = object.find("display"); it != object.end()) {
    const std::string d = readString(*it, join(path, "display"), 32);
    if (d == "lit")
      s.display = VolumeDisplay::Lit;
    else if (d == "xray")
      s.display = VolumeDisplay::Xray;
    else
      fail(join(path, "display"), "expected \"lit\" or \"xray\", found \"" + d.substr(0, 32) + "\"");
  }
  if (auto it = object.find("transfer"); it != object.end()) {
    const std::string p = join(path, "transfer");
    if (!it->is_array()) fail(p, std::string("expected an array of stops, found ") + typeName(*it));
    if (it->size() > std::size_t(kMaxTransferStops))
      fail(p, "more than " + std::to_string(kMaxTransferStops) + " stops");
    for (std::size_t i = 0; i < it->size(); ++i) s.transfer.push_back(readStop((*it)[i], item(p, i)));
  }
  validateVolumeRender(s, path);
  return s;
}

nlohmann::ordered_json writeVolumeRender(const VolumeRenderSettings& s) {
  nlohmann::ordered_json out;
  out["resolution"] = s.resolution;
  out["density_scale"] = s.density_scale;
  out["display"] = volumeDisplayName(s.display);
  nlohmann::ordered_json stops = nlohmann::ordered_json::array();
  for (const TransferStop& t : s.transfer) {
    nlohmann::ordered_json stop;
    stop["density"] = t.density;
    stop["color"] = {t.color.x, t.color.y, t.color.z};
    stop["opacity"] = t.opacity;
    stops.push_back(stop);
  }
  out["transfer"] = stops;
  return out;
}

std::optional<StoredPreviewMode> readPreviewMode(const json& root) {
  auto view = root.find("view");
  if (view == root.end() || view->is_null()) return std::nullopt;
  requireObject(*view, "view");
  auto it = view->find("preview_mode");
  if (it == view->end()) return std::nullopt;
  const std::string name = readString(*it, "view.preview_mode", 32);
  for (StoredPreviewMode m : {StoredPreviewMode::ZBuffer, StoredPreviewMode::Flame, StoredPreviewMode::Shaded,
                              StoredPreviewMode::Mesh, StoredPreviewMode::Volume})
    if (name == previewModeName(m)) return m;
  fail("view.preview_mode",
       "expected \"zbuffer\", \"flame\", \"shaded\", \"mesh\" or \"volume\", found \"" + name.substr(0, 32) + "\"");
}

void writeView(const Project& project, nlohmann::ordered_json& root) {
  if (project.preview_mode) root["view"]["preview_mode"] = previewModeName(*project.preview_mode);
}

}  // namespace gridifs::volume_render_io
