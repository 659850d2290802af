#include "schema/project_parameter.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "schema/field_layer.h"
#include "schema/settings_tables.h"
#include "variations/flame_variations.h"

namespace gridifs {
namespace {

constexpr double kMaxCoordinate = limits::kMaxCoordinate;

[[noreturn]] void fail(const std::string& path, const std::string& message) { throw ModelError(path, message); }

/// A number in a message, printed as the file readers print them.
std::string show(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string item(const std::string& path, int index) { return path + "[" + std::to_string(index) + "]"; }

/// Layer `a` of volume.field: the field itself, or one of the layers after it.
VolumeDensityField& fieldLayerOf(Project& project, int a) {
  return a == 0 ? *project.volume->field : project.volume->more_fields[std::size_t(a - 1)];
}

/// How the file names layer `a`: "volume.field" for one field, "volume.field[a]" in a list.
std::string layerPathOf(bool list, int a) { return list ? item("volume.field", a) : std::string("volume.field"); }

/// A range bound of a setting read with SettingWords::IntegerRange as an integer (the table's
/// INT64_MAX is stored as the double 2^63), as io/settings_json reads it.
std::int64_t integerBound(double v) {
  if (v >= 0x1p63) return INT64_MAX;
  if (v <= -0x1p63) return INT64_MIN;
  return std::int64_t(v);
}

/// A version number as the project file would hold it once keyed: the JSON library's text of a
/// number that is no integer (shortest digits; "2.0", "1.5", "10000000.0", "1e+16"), or null
/// when it is not finite.
std::string versionText(double v) {
  if (!std::isfinite(v)) return "null";
  char scientific[40];
  const char* end =
      std::to_chars(scientific, scientific + sizeof scientific, std::abs(v), std::chars_format::scientific).ptr;
  const std::string_view text(scientific, std::size_t(end - scientific));
  const std::size_t e = text.find('e');
  std::string digits;
  for (char ch : text.substr(0, e))
    if (ch != '.') digits += ch;
  const int k = int(digits.size());
  const int n = std::atoi(std::string(text.substr(e + 1)).c_str()) + 1;  // where the point goes
  std::string out = std::signbit(v) ? "-" : "";
  if (k <= n && n <= 15) return out + digits + std::string(std::size_t(n - k), '0') + ".0";
  if (0 < n && n <= 15) return out + digits.substr(0, std::size_t(n)) + "." + digits.substr(std::size_t(n));
  if (-4 < n && n <= 0) return out + "0." + std::string(std::size_t(-n), '0') + digits;
  out += digits.substr(0, 1) + (k > 1 ? "." + digits.substr(1) : "") + (n - 1 < 0 ? "e-" : "e+");
  const int exponent = std::abs(n - 1);
  return out + (exponent < 10 ? "0" : "") + std::to_string(exponent);
}

const char* const kPlacementKeys[3] = {"translate", "rotate", "scale"};
const char* const kCalculatorFields[3] = {"value", "min", "max"};
const char* const kSelectionAxes[3] = {"i", "j", "k"};

int keyIndex(std::string_view key, const char* const (&keys)[3]) {
  for (int i = 0; i < 3; ++i)
    if (key == keys[i]) return i;
  return -1;
}

}  // namespace

// ---- resolution: the project file's layout, as io/project_io writes it ------------------------

/// Walks a path's tokens through the objects and lists the project file would hold, filling in
/// the parameter as it goes.
class ParameterResolver {
 public:
  ParameterResolver(const Project& project, const TrackPath& path, ParameterScope scope)
      : project_(project), path_(path), editing_(scope == ParameterScope::Edit) {}

  FoundParameter run() {
    FoundParameter found;
    found.lookup = root();
    if (found.lookup == ParameterLookup::Number) found.parameter = p_;
    return found;
  }

 private:
  using Lookup = ParameterLookup;
  using Where = ProjectParameter::Where;
  using Group = ProjectParameter::Group;
  using Reader = ProjectParameter::Reader;
  using Storage = ProjectParameter::Storage;

  bool end() const { return at_ == path_.size(); }
  std::string_view token() { return path_[at_++]; }

  /// Records the position, among its siblings, of the member or element the path enters, in the
  /// order reading the file meets them (1-based: 0 marks levels the path does not reach).
  void position(int i) {
    if (depth_ < p_.order_.size()) p_.order_[depth_++] = std::int32_t(i) + 1;
  }

  /// The path reached a string or a switch: not a number, and nothing lies inside.
  Lookup text() const { return end() ? Lookup::NotANumber : Lookup::Missing; }
  /// Any path inside a structure that holds no parameters.
  Lookup structure() const { return Lookup::NotANumber; }

  Lookup number(Where where, Reader reader, Storage storage, double lo = 0.0, double hi = 0.0) {
    if (!end()) return Lookup::Missing;
    p_.where_ = where;
    p_.reader_ = reader;
    p_.storage_ = storage;
    p_.lo_ = lo;
    p_.hi_ = hi;
    return Lookup::Number;
  }

