#include "io/volume_io.h"

#include <cmath>

#include "io/json_read.h"
#include "io/operation_json.h"
#include "io/settings_json.h"
#include "schema/field_layer.h"
#include "schema/operation_table.h"
#include "schema/settings_tables.h"
#include "schema/validation.h"

namespace gridifs::volume_io {
namespace {

using json = nlohmann::json;
using ordered_json = nlohmann::ordered_json;

[[noreturn]] void fail(const std::string& path, const std::string& message) { throw ModelError(path, message); }

std::string readText(const json& j, const std::string& path) {
  if (!j.is_string() || j.get_ref<const std::string&>().size() > 4096) fail(path, "expected a string");
  return j.get<std::string>();
}

ordered_json vec(const Vec3& v) { return ordered_json::array({v.x, v.y, v.z}); }

void readPlacement(const json& s, const std::string& path, CondensationSet& set) {
  if (auto pl = s.find("placement"); pl != s.end())
    readSettingFields(placementTable(), *pl, path + ".placement", &set.placement);
}

CondensationSet readSet(const json& s, const std::string& path) {
  if (!s.is_object()) fail(path, "expected an object with \"primitive\", \"mesh\", \"vdb\" or \"image\"");
  CondensationSet set;
  const int sources =
      int(s.contains("primitive")) + int(s.contains("mesh")) + int(s.contains("vdb")) + int(s.contains("image"));
  if (sources != 1) fail(path, "expected exactly one of \"primitive\", \"mesh\", \"vdb\" or \"image\"");
  auto allowOnly = [&](std::initializer_list<const char*> keys) {
    for (auto it = s.begin(); it != s.end(); ++it) {
      bool known = false;
      for (const char* k : keys) known |= it.key() == k;
      if (!known) fail(path + "." + it.key().substr(0, 32), "this set has no such field");
    }
  };
  if (auto it = s.find("primitive"); it != s.end()) {
    const std::string name = readText(*it, path + ".primitive");
    if (name == "sphere") {
      set.shape = SetShape::Sphere;
      allowOnly({"primitive", "center", "radius"});
    } else if (name == "box") {
      set.shape = SetShape::Box;
      allowOnly({"primitive", "center", "size"});
    } else if (name == "torus") {
      set.shape = SetShape::Torus;
      allowOnly({"primitive", "center", "major", "minor", "axis"});
    } else {
      fail(path + ".primitive", "expected \"sphere\", \"box\" or \"torus\", found \"" + name.substr(0, 32) + "\"");
    }
  } else if (auto image = s.find("image"); image != s.end()) {
    // A drawing (Sokolov & Gentil's sketches): its dark pixels as a slab on z = 0, placed like a mesh.
    set.shape = SetShape::Image;
    allowOnly({"image", "threshold", "thickness", "invert", "placement"});
    set.path = readText(*image, path + ".image");
    readPlacement(s, path, set);
  } else if (auto mesh = s.find("mesh"); mesh != s.end()) {
    set.shape = SetShape::Mesh;
    allowOnly({"mesh", "fill", "placement"});
    set.path = readText(*mesh, path + ".mesh");
    if (auto fill = s.find("fill"); fill != s.end()) {
      const std::string word = readText(*fill, path + ".fill");
      if (word == "solid")
        set.fill = SetFill::Solid;
      else if (word == "surface")
        set.fill = SetFill::Surface;
      else
        fail(path + ".fill", "expected \"solid\" or \"surface\"");
    }
    readPlacement(s, path, set);
  } else {
    set.shape = SetShape::Vdb;
    allowOnly({"vdb", "grid", "threshold"});
    set.path = readText(s["vdb"], path + ".vdb");
    if (auto g = s.find("grid"); g != s.end()) set.grid = readText(*g, path + ".grid");
  }
  // The shape's numbers (condensationSetTable), read with the words validation uses.
  readSettingFields(condensationSetTable(set.shape), s, path, &set);
  checkCondensationSet(set, path);
  return set;
}

ordered_json writeSet(const CondensationSet& set) {
  ordered_json o;
  switch (set.shape) {
    case SetShape::Sphere:
    case SetShape::Box:
    case SetShape::Torus:
      o["primitive"] = setShapeName(set.shape);
      break;
    case SetShape::Mesh:
      o["mesh"] = set.path;
      o["fill"] = setFillName(set.fill);
      break;
    case SetShape::Vdb:
      o["vdb"] = set.path;
      o["grid"] = set.grid;
      break;
    case SetShape::Image:
      o["image"] = set.path;
      break;
  }
  writeSettingFields(condensationSetTable(set.shape), &set, o);
  if (set.shape == SetShape::Mesh || set.shape == SetShape::Image)
    o["placement"] = writeSettings(placementTable(), set.placement);
  return o;
}

}  // namespace

void readSetFunctionFields(const json& f, const std::string& path, Function& fn) {
  if (!isSetKind(fn.kind)) {
    for (const char* key : {"set", "rotate", "rotate_axis"})
      if (f.contains(key))
        fail(path + "." + key,
             "only a function of kind \"condensation\" or \"median\" has a \"" + std::string(key) + "\"");
    return;
  }
  for (const char* gridField : {"resolution", "placement", "ops"})
    if (f.contains(gridField))
      fail(path + "." + gridField,
           "a function with a condensation set has no grid, so no \"" + std::string(gridField) + "\"");
  auto it = f.find("set");
  if (it == f.end()) fail(path + ".set", "a \"" + std::string(functionKindName(fn.kind)) + "\" function needs its set");
  fn.set = readSet(*it, path + ".set");
  if (fn.kind == FunctionKind::Median) {
    const FieldInfo& rotate = medianRotateField();
    if (auto r = f.find(rotate.key); r != f.end())
      fn.rotate = json_read::readNumber(*r, path + "." + rotate.key, rotate.min, rotate.max);
    const FieldInfo& axis = medianRotateAxisField();
    if (auto a = f.find(axis.key); a != f.end())
      fn.rotate_axis = json_read::readVec3(*a, path + "." + axis.key, axis.min, axis.max);
  } else {
    for (const char* key : {"rotate", "rotate_axis"})
      if (f.contains(key)) fail(path + "." + key, "only a \"median\" function is rotated");
  }
}

ordered_json writeSetFunction(const Function& fn) {
  ordered_json o;
  o["name"] = fn.name;
  o["kind"] = functionKindName(fn.kind);
  writeSettingField(functionTable().field("weight"), &fn, o);
  if (fn.kind == FunctionKind::Median) {
    o["rotate"] = fn.rotate;
    if (fn.rotate_axis != Vec3{0.0, 0.0, 1.0}) o["rotate_axis"] = vec(fn.rotate_axis);
  }
  o["set"] = writeSet(fn.set);
  for (const char* key : {"color", "palette_index", "color_speed", "muted"})
    writeSettingField(functionTable().field(key), &fn, o);
  return o;
}

namespace {

// The field operation's parameters that a density field carries: all but the amplitude.
bool isDensityFieldParam(const ParamSpec& spec) { return std::string_view(spec.key) != "amplitude"; }

// A layer's role in the scene and the shape it is blended with (Colonna's figures 3 and 6), with
// its numbers from fieldLayerTable(); each is written only when it differs from the single
// field's default or matters for the layer, so a file with one plain field saves as before.
void readLayerFields(const json& object, const std::string& path, VolumeDensityField& field) {
  if (auto it = object.find("role"); it != object.end()) {
    const std::string word = readText(*it, path + ".role");
    if (!parseFieldRole(word, field.role))
      fail(path + ".role", "expected \"density\", \"cloud\" or \"terrain\", found \"" + word.substr(0, 32) + "\"");
  }
  if (auto it = object.find("shape"); it != object.end() && !it->is_null()) {
    field.shape = readSet(*it, path + ".shape");
    if (field.shape->shape == SetShape::Mesh || field.shape->shape == SetShape::Vdb ||
        field.shape->shape == SetShape::Image)
      fail(path + ".shape", "a field's shape must be a sphere, a box or a torus");
  }
}

void writeLayerFields(const VolumeDensityField& field, ordered_json& o) {
  const SettingTableOf<VolumeDensityField>& table = fieldLayerTable();
  auto write = [&](const char* key) {
    if (settingWritten(table.field(key), &field)) writeSettingField(table.field(key), &field, o);
  };
  if (field.role != VolumeDensityField{}.role) o["role"] = toString(field.role);
  write("height");
  write("thickness");
  if (field.shape) o["shape"] = writeSet(*field.shape);
  write("blend");
  write("softness");
}

VolumeDensityField readDensityField(const json& object, const std::string& path) {
  json_read::requireObject(object, path);
  VolumeDensityField field;
  readSettingFields(fieldLayerTable(), object, path, &field);
  OpParams params = field.field;
  for (const ParamSpec& spec : findOperation("field")->params)
    if (isDensityFieldParam(spec)) operation_json::readParam(spec, object, path, params);
  field.field = std::get<FieldOp>(params);
  readLayerFields(object, path, field);
  return field;
}

ordered_json writeDensityField(const VolumeDensityField& field) {
  ordered_json o;
  writeSettingField(fieldLayerTable().field("strength"), &field, o);
  const OpParams params = field.field;
  for (const ParamSpec& spec : findOperation("field")->params)
    if (isDensityFieldParam(spec)) o[spec.key] = operation_json::writeParam(spec, params);
  writeLayerFields(field, o);
  return o;
}

// "field": one layer as an object, or a list of layers (Colonna's fig. 6: mountains and clouds).
void readFieldLayers(const json& field, VolumeSettings& v) {
  if (!field.is_array()) {
    v.field = readDensityField(field, "volume.field");
    return;
  }
  if (field.empty()) return;
  if (field.size() > kMaxFieldLayers)
    fail("volume.field", "expected at most " + std::to_string(kMaxFieldLayers) + " field layers");
  for (std::size_t i = 0; i < field.size(); ++i) {
    VolumeDensityField layer = readDensityField(field[i], "volume.field[" + std::to_string(i) + "]");
    if (i == 0)
      v.field = std::move(layer);
    else
      v.more_fields.push_back(std::move(layer));
  }
}

}  // namespace

std::optional<VolumeSettings> readVolume(const json& root) {
  auto it = root.find("volume");
  if (it == root.end() || it->is_null()) return std::nullopt;
  if (!it->is_object()) fail("volume", "expected an object");
  // Validated with the rest of the project (validateProject), after the functions.
  VolumeSettings v;
  readSettingFields(volumeSettingsTable(), *it, "volume", &v);
  if (auto field = it->find("field"); field != it->end() && !field->is_null()) readFieldLayers(*field, v);
  if (auto start = it->find("start"); start != it->end() && !start->is_null())
    v.start = readSet(*start, "volume.start");
  return v;
}

void writeVolume(const Project& project, ordered_json& root) {
  if (!project.volume) return;
  ordered_json volume = writeSettings(volumeSettingsTable(), *project.volume);
  if (project.volume->field && project.volume->more_fields.empty()) {
    volume["field"] = writeDensityField(*project.volume->field);
  } else if (project.volume->field) {
    ordered_json layers = ordered_json::array({writeDensityField(*project.volume->field)});
    for (const VolumeDensityField& layer : project.volume->more_fields) layers.push_back(writeDensityField(layer));
    volume["field"] = layers;
  }
  if (project.volume->start) volume["start"] = writeSet(*project.volume->start);
  root["volume"] = volume;
}

}  // namespace gridifs::volume_io
