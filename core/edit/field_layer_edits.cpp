#include "edit/field_layer_edits.h"

#include "base/errors.h"
#include "schema/field_layer.h"

namespace gridifs {
namespace {

VolumeDensityField& layerIn(Project& project, std::size_t index) {
  if (!project.volume || index >= fieldLayerCount(project))
    throw ModelError("volume.field", "the project has no field layer " + std::to_string(index));
  return index == 0 ? *project.volume->field : project.volume->more_fields[index - 1];
}

// Tracks follow the file's spelling: "volume.field.KEY" for one layer, "volume.field[i].KEY" for a
// list, so a layer added to a single field or a list shrunk to one renames its tracks.
void renameTracks(Project& project, const std::string& from, const std::string& to) {
  KeyframeTracks renamed;
  for (auto& [path, track] : project.tracks)
    renamed.emplace(path.rfind(from, 0) == 0 ? to + path.substr(from.size()) : path, std::move(track));
  project.tracks = std::move(renamed);
}

}  // namespace

std::size_t fieldLayerCount(const Project& project) {
  if (!project.volume || !project.volume->field) return 0;
  return 1 + project.volume->more_fields.size();
}

const VolumeDensityField* fieldLayerAt(const Project& project, std::size_t index) {
  if (index >= fieldLayerCount(project)) return nullptr;
  return index == 0 ? &*project.volume->field : &project.volume->more_fields[index - 1];
}

void AddFieldLayer::apply(Project& project) const {
  if (!project.volume) project.volume = VolumeSettings{};
  if (fieldLayerCount(project) >= kMaxFieldLayers)
    throw ModelError("volume.field", "a scene holds at most " + std::to_string(kMaxFieldLayers) + " field layers");
  VolumeDensityField layer;
  layer.role = role;
  // Colonna's fig. 6: a low mountain, clouds above it.
  if (role == FieldRole::Terrain) {
    layer.height = -0.5;
    layer.strength = 0.5;
  } else if (role == FieldRole::Cloud) {
    layer.height = 0.4;
    layer.strength = 2.0;
  }
  if (!project.volume->field) {
    project.volume->field = layer;
    return;
  }
  if (project.volume->more_fields.empty()) renameTracks(project, "volume.field.", "volume.field[0].");
  project.volume->more_fields.push_back(layer);
}

std::string AddFieldLayer::label() const { return std::string("Add ") + toString(role) + " layer"; }

void RemoveFieldLayer::apply(Project& project) const {
  layerIn(project, layer);
  VolumeSettings& v = *project.volume;
  if (v.more_fields.empty()) {
    // The one layer goes, and its tracks with it.
    for (auto it = project.tracks.begin(); it != project.tracks.end();)
      it = it->first.rfind("volume.field.", 0) == 0 ? project.tracks.erase(it) : std::next(it);
    v.field.reset();
    return;
  }
  const int removed = int(layer);
  remapTrackIndices(project.tracks, "volume.field", [removed](int i) {
    return i == removed ? -1 : i > removed ? i - 1 : i;
  });
  if (layer == 0) {
    v.field = v.more_fields.front();
    v.more_fields.erase(v.more_fields.begin());
  } else {
    v.more_fields.erase(v.more_fields.begin() + std::ptrdiff_t(layer - 1));
  }
  if (v.more_fields.empty()) renameTracks(project, "volume.field[0].", "volume.field.");
}

void SetFieldLayer::apply(Project& project) const { layerIn(project, layer) = value; }

}  // namespace gridifs