  /// The next token as an index into a list of `size` elements, the way a JSON pointer reads
  /// one ("0", or digits without a leading zero); -1 when it is none.
  int index(std::size_t size) {
    const std::string_view t = token();
    if (t.empty() || t.size() > 9 || (t.size() > 1 && t[0] == '0')) return -1;
    std::size_t value = 0;
    for (char ch : t) {
      if (ch < '0' || ch > '9') return -1;
      value = value * 10 + std::size_t(ch - '0');
    }
    if (value >= size) return -1;
    position(int(value));
    return int(value);
  }

  /// Component `c` of a list of `n` numbers.
  Lookup component(int n, Where where, Reader reader, double lo, double hi, Storage storage = Storage::Double) {
    if (end()) return Lookup::NotANumber;
    const int c = index(std::size_t(n));
    if (c < 0) return Lookup::Missing;
    p_.c_ = c;
    return number(where, reader, storage, lo, hi);
  }

  /// {"translate", "rotate", "scale"}, three numbers each.
  Lookup placement(Where where, Reader reader, double lo, double hi) {
    if (end()) return Lookup::NotANumber;
    const int b = keyIndex(token(), kPlacementKeys);
    if (b < 0) return Lookup::Missing;
    position(b);
    p_.b_ = b;
    return component(3, where, reader, lo, hi);
  }

  Lookup root() {
    if (end()) return Lookup::NotANumber;
    const std::string_view key = token();
    // Positions follow parseProject: the version, the camera, the render settings, the
    // functions, the final function, the transitions, then the animation, space and volume.
    if (key == "format") return text();
    if (key == "version") {
      position(0);
      return number(Where::Version, Reader::Version, Storage::None);
    }
    if (key == "camera") {
      position(1);
      return camera();
    }
    if (key == "render") {
      position(2);
      return render();
    }
    if (key == "functions") {
      position(3);
      if (end()) return Lookup::NotANumber;
      const int f = index(project_.functions.size());
      if (f < 0) return Lookup::Missing;
      p_.f_ = f;
      return function(project_.functions[std::size_t(f)]);
    }
    if (key == "final" && project_.final_function) {
      position(4);
      p_.f_ = -1;
      return function(*project_.final_function);
    }
    if (key == "transitions" && !project_.transitions.empty()) {
      position(5);
      if (end()) return Lookup::NotANumber;
      const int row = index(project_.transitions.size());
      if (row < 0) return Lookup::Missing;
      p_.a_ = row;
      return component(int(project_.transitions[std::size_t(row)].size()), Where::Transition, Reader::Number,
                       transitionWeightField().min, transitionWeightField().max);
    }
    if (key == "time" && project_.time != 0.0) {  // written only when not 0
      position(6);
      p_.fragile_ = true;
      return number(Where::Time, Reader::Time, Storage::Double);
    }
    if (key == "animation" && project_.animation) {
      position(7);
      return settingsObject(animationSettingsTable(), Group::Animation, &*project_.animation);
    }
    // The tracks' own keys are not parameters: keying a key would change the animation itself.
    if (key == "tracks" && !project_.tracks.empty()) return text();
    // Nor are the states' function and state indices: keying one would change the matrix's
    // structure, not a quantity (Thollot et al. §3.2).
    if (key == "states" && project_.states) return structure();
    if (key == "space" && project_.space) {
      position(8);
      if (end()) return Lookup::NotANumber;
      if (token() != "control_points") return Lookup::Missing;
      if (end()) return Lookup::NotANumber;
      const int point = index(project_.space->control_points.size());
      if (point < 0) return Lookup::Missing;
      p_.a_ = point;
      return component(3, Where::ControlPoint, Reader::Number, controlPointField().min, controlPointField().max);
    }
    if (key == "volume" && project_.volume) {
      position(9);
      return volume();
    }
    return Lookup::Missing;
  }

  // ---- settings groups (schema/settings_tables.h, written by io/settings_json) ----

  Lookup settingsObject(const SettingTable& table, Group group, const void* object) {
    if (end()) return Lookup::NotANumber;
    return settingField(table, group, object, token());
  }

  /// `first`: the position of the table's first field among the object's members.
  Lookup settingField(const SettingTable& table, Group group, const void* object, std::string_view key, int first = 0) {
    for (std::size_t i = 0; i < table.fields.size(); ++i) {
      const SettingSpec& s = table.fields[i];
      if (key != s.key) continue;
      if (!settingWritten(s, object) && !editing_) return Lookup::Missing;  // not in the file
      position(first + int(i));
      p_.group_ = group;
      p_.field_ = &s;
      p_.fragile_ |= s.omitDefault;
      switch (s.type) {
        case SettingType::Boolean:
        case SettingType::Text:
          return text();
        case SettingType::Number:
          return settingNumber(table, s, Storage::Double);
        case SettingType::Vector: {
          if (end()) return Lookup::NotANumber;
          const int c = index(3);
          if (c < 0) return Lookup::Missing;
          p_.c_ = c;
          return settingNumber(table, s, Storage::Double);
        }
        case SettingType::OptionalNumber:
          if (!s.value<std::optional<double>>(object) && !editing_) return Lookup::Missing;  // not written until set
          p_.fragile_ = true;
          return settingNumber(table, s, Storage::Optional);
        case SettingType::Integer:
          return settingInteger(table, s, Storage::Int);
        case SettingType::Count:
          return settingInteger(table, s, Storage::Int64);
        case SettingType::Seed:
          return table.words == SettingWords::IntegerRange
                     ? number(Where::Setting, Reader::IntegerRange, Storage::UInt64, s.min, s.max)
                     : number(Where::Setting, Reader::Seed, Storage::UInt64);
        case SettingType::Choice:
        case SettingType::CalculatorVars:
        case SettingType::MorphPairs:
        case SettingType::NodeMoves:
          return text();  // no settings group has these
      }
    }
    return Lookup::Missing;
  }

