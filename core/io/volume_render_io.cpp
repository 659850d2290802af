#include "io/volume_render_io.h"

#include "io/json_read.h"
#include "io/settings_json.h"
#include "model/volume_settings.h"
#include "schema/settings_tables.h"
#include "schema/validation.h"

namespace gridifs::volume_render_io {

using namespace json_read;

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

const char* volumeDisplayName(VolumeDisplay display) {
  return volumeRenderTable().field("display").choices->names[std::size_t(display)];
}

VolumeRenderSettings readVolumeRender(const json& object, const std::string& path) {
  VolumeRenderSettings s;
  readSettingFields(volumeRenderTable(), object, path, &s);
  if (auto it = object.find("transfer"); it != object.end()) {
    const std::string p = join(path, "transfer");
    if (!it->is_array()) fail(p, std::string("expected an array of stops, found ") + typeName(*it));
    if (it->size() > std::size_t(kMaxTransferStops))
      fail(p, "more than " + std::to_string(kMaxTransferStops) + " stops");
    for (std::size_t i = 0; i < it->size(); ++i)
      readSettingFields(transferStopTable(), (*it)[i], item(p, i), &s.transfer.emplace_back());
  }
  validateVolumeRender(s, path);
  return s;
}

nlohmann::ordered_json writeVolumeRender(const VolumeRenderSettings& s) {
  nlohmann::ordered_json out = writeSettings(volumeRenderTable(), s);
  nlohmann::ordered_json stops = nlohmann::ordered_json::array();
  for (const TransferStop& t : s.transfer) stops.push_back(writeSettings(transferStopTable(), t));
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