  // "camera": its table, "ortho" (written beside it), and the optional "stereo" block.
  Lookup camera() {
    if (end()) return Lookup::NotANumber;
    const std::string_view key = token();
    const int fields = int(cameraTable().fields.size());
    if (key == "ortho") {
      position(fields);
      return text();
    }
    if (key == "stereo" && project_.camera.stereo) {
      position(fields + 1);
      p_.fragile_ = true;  // gone when the stereo pair is switched off
      return settingsObject(stereoTable(), Group::Stereo, &*project_.camera.stereo);
    }
    return settingField(cameraTable(), Group::Camera, &project_.camera, key);
  }

  // As io/settings_json reads a number by the table's words.
  Lookup settingNumber(const SettingTable& table, const SettingSpec& s, Storage storage) {
    if (table.words == SettingWords::FiniteOnly) return number(Where::Setting, Reader::AnyFinite, storage);
    // A field with a noun or a message of its own: validation names the range, as it does after reading.
    if (s.noun || s.invalid) return number(Where::Setting, Reader::Finite, storage);
    return number(Where::Setting, Reader::Number, storage, s.min, s.max);
  }

  Lookup settingInteger(const SettingTable& table, const SettingSpec& s, Storage storage) {
    if (table.words == SettingWords::IntegerRange)
      return number(Where::Setting, Reader::IntegerRange, storage, s.min, s.max);
    if (!s.noun)
      return number(Where::Setting, Reader::Integer, storage, double(std::int64_t(s.min)), double(std::int64_t(s.max)));
    return number(Where::Setting, Reader::NounInteger, storage, s.min, s.max);
  }

  Lookup render() {
    if (end()) return Lookup::NotANumber;
    const std::string_view key = token();
    const RenderSettings& r = project_.render;
    const int fields = int(renderSettingsTable().fields.size());
    if (key == "mode") return text();
    if (key == "flame") {
      position(fields + 1);
      return settingsObject(flameSettingsTable(), Group::Flame, &r.flame);
    }
    if (key == "shading") {
      // Written when it says something, so it comes and goes with the values inside.
      if (!(r.mode == DisplayMode::Shaded || !(r.shading == ShadingSettings{})) && !editing_) return Lookup::Missing;
      position(fields + 2);
      p_.fragile_ = true;
      return shading();
    }
    if (key == "volume" && (r.volume || editing_)) {
      position(fields + 3);
      p_.fragile_ |= !r.volume;
      static const VolumeRenderSettings defaults;
      const VolumeRenderSettings& v = r.volume ? *r.volume : defaults;
      if (end()) return Lookup::NotANumber;
      const std::string_view field = token();
      if (field == "transfer") {
        position(int(volumeRenderTable().fields.size()));
        if (end()) return Lookup::NotANumber;
        const int stop = index(v.transfer.size());
        if (stop < 0) return Lookup::Missing;
        p_.a_ = stop;
        return settingsObject(transferStopTable(), Group::TransferStop, &v.transfer[std::size_t(stop)]);
      }
      return settingField(volumeRenderTable(), Group::VolumeRender, &v, field);
    }
    return settingField(renderSettingsTable(), Group::Render, &r, key);
  }

  Lookup shading() {
    if (end()) return Lookup::NotANumber;
    const std::string_view key = token();
    const ShadingSettings& s = project_.render.shading;
    if (key == "lights") {
      position(0);
      if (end()) return Lookup::NotANumber;
      const int light = index(s.lights.size());
      if (light < 0) return Lookup::Missing;
      p_.a_ = light;
      return settingsObject(shadingLightTable(), Group::Light, &s.lights[std::size_t(light)]);
    }
    if (key == "ao") {
      position(2);
      return settingsObject(ambientOcclusionTable(), Group::Ao, &s.ao);
    }
    if (key == "fog") {
      position(3);
      return settingsObject(fogTable(), Group::Fog, &s.fog);
    }
    if (key == "dof") {
      position(4);
      return settingsObject(depthOfFieldTable(), Group::Dof, &s.dof);
    }
    position(1);
    return settingField(shadingSettingsTable(), Group::Shading, &s, key);
  }

  Lookup volume() {
    if (end()) return Lookup::NotANumber;
    const std::string_view key = token();
    const VolumeSettings& v = *project_.volume;
    if (key == "start") {
      // The deterministic algorithm's start set: the set accessors with no function.
      if (!v.start) return Lookup::Missing;
      position(int(volumeSettingsTable().fields.size()) + 1);
      p_.f_ = ProjectParameter::kStartSet;
      return set(*v.start);
    }
    if (key != "field") return settingField(volumeSettingsTable(), Group::Volume, &v, key);
    if (!v.field) return Lookup::Missing;
    position(int(volumeSettingsTable().fields.size()));
    if (end()) return Lookup::NotANumber;
    // One layer is an object; several are a list (io/volume_io).
    const VolumeDensityField* layer = &*v.field;
    if (!v.more_fields.empty()) {
      const int i = index(1 + v.more_fields.size());
      if (i < 0) return Lookup::Missing;
      p_.layerList_ = true;
      p_.a_ = i;
      if (i > 0) layer = &v.more_fields[std::size_t(i - 1)];
      if (end()) return Lookup::NotANumber;
    }
    const std::string_view field = token();
    if (field == "strength") return settingField(fieldLayerTable(), Group::FieldLayer, layer, field);
    if (const Lookup found = layerField(*layer, field); found != Lookup::Missing) return found;
    // The field operation's parameters but its amplitude (io/volume_io).
    const std::vector<ParamSpec>& params = findOperation("field")->params;
    for (std::size_t i = 0; i < params.size(); ++i) {
      const ParamSpec& s = params[i];
      if (field != s.key || field == "amplitude") continue;
      position(int(i) + 1);
      p_.field_ = &s;
      // Where the parameter sits in FractalFieldParams: the table locates members of an
      // operation, the volume keeps the bare parameters.
      OpParams probe{FieldOp{}};
      p_.offset_ = std::size_t(static_cast<const char*>(s.locate(&probe)) -
                               reinterpret_cast<const char*>(&std::get<FieldOp>(probe)));
      return simpleParam(s, Where::DensityParam);
    }
    return Lookup::Missing;
  }

  /// A field layer's role, placement and shape (io/volume_io's writeLayerFields: each is in the
  /// file only while it differs from the single field's default, as there).
  Lookup layerField(const VolumeDensityField& layer, std::string_view key) {
    const VolumeDensityField defaults;
    const int after = int(findOperation("field")->params.size()) + 1;
    if (key == "role") return layer.role != defaults.role ? text() : Lookup::Missing;
    if (key != "strength" && key != "shape")
      if (const Lookup found = settingField(fieldLayerTable(), Group::FieldLayer, &layer, key, after);
          found != Lookup::Missing)
        return found;
    if (key == "shape" && layer.shape) {
      position(after + 5);
      p_.layerShape_ = true;
      p_.fragile_ = true;
      return set(*layer.shape);
    }
    return Lookup::Missing;
  }

  // ---- functions (io/project_io, io/free_form_io, io/volume_io) ----

  Lookup function(const Function& fn) {
    if (end()) return Lookup::NotANumber;
    const std::string_view key = token();
    // Positions follow readFunction.
    if (key == "name") return text();
    // The numbers every kind holds (schema/settings_tables.h), read after the resolution.
    for (const SettingSpec& s : functionTable().fields)
      if (key == s.key) return settingField(functionTable(), Group::Function, &fn, key, 1);
    switch (fn.kind) {
      case FunctionKind::Matrix:
        if (key == "kind") return text();
        if (key == "matrix") {
          position(11);
          if (end()) return Lookup::NotANumber;
          const int row = index(fn.matrix.size());
          if (row < 0) return Lookup::Missing;
          p_.a_ = row;
          return component(int(fn.matrix[std::size_t(row)].size()), Where::MatrixEntry, Reader::Number,
                           barycentricEntryField().min, barycentricEntryField().max);
        }
        return Lookup::Missing;
      case FunctionKind::Condensation:
      case FunctionKind::Median:
        if (key == "kind") return text();
        if (key == "set") {
          position(12);
          return set(fn.set);
        }
        if (key == "rotate" && fn.kind == FunctionKind::Median) {
          position(13);
          return number(Where::MedianRotate, Reader::Number, Storage::Double, medianRotateField().min,
                        medianRotateField().max);
        }
        if (key == "rotate_axis" && fn.kind == FunctionKind::Median &&
            (fn.rotate_axis != Vec3{0.0, 0.0, 1.0} || editing_)) {
          position(14);
          return component(3, Where::MedianRotateAxis, Reader::Number, medianRotateAxisField().min,
                           medianRotateAxisField().max);
        }
        return Lookup::Missing;
      case FunctionKind::Grid:
        break;
    }
    if (key == "resolution") {
      position(0);
      return component(3, Where::Resolution, Reader::Integer, gridResolutionField().min, gridResolutionField().max,
                       Storage::Int);
    }
    if (key == "placement") {
      position(7);
      return settingsObject(placementTable(), Group::Placement, &fn.placement);
    }
    if (key == "ops") {
      position(8);
      if (end()) return Lookup::NotANumber;
      const int o = index(fn.ops.size());
      if (o < 0) return Lookup::Missing;
      p_.o_ = o;
      return operation(fn.ops[std::size_t(o)]);
    }
    if (key == "interpolation" && fn.interpolation != LatticeInterpolation::Trilinear) return text();
    // Positions follow io/variation_io's reader: the variations, their parameters, the post map.
    if (key == "variations") {
      position(9);
      return namedNumber(fn.variations, Where::VariationWeight);
    }
    if (key == "variation_params") {
      position(10);
      return namedNumber(fn.variation_params, Where::VariationParam);
    }
    if (key == "post" && fn.post) {
      position(14);
      if (!fn.post->matrix) return settingsObject(placementTable(), Group::PostPlacement, &fn.post->placement);
      if (end() || token() != "matrix") return end() ? Lookup::NotANumber : Lookup::Missing;
      if (end()) return Lookup::NotANumber;
      const int row = index(3);
      if (row < 0) return Lookup::Missing;
      p_.a_ = row;
      return component(4, Where::PostMatrix, Reader::Number, postMatrixEntryField().min, postMatrixEntryField().max);
    }
    return Lookup::Missing;
  }

  /// A number of a {"name": number} object (a function's variations or their parameters), at
  /// the name's place in the file's sorted order.
  Lookup namedNumber(const std::map<std::string, double>& values, Where where) {
    if (end()) return values.empty() ? Lookup::Missing : Lookup::NotANumber;
    const std::string name(token());
    const auto it = values.find(name);
    if (it == values.end()) {
      // An edit may set a variation's parameter the file does not hold yet (it has its default).
      int variation = -1, parameter = -1;
      if (!(editing_ && where == Where::VariationParam && findVariationParameter(name, variation, parameter)))
        return Lookup::Missing;
      p_.fragile_ = true;
    }
    position(int(std::distance(values.begin(), values.lower_bound(name))));
    p_.key_ = name;
    // As io/variation_io reads them (json_read::readFinite): any number of magnitude at most 1e6.
    return number(where, Reader::Finite, Storage::Double);
  }

  Lookup set(const CondensationSet& set) {
    if (end()) return Lookup::NotANumber;
    const std::string_view key = token();
    // Positions follow io/volume_io's writeSet: the source's name, the shape's numbers
    // (condensationSetTable), the placement.
    static constexpr const char* kNames[] = {"primitive", "mesh", "fill", "vdb", "grid", "image"};
    for (const char* name : kNames)
      if (key == name) return text();
    if (key == "placement" && (set.shape == SetShape::Mesh || set.shape == SetShape::Image)) {
      position(int(condensationSetTable(set.shape).fields.size()) + 1);
      return settingsObject(placementTable(), Group::SetPlacement, &set.placement);
    }
    return settingField(condensationSetTable(set.shape), Group::Set, &set, key, 1);
  }

  // ---- operations (schema/operation_table.h, written by io/operation_json) ----

  Lookup operation(const Operation& op) {
    if (end()) return Lookup::NotANumber;
    const std::string_view key = token();
    const OperationSpec& spec = operationSpec(op.params);
    const int params = int(spec.params.size());
    // Positions follow readOperation: the parameters, the center, the selection.
    if (key == "type") return text();
    if (key == "muted") return op.muted ? text() : Lookup::Missing;  // written when set
    if (key == "center") {
      if (op.center.kind != Center::Kind::Point) return text();
      position(params);
      return component(3, Where::OpCenter, Reader::Number, -kMaxCoordinate, kMaxCoordinate);
    }
    if (key == "selection") {
      position(params + 1);
      if (end()) return Lookup::NotANumber;
      const int box = index(op.selection.size());
      if (box < 0) return Lookup::Missing;
      p_.a_ = box;
      if (end()) return Lookup::NotANumber;
      const std::string_view axis = token();
      if (axis == "op") return text();
      const int b = keyIndex(axis, kSelectionAxes);
      if (b < 0) return Lookup::Missing;
      position(b);
      p_.b_ = b;
      return component(2, Where::SelectionBound, Reader::Integer, 0.0, limits::kMaxResolution - 1, Storage::Int);
    }
    for (int i = 0; i < params; ++i) {
      const ParamSpec& s = spec.params[std::size_t(i)];
      if (key != s.key) continue;
      position(i);
      p_.field_ = &s;
      return param(s, op.params);
    }
    return Lookup::Missing;
  }

  /// A number, an integer, a seed, a vector or a choice, as io/operation_json reads them.
  Lookup simpleParam(const ParamSpec& s, Where where) {
    switch (s.type) {
      case ParamType::Number:
        return number(where, Reader::Number, Storage::Double, s.min, s.max);
      case ParamType::Integer:
        return number(where, Reader::Integer, Storage::Int, double(std::int64_t(s.min)), double(std::int64_t(s.max)));
      case ParamType::Seed:
        return number(where, Reader::Seed, Storage::UInt64);
      case ParamType::Vector:
        return component(s.components, where, Reader::Number, s.min, s.max);
      default:
        return text();
    }
  }

  Lookup param(const ParamSpec& s, const OpParams& params) {
    switch (s.type) {
      case ParamType::CalculatorVars: {
        // {"v1": {"value", "min", "max"}, ...}; reading meets min, max, value.
        if (end()) return Lookup::NotANumber;
        const std::string_view name = token();
        if (name.size() != 2 || name[0] != 'v' || name[1] < '1' || name[1] > '3') return Lookup::Missing;
        p_.a_ = name[1] - '1';
        position(p_.a_);
        if (end()) return Lookup::NotANumber;
        const int b = keyIndex(token(), kCalculatorFields);
        if (b < 0) return Lookup::Missing;
        position((b + 2) % 3);
        p_.b_ = b;
        return number(Where::CalculatorVar, Reader::Number, Storage::Double, -kMaxCoordinate, kMaxCoordinate);
      }
      case ParamType::MorphPairs: {
        // [[from, to], ...]
        if (end()) return Lookup::NotANumber;
        const int pair = index(s.value<std::vector<MorphPair>>(params).size());
        if (pair < 0) return Lookup::Missing;
        p_.a_ = pair;
        if (end()) return Lookup::NotANumber;
        const int b = index(2);
        if (b < 0) return Lookup::Missing;
        p_.b_ = b;
        return component(3, Where::MorphPoint, Reader::Number, -kMaxCoordinate, kMaxCoordinate);
      }
      case ParamType::NodeMoves: {
        // [[i, j, k, [dx, dy, dz]], ...]
        if (end()) return Lookup::NotANumber;
        const int move = index(s.value<std::vector<NodeMove>>(params).size());
        if (move < 0) return Lookup::Missing;
        p_.a_ = move;
        if (end()) return Lookup::NotANumber;
        const int slot = index(4);
        if (slot < 0) return Lookup::Missing;
        if (slot == 3) return component(3, Where::NodeMoveShift, Reader::Number, -kMaxCoordinate, kMaxCoordinate);
        p_.c_ = slot;
        return number(Where::NodeMoveIndex, Reader::Integer, Storage::Int, 0.0, limits::kMaxResolution - 1);
      }
      default:
        return simpleParam(s, Where::OpParam);
    }
  }

  const Project& project_;
  const TrackPath& path_;
  /// ParameterScope::Edit: numbers the file leaves out while they keep their defaults count too.
  bool editing_ = false;
  std::size_t at_ = 0;
  std::size_t depth_ = 0;
  ProjectParameter p_;
};

ParameterSpan ProjectParameter::span() const {
  if (field_ && field_->sliderMin < field_->sliderMax)
    return {std::max(field_->sliderMin, field_->min), std::min(field_->sliderMax, field_->max)};
  if (std::isfinite(lo_) && std::isfinite(hi_) && lo_ < hi_ && hi_ - lo_ <= 1000.0) return {lo_, hi_};
  return {};
}

FoundParameter findParameter(const Project& project, const TrackPath& path, ParameterScope scope) {
  return ParameterResolver(project, path, scope).run();
}

// ---- access ----------------------------------------------------------------------------------

CondensationSet& ProjectParameter::setOf(Project& project) const {
  if (f_ == kStartSet) return *project.volume->start;
  if (layerShape_) return *fieldLayerOf(project, a_).shape;
  return (f_ < 0 ? *project.final_function : project.functions[std::size_t(f_)]).set;
}

std::string ProjectParameter::setPath() const {
  if (f_ == kStartSet) return "volume.start";
  if (layerShape_) return layerPathOf(layerList_, a_) + ".shape";
  return (f_ < 0 ? std::string("final") : item("functions", f_)) + ".set";
}

void* ProjectParameter::locate(Project& project) const {
  auto vectorComponent = [&](Vec3& v) -> void* { return &v[c_]; };
  if (where_ == Where::Setting) {
    void* group = nullptr;
    ShadingSettings& shading = project.render.shading;
    switch (group_) {
      case Group::Function:
        group = f_ < 0 ? &*project.final_function : &project.functions[std::size_t(f_)];
        break;
      case Group::Placement:
        group = f_ < 0 ? &project.final_function->placement : &project.functions[std::size_t(f_)].placement;
        break;
      case Group::PostPlacement:
        group = f_ < 0 ? &project.final_function->post->placement : &project.functions[std::size_t(f_)].post->placement;
        break;
      case Group::FieldLayer:
        group = &fieldLayerOf(project, a_);
        break;
      case Group::Set:
        group = &setOf(project);
        break;
      case Group::SetPlacement:
        group = &setOf(project).placement;
        break;
      case Group::Camera:
        group = &project.camera;
        break;
      case Group::Stereo:
        group = &*project.camera.stereo;
        break;
      case Group::Render:
        group = &project.render;
        break;
      case Group::Flame:
        group = &project.render.flame;
        break;
      case Group::VolumeRender:
        // An edit may set a number of "render.volume" before the project has one (its defaults).
        if (!project.render.volume) project.render.volume.emplace();
        group = &*project.render.volume;
        break;
      case Group::TransferStop:
        group = &project.render.volume->transfer[std::size_t(a_)];
        break;
      case Group::Light:
        group = &shading.lights[std::size_t(a_)];
        break;
      case Group::Shading:
        group = &shading;
        break;
      case Group::Ao:
        group = &shading.ao;
        break;
      case Group::Fog:
        group = &shading.fog;
        break;
      case Group::Dof:
        group = &shading.dof;
        break;
      case Group::Animation:
        group = &*project.animation;
        break;
      case Group::Volume:
        group = &*project.volume;
        break;
    }
    return fieldComponent(field_->locate(group));
  }
  switch (where_) {
    case Where::Transition:
      return &project.transitions[std::size_t(a_)][std::size_t(c_)];
    case Where::ControlPoint:
      return vectorComponent(project.space->control_points[std::size_t(a_)]);
    case Where::DensityParam: {
      return fieldComponent(reinterpret_cast<char*>(&fieldLayerOf(project, a_).field) + offset_);
    }
    case Where::Time:
      return &project.time;
    case Where::Version:
      return nullptr;
    default:
      break;
  }
  Function& fn = f_ < 0 ? *project.final_function : project.functions[std::size_t(f_)];
  switch (where_) {
    case Where::Resolution:
      return &fn.resolution[std::size_t(c_)];
    case Where::MatrixEntry:
      return &fn.matrix[std::size_t(a_)][std::size_t(c_)];
    case Where::MedianRotate:
      return &fn.rotate;
    case Where::MedianRotateAxis:
      return vectorComponent(fn.rotate_axis);
    case Where::VariationWeight:
      return &fn.variations.at(key_);
    case Where::VariationParam:
      return &fn.variation_params[key_];  // an edit adds a parameter the function lacks
    case Where::PostMatrix:
      return &(*fn.post->matrix)[std::size_t(a_)][std::size_t(c_)];

    default:
      break;
  }
  Operation& op = fn.ops[std::size_t(o_)];
  switch (where_) {
    case Where::OpParam:
      return fieldComponent(field_->locate(&op.params));
    case Where::CalculatorVar: {
      CalculatorVar& var = field_->value<std::array<CalculatorVar, 3>>(op.params)[std::size_t(a_)];
      return b_ == 0 ? &var.value : b_ == 1 ? &var.min : &var.max;
    }
    case Where::MorphPoint: {
      MorphPair& pair = field_->value<std::vector<MorphPair>>(op.params)[std::size_t(a_)];
      return vectorComponent(b_ == 0 ? pair.from : pair.to);
    }
    case Where::NodeMoveIndex:
      return &field_->value<std::vector<NodeMove>>(op.params)[std::size_t(a_)].index[std::size_t(c_)];
    case Where::NodeMoveShift:
      return vectorComponent(field_->value<std::vector<NodeMove>>(op.params)[std::size_t(a_)].displacement);
    case Where::OpCenter:
      return vectorComponent(op.center.point);
    case Where::SelectionBound: {
      SelectionBox& box = op.selection[std::size_t(a_)];
      return &(b_ == 0 ? box.i : b_ == 1 ? box.j : box.k)[std::size_t(c_)];
    }
    default:
      return nullptr;
  }
}

void* ProjectParameter::fieldComponent(void* field) const {
  return field_->type == FieldType::Vector ? static_cast<double*>(field) + c_ : field;
}

double ProjectParameter::get(const Project& project) const {
  // A project without "render.volume" reads its defaults (locate() would add one).
  if (where_ == Where::Setting && group_ == Group::VolumeRender && !project.render.volume) {
    static const VolumeRenderSettings defaults;
    return field_->number(&defaults, field_->type == SettingType::Vector ? c_ : 0);
  }
  // A variation parameter the function does not hold yet reads its default (locate() would add it).
  if (where_ == Where::VariationParam) {
    const Function& fn = f_ < 0 ? *project.final_function : project.functions[std::size_t(f_)];
    int variation = -1, parameter = -1;
    if (!fn.variation_params.count(key_) && findVariationParameter(key_, variation, parameter))
      return flameVariations()[std::size_t(variation)].params[std::size_t(parameter)].second;
  }
  // locate() hands out a pointer into the project; here it is only read.
  const void* slot = locate(const_cast<Project&>(project));
  switch (storage_) {
    case Storage::Double:
      return *static_cast<const double*>(slot);
    case Storage::Int:
      return double(*static_cast<const int*>(slot));
    case Storage::Int64:
      return double(*static_cast<const std::int64_t*>(slot));
    case Storage::UInt64:
      return double(*static_cast<const std::uint64_t*>(slot));
    case Storage::Optional:
      return static_cast<const std::optional<double>*>(slot)->value_or(0.0);
    case Storage::None:
      break;
  }
  return double(kProjectFormatVersion);
}

void ProjectParameter::set(Project& project, double value) const {
  // The file would hold a value that is not finite as null, which an optional number reads as
  // unset.
  if (storage_ == Storage::Optional && !std::isfinite(value)) {
    *static_cast<std::optional<double>*>(locate(project)) = std::nullopt;
    return;
  }
  check(value);
  void* slot = locate(project);
  switch (storage_) {
    case Storage::Double:
      *static_cast<double*>(slot) = value;
      break;
    case Storage::Int:
      *static_cast<int*>(slot) = int(value);
      break;
    case Storage::Int64:
      *static_cast<std::int64_t*>(slot) = std::int64_t(value);
      break;
    case Storage::UInt64:
      *static_cast<std::uint64_t*>(slot) = std::uint64_t(value);
      break;
    case Storage::Optional:
      *static_cast<std::optional<double>*>(slot) = value;
      break;
    case Storage::None:
      break;
  }
}

// The file readers' checks and words (io/json_read, io/settings_json, io/free_form_io,
// io/volume_io). A value that is not finite reaches them as null.
void ProjectParameter::check(double v) const {
  const bool finite = std::isfinite(v);
  auto integerRange = [](std::int64_t lo, std::int64_t hi) {
    return "expected an integer between " + std::to_string(lo) + " and " + std::to_string(hi);
  };
  switch (reader_) {
    case Reader::Number:
      if (!finite) fail(path(), "expected a number, found null");
      if (v < lo_ || v > hi_)
        fail(path(), "expected a number between " + show(lo_) + " and " + show(hi_) + ", found " + show(v));
      return;
    case Reader::Integer:
      if (!finite) fail(path(), "expected an integer, found null");
      if (v != std::floor(v)) fail(path(), "expected an integer");
      if (v < lo_ || v > hi_) fail(path(), integerRange(std::int64_t(lo_), std::int64_t(hi_)));
      return;
    case Reader::Seed:
      if (!finite) fail(path(), "expected a non-negative integer, found null");
      if (!(v >= 0 && v == std::floor(v) && v < 1.8e19))
        fail(path(), "expected a non-negative integer, found a number");
      return;
    case Reader::Finite:
    case Reader::NounInteger:
      if (!finite) fail(path(), "expected a number, found null");
      if (std::abs(v) > kMaxCoordinate) fail(path(), "expected a finite number");
      if (reader_ == Reader::NounInteger && (v != std::floor(v) || v < lo_ || v > hi_))
        fail(path(), integerRange(std::int64_t(lo_), std::int64_t(hi_)));
      return;
    case Reader::AnyFinite:
    case Reader::Time:
      if (!finite) fail(path(), "expected a number");
      return;
    case Reader::IntegerRange: {
      const std::int64_t lo = integerBound(lo_), hi = integerBound(hi_);
      if (!finite || v != std::floor(v) || v < double(lo) || v > double(hi)) fail(path(), integerRange(lo, hi));
      return;
    }
    case Reader::Version: {
      std::string found = versionText(v);
      if (found.size() > 20) found = found.substr(0, 20) + "…";
      fail("version", "unsupported version " + found + " (this GridIFS reads version " +
                          std::to_string(kProjectFormatVersion) + ")");
    }
  }
}

bool ProjectParameter::inAnimation() const { return where_ == Where::Setting && group_ == Group::Animation; }

std::string ProjectParameter::path() const {
  if (where_ == Where::Setting) {
    std::string group;
    switch (group_) {
      case Group::Function:
        group = f_ < 0 ? std::string("final") : item("functions", f_);
        break;
      case Group::Placement:
        group = (f_ < 0 ? std::string("final") : item("functions", f_)) + ".placement";
        break;
      case Group::PostPlacement:
        group = (f_ < 0 ? std::string("final") : item("functions", f_)) + ".post";
        break;
      case Group::FieldLayer:
        group = layerPathOf(layerList_, a_);
        break;
      case Group::Set:
        group = setPath();
        break;
      case Group::SetPlacement:
        group = setPath() + ".placement";
        break;
      case Group::Camera:
        group = "camera";
        break;
      case Group::Stereo:
        group = "camera.stereo";
        break;
      case Group::Render:
        group = "render";
        break;
      case Group::Flame:
        group = "render.flame";
        break;
      case Group::VolumeRender:
        group = "render.volume";
        break;
      case Group::TransferStop:
        group = item("render.volume.transfer", a_);
        break;
      case Group::Light:
        group = item("render.shading.lights", a_);
        break;
      case Group::Shading:
        group = "render.shading";
        break;
      case Group::Ao:
        group = "render.shading.ao";
        break;
      case Group::Fog:
        group = "render.shading.fog";
        break;
      case Group::Dof:
        group = "render.shading.dof";
        break;
      case Group::Animation:
        group = "animation";
        break;
      case Group::Volume:
        group = "volume";
        break;
    }
    const std::string field = settingPath(group, field_->key);
    return field_->type == SettingType::Vector ? item(field, c_) : field;
  }
  switch (where_) {
    case Where::Transition:
      return item(item("transitions", a_), c_);
    case Where::ControlPoint:
      return item(item("space.control_points", a_), c_);
    case Where::DensityParam: {
      const std::string field = layerPathOf(layerList_, a_) + "." + field_->key;
      return field_->type == ParamType::Vector ? item(field, c_) : field;
    }
    case Where::Time:
      return "time";
    case Where::Version:
      return "version";
    default:
      break;
  }
  const std::string fn = f_ < 0 ? std::string("final") : item("functions", f_);
  switch (where_) {
    case Where::Resolution:
      return item(fn + ".resolution", c_);
    case Where::MatrixEntry:
      return item(item(fn + ".matrix", a_), c_);
    case Where::MedianRotate:
      return fn + ".rotate";
    case Where::MedianRotateAxis:
      return item(fn + ".rotate_axis", c_);
    case Where::VariationWeight:
      return fn + ".variations." + key_;
    case Where::VariationParam:
      return fn + ".variation_params." + key_;
    case Where::PostMatrix:
      return item(item(fn + ".post.matrix", a_), c_);
    default:
      break;
  }
  const std::string op = item(fn + ".ops", o_);
  switch (where_) {
    case Where::OpParam: {
      const std::string p = op + "." + field_->key;
      return field_->type == ParamType::Vector ? item(p, c_) : p;
    }
    case Where::CalculatorVar:
      return op + "." + field_->key + ".v" + std::to_string(a_ + 1) + "." + kCalculatorFields[b_];
    case Where::MorphPoint:
      return item(item(item(op + "." + field_->key, a_), b_), c_);
    case Where::NodeMoveIndex:
      return item(item(op + "." + field_->key, a_), c_);
    case Where::NodeMoveShift:
      return item(item(item(op + "." + field_->key, a_), 3), c_);
    case Where::OpCenter:
      return item(op + ".center", c_);
    case Where::SelectionBound:
      return item(item(op + ".selection", a_) + "." + kSelectionAxes[b_], c_);
    default:
      return op;
  }
}

}  // namespace gridifs
