#include "io/project_io.h"

#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>
#include <sstream>

#include "base/atomic_file.h"
#include "base/bounded_read.h"
#include "io/animation_io.h"
#include "io/animation_json.h"
#include "io/free_form_io.h"
#include "io/json_read.h"
#include "io/settings_json.h"
#include "io/shading_io.h"
#include "io/volume_io.h"
#include "model/operation_table.h"
#include "model/settings_tables.h"
#include "model/transition_matrix.h"
#include "model/validation.h"

namespace gridifs {
namespace {

using json = nlohmann::json;
using ordered_json = nlohmann::ordered_json;

using namespace json_read;

double number(const json& obj, const char* key, const std::string& path, double fallback,
              double lo = -limits::kMaxCoordinate, double hi = limits::kMaxCoordinate) {
  auto it = obj.find(key);
  if (it == obj.end()) return fallback;
  return readNumber(*it, join(path, key), lo, hi);
}

std::uint64_t unsignedInteger(const json& obj, const char* key, const std::string& path, std::uint64_t fallback) {
  auto it = obj.find(key);
  return it == obj.end() ? fallback : readSeed(*it, join(path, key));
}

bool boolean(const json& obj, const char* key, const std::string& path, bool fallback) {
  auto it = obj.find(key);
  return it == obj.end() ? fallback : readBoolean(*it, join(path, key));
}

std::string string(const json& obj, const char* key, const std::string& path, const std::string& fallback,
                   std::size_t maxLength) {
  auto it = obj.find(key);
  if (it == obj.end()) return fallback;
  return readString(*it, join(path, key), maxLength);
}

Vec3 vec3(const json& obj, const char* key, const std::string& path, Vec3 fallback,
          double lo = -limits::kMaxCoordinate, double hi = limits::kMaxCoordinate) {
  auto it = obj.find(key);
  if (it == obj.end()) return fallback;
  return readVec3(*it, join(path, key), lo, hi);
}

Center readCenter(const json& obj, const std::string& path) {
  Center c;
  auto it = obj.find("center");
  if (it == obj.end()) return c;
  const std::string p = join(path, "center");
  if (it->is_string()) {
    const std::string s = it->get<std::string>();
    if (s == "grid") c.kind = Center::Kind::Grid;
    else if (s == "selection") c.kind = Center::Kind::Selection;
    else fail(p, "expected \"grid\", \"selection\" or a point [x, y, z]");
  } else {
    c.kind = Center::Kind::Point;
    c.point = readVec3(*it, p, -limits::kMaxCoordinate, limits::kMaxCoordinate);
  }
  return c;
}

std::array<int, 2> readRange(const json& box, const char* key, const std::string& path) {
  auto it = box.find(key);
  if (it == box.end()) return {0, limits::kMaxResolution - 1};
  const std::string p = join(path, key);
  if (!it->is_array() || it->size() != 2) fail(p, "expected an index range [first, last]");
  return {int(readInteger((*it)[0], item(p, 0), 0, limits::kMaxResolution - 1)),
          int(readInteger((*it)[1], item(p, 1), 0, limits::kMaxResolution - 1))};
}

Selection readSelection(const json& obj, const std::string& path) {
  Selection selection;
  auto it = obj.find("selection");
  if (it == obj.end()) return selection;
  const std::string p = join(path, "selection");
  if (!it->is_array()) fail(p, std::string("expected an array of index boxes, found ") + typeName(*it));
  if (it->size() > std::size_t(limits::kMaxSelectionBoxes))
    fail(p, "more than " + std::to_string(limits::kMaxSelectionBoxes) + " selection boxes");
  for (std::size_t b = 0; b < it->size(); ++b) {
    const json& box = (*it)[b];
    const std::string bp = item(p, b);
    requireObject(box, bp);
    SelectionBox s;
    s.i = readRange(box, "i", bp);
    s.j = readRange(box, "j", bp);
    s.k = readRange(box, "k", bp);
    const std::string op = string(box, "op", bp, "or", 16);
    if (!parseSelectionOp(op, s.op)) fail(join(bp, "op"), "expected \"or\", \"and\", \"xor\" or \"minus\"");
    selection.push_back(s);
  }
  return selection;
}

CalculatorVar readCalculatorVar(const json& v, const std::string& path) {
  requireObject(v, path);
  CalculatorVar var;
  var.min = number(v, "min", path, var.min);
  var.max = number(v, "max", path, var.max);
  var.value = number(v, "value", path, var.value);
  if (var.min > var.max) fail(join(path, "min"), "the slider minimum is larger than its maximum");
  return var;
}

/// Reads one parameter of the operation table into `params`; an absent key keeps the default.
void readParam(const ParamSpec& s, const json& o, const std::string& opPath, OpParams& params) {
  auto it = o.find(s.key);
  if (it == o.end()) return;
  const std::string path = join(opPath, s.key);
  switch (s.type) {
    case ParamType::Number: s.setNumber(params, 0, readNumber(*it, path, s.min, s.max)); break;
    case ParamType::Integer:
      s.setNumber(params, 0, double(readInteger(*it, path, std::int64_t(s.min), std::int64_t(s.max))));
      break;
    case ParamType::Seed: s.value<std::uint64_t>(params) = unsignedInteger(o, s.key, opPath, 0); break;
    case ParamType::Vector: {
      if (!it->is_array() || it->size() != std::size_t(s.components))
        fail(path, "expected an array of " + std::to_string(s.components) + " numbers");
      for (int c = 0; c < s.components; ++c) s.setNumber(params, c, readNumber((*it)[c], item(path, c), s.min, s.max));
      break;
    }
    case ParamType::Choice: {
      const std::string name = readString(*it, path, 16);
      int index = 0;
      while (index < int(s.choices->names.size()) && name != s.choices->names[std::size_t(index)]) ++index;
      if (index == int(s.choices->names.size())) fail(path, "expected " + choiceList(*s.choices));
      s.setChoice(params, index);
      break;
    }
    case ParamType::Expression: s.value<std::string>(params) = readString(*it, path, s.maxLength); break;
    case ParamType::CalculatorVars: {
      requireObject(*it, path);
      auto& vars = s.value<std::array<CalculatorVar, 3>>(params);
      for (auto v = it->begin(); v != it->end(); ++v) {
        const std::string& name = v.key();
        if (name != "v1" && name != "v2" && name != "v3")
          fail(join(path, name.substr(0, 32)), "unknown calculator variable (use v1, v2 or v3)");
        vars[std::size_t(name[1] - '1')] = readCalculatorVar(v.value(), join(path, name));
      }
      break;
    }
    case ParamType::MorphPairs: {
      if (!it->is_array()) fail(path, std::string("expected an array of [start, end] pairs, found ") + typeName(*it));
      if (it->size() > std::size_t(limits::kMaxMorphPairs))
        fail(path, "more than " + std::to_string(limits::kMaxMorphPairs) + " morph pairs");
      auto& pairs = s.value<std::vector<MorphPair>>(params);
      pairs.clear();
      for (std::size_t i = 0; i < it->size(); ++i) {
        const json& pair = (*it)[i];
        if (!pair.is_array() || pair.size() != 2) fail(item(path, i), "expected a pair [[x, y, z], [x, y, z]]");
        pairs.push_back({readVec3(pair[0], item(item(path, i), 0), -limits::kMaxCoordinate, limits::kMaxCoordinate),
                         readVec3(pair[1], item(item(path, i), 1), -limits::kMaxCoordinate, limits::kMaxCoordinate)});
      }
      break;
    }
    case ParamType::NodeMoves: {
      if (!it->is_array()) fail(path, std::string("expected an array of [i, j, k, [dx, dy, dz]], found ") + typeName(*it));
      if (it->size() > std::size_t(limits::kMaxNodeMoves)) fail(path, "too many node moves");
      auto& moves = s.value<std::vector<NodeMove>>(params);
      moves.clear();
      for (std::size_t m = 0; m < it->size(); ++m) {
        const json& mv = (*it)[m];
        const std::string mp = item(path, m);
        if (!mv.is_array() || mv.size() != 4) fail(mp, "expected [i, j, k, [dx, dy, dz]]");
        NodeMove move;
        for (int d = 0; d < 3; ++d) move.index[d] = int(readInteger(mv[d], item(mp, d), 0, limits::kMaxResolution - 1));
        move.displacement = readVec3(mv[3], item(mp, 3), -limits::kMaxCoordinate, limits::kMaxCoordinate);
        moves.push_back(move);
      }
      break;
    }
  }
}

Operation readOperation(const json& o, const std::string& path) {
  requireObject(o, path);
  auto typeIt = o.find("type");
  if (typeIt == o.end()) fail(path, "the operation has no \"type\"");
  const std::string type = readString(*typeIt, join(path, "type"), 64);
  const OperationSpec* spec = findOperation(type);
  if (!spec)
    fail(join(path, "type"), "unknown operation \"" + type.substr(0, 40) + "\" (expected " + operationTypeList() + ")");
  Operation op;
  op.params = spec->defaults;
  for (const ParamSpec& param : spec->params) readParam(param, o, path, op.params);
  op.center = readCenter(o, path);
  op.selection = readSelection(o, path);
  op.muted = boolean(o, "muted", path, false);
  return op;
}

Function readFunction(const json& f, const std::string& path, std::size_t index) {
  requireObject(f, path);
  Function fn;
  fn.name = string(f, "name", path, "f" + std::to_string(index + 1), limits::kMaxNameLength);
  if (auto it = f.find("resolution"); it != f.end()) {
    const std::string p = join(path, "resolution");
    if (!it->is_array() || it->size() != 3) fail(p, "expected an array of 3 integers");
    for (int d = 0; d < 3; ++d)
      fn.resolution[d] = int(readInteger((*it)[d], item(p, d), limits::kMinResolution, limits::kMaxResolution));
  }
  fn.weight = number(f, "weight", path, 1.0, 0.0, 1e9);
  fn.color = vec3(f, "color", path, Vec3{1.0}, 0.0, 1.0);
  fn.palette_index = number(f, "palette_index", path, 0.0, 0.0, 1.0);
  fn.color_speed = number(f, "color_speed", path, 0.5, 0.0, 1.0);
  fn.muted = boolean(f, "muted", path, false);
  if (auto it = f.find("sampling_error"); it != f.end() && !it->is_null())
    fn.sampling_error = readNumber(*it, join(path, "sampling_error"), 0.0, limits::kMaxCoordinate);
  if (auto it = f.find("placement"); it != f.end()) {
    const std::string p = join(path, "placement");
    requireObject(*it, p);
    fn.placement.translate = vec3(*it, "translate", p, Vec3{0.0});
    fn.placement.rotate = vec3(*it, "rotate", p, Vec3{0.0});
    fn.placement.scale = vec3(*it, "scale", p, Vec3{1.0});
  }
  if (auto it = f.find("ops"); it != f.end()) {
    const std::string p = join(path, "ops");
    if (!it->is_array()) fail(p, std::string("expected an array of operations, found ") + typeName(*it));
    if (it->size() > std::size_t(limits::kMaxOpsPerFunction))
      fail(p, "more than " + std::to_string(limits::kMaxOpsPerFunction) + " operations");
    for (std::size_t o = 0; o < it->size(); ++o) fn.ops.push_back(readOperation((*it)[o], item(p, o)));
  }
  free_form_io::readFunctionFields(f, path, fn);
  volume_io::readSetFunctionFields(f, path, fn);
  return fn;
}

/// Rejects nesting deeper than the format needs before handing text to the parser.
void checkDepth(const std::string& text) {
  int depth = 0;
  bool inString = false, escaped = false;
  for (char ch : text) {
    if (inString) {
      if (escaped) escaped = false;
      else if (ch == '\\') escaped = true;
      else if (ch == '"') inString = false;
      continue;
    }
    if (ch == '"') inString = true;
    else if (ch == '[' || ch == '{') {
      if (++depth > limits::kMaxJsonDepth)
        fail("", "the JSON is nested more than " + std::to_string(limits::kMaxJsonDepth) + " levels deep");
    } else if (ch == ']' || ch == '}') --depth;
  }
}

ordered_json writeVec3(const Vec3& v) { return ordered_json::array({v.x, v.y, v.z}); }

ordered_json writeParam(const ParamSpec& s, const OpParams& params) {
  switch (s.type) {
    case ParamType::Number: return s.value<double>(params);
    case ParamType::Integer: return s.value<int>(params);
    case ParamType::Seed: return s.value<std::uint64_t>(params);
    case ParamType::Vector: {
      ordered_json a = ordered_json::array();
      for (int c = 0; c < s.components; ++c) a.push_back(s.number(params, c));
      return a;
    }
    case ParamType::Choice: return s.choices->names[std::size_t(s.choice(params))];
    case ParamType::Expression: return s.value<std::string>(params);
    case ParamType::CalculatorVars: {
      ordered_json vars;
      const auto& v = s.value<std::array<CalculatorVar, 3>>(params);
      for (int i = 0; i < 3; ++i)
        vars["v" + std::to_string(i + 1)] = {{"value", v[std::size_t(i)].value}, {"min", v[std::size_t(i)].min},
                                             {"max", v[std::size_t(i)].max}};
      return vars;
    }
    case ParamType::MorphPairs: {
      ordered_json pairs = ordered_json::array();
      for (const MorphPair& pair : s.value<std::vector<MorphPair>>(params))
        pairs.push_back({writeVec3(pair.from), writeVec3(pair.to)});
      return pairs;
    }
    case ParamType::NodeMoves: {
      ordered_json moves = ordered_json::array();
      for (const NodeMove& m : s.value<std::vector<NodeMove>>(params))
        moves.push_back({m.index[0], m.index[1], m.index[2], writeVec3(m.displacement)});
      return moves;
    }
  }
  return nullptr;
}

ordered_json writeOperation(const Operation& op) {
  ordered_json o;
  const OperationSpec& spec = operationSpec(op.params);
  o["type"] = spec.type;
  for (const ParamSpec& param : spec.params) o[param.key] = writeParam(param, op.params);
  if (op.center.kind == Center::Kind::Grid) o["center"] = "grid";
  else if (op.center.kind == Center::Kind::Selection) o["center"] = "selection";
  else o["center"] = writeVec3(op.center.point);
  ordered_json selection = ordered_json::array();
  for (const SelectionBox& b : op.selection)
    selection.push_back({{"i", {b.i[0], b.i[1]}}, {"j", {b.j[0], b.j[1]}}, {"k", {b.k[0], b.k[1]}}, {"op", selectionOpName(b.op)}});
  o["selection"] = selection;
  if (op.muted) o["muted"] = true;
  return o;
}

ordered_json writeFunction(const Function& f) {
  if (free_form_io::isMatrixFunction(f)) return free_form_io::writeMatrixFunction(f);
  if (isSetKind(f.kind)) return volume_io::writeSetFunction(f);
  ordered_json o;
  o["name"] = f.name;
  o["resolution"] = {f.resolution[0], f.resolution[1], f.resolution[2]};
  o["weight"] = f.weight;
  o["color"] = writeVec3(f.color);
  o["palette_index"] = f.palette_index;
  o["color_speed"] = f.color_speed;
  o["muted"] = f.muted;
  if (f.sampling_error) o["sampling_error"] = *f.sampling_error;
  o["placement"] = {{"translate", writeVec3(f.placement.translate)},
                    {"rotate", writeVec3(f.placement.rotate)},
                    {"scale", writeVec3(f.placement.scale)}};
  ordered_json ops = ordered_json::array();
  for (const Operation& op : f.ops) ops.push_back(writeOperation(op));
  o["ops"] = ops;
  free_form_io::writeGridFunctionFields(f, o);
  return o;
}

std::string lineColumn(const std::string& text, std::size_t byte) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') ++line, column = 1;
    else ++column;
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

}  // namespace

Project parseProject(const std::string& text) {
  if (text.size() > limits::kMaxFileBytes) fail("", "the file is larger than 64 MiB");
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) fail("", "the file is empty");
  checkDepth(text);
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    std::string what = e.what();
    const std::size_t lastContent = text.find_last_not_of(" \t\r\n");
    const bool truncated = what.find("unexpected end of input") != std::string::npos ||
                           (lastContent != std::string::npos && e.byte >= lastContent + 1);
    fail("", std::string(truncated ? "the JSON ends too early (truncated?)" : "the file is not valid JSON") +
                 " at " + lineColumn(text, e.byte == 0 ? 0 : e.byte - 1));
  } catch (const json::exception&) {
    fail("", "the file contains a number too large to represent");
  }
  requireObject(root, "");
  if (auto it = root.find("format"); it == root.end() || !it->is_string() || it->get<std::string>() != "gridifs")
    fail("format", "expected \"gridifs\" (this is not a GridIFS project)");
  auto version = root.find("version");
  if (version == root.end()) fail("version", "the project has no version");
  if (!version->is_number_integer() || version->get<std::int64_t>() != kProjectFormatVersion) {
    std::string found = version->dump();
    if (found.size() > 20) found = found.substr(0, 20) + "…";
    fail("version", "unsupported version " + found + " (this GridIFS reads version " +
                        std::to_string(kProjectFormatVersion) + ")");
  }
  Project project;
  if (auto it = root.find("camera"); it != root.end()) project.camera = readSettings(cameraTable(), *it, "camera");
  if (auto it = root.find("render"); it != root.end()) {
    RenderSettings& r = project.render;
    readSettingFields(renderSettingsTable(), *it, "render", &r);
    if (auto m = it->find("mode"); m != it->end()) {
      if (!parseDisplayMode(readString(*m, "render.mode", 32), r.mode))
        fail("render.mode", "expected \"zbuffer\", \"flame\" or \"shaded\"");
    }
    if (auto fl = it->find("flame"); fl != it->end()) r.flame = readSettings(flameSettingsTable(), *fl, "render.flame");
    if (auto sh = it->find("shading"); sh != it->end()) r.shading = readShadingSettings(*sh, "render.shading");
  }
  auto functions = root.find("functions");
  if (functions == root.end()) fail("functions", "the project has no functions");
  if (!functions->is_array()) fail("functions", std::string("expected an array, found ") + typeName(*functions));
  if (functions->empty()) fail("functions", "the IFS needs at least one function");
  if (functions->size() > std::size_t(limits::kMaxFunctions))
    fail("functions", "more than " + std::to_string(limits::kMaxFunctions) + " functions (found " +
                          std::to_string(functions->size()) + ")");
  for (std::size_t f = 0; f < functions->size(); ++f)
    project.functions.push_back(readFunction((*functions)[f], item("functions", f), f));
  if (auto it = root.find("final"); it != root.end() && !it->is_null())
    project.final_function = readFunction(*it, "final", 0);
  if (auto it = root.find("transitions"); it != root.end() && !it->is_null()) {
    // Sizes are checked against the functions by checkTransitions; here only the JSON shape.
    if (!it->is_array()) fail("transitions", std::string("expected an array of rows, found ") + typeName(*it));
    if (it->size() > std::size_t(limits::kMaxFunctions))
      fail("transitions", "more than " + std::to_string(limits::kMaxFunctions) + " rows");
    for (std::size_t i = 0; i < it->size(); ++i) {
      const json& row = (*it)[i];
      const std::string p = item("transitions", i);
      if (!row.is_array()) fail(p, std::string("expected an array of weights, found ") + typeName(row));
      if (row.size() > std::size_t(limits::kMaxFunctions))
        fail(p, "more than " + std::to_string(limits::kMaxFunctions) + " entries");
      std::vector<double> weights;
      for (std::size_t j = 0; j < row.size(); ++j) weights.push_back(readNumber(row[j], item(p, j), 0.0, 1e9));
      project.transitions.push_back(std::move(weights));
    }
  }
  readAnimation(root, project);
  project.space = free_form_io::readSpace(root);
  project.volume = volume_io::readVolume(root);
  validateProject(project);
  checkTrackPaths(project);
  return project;
}

std::string serializeProject(const Project& project) {
  ordered_json root;
  root["format"] = "gridifs";
  root["version"] = kProjectFormatVersion;
  root["camera"] = writeSettings(cameraTable(), project.camera);
  const RenderSettings& r = project.render;
  root["render"] = writeSettings(renderSettingsTable(), r);
  root["render"]["mode"] = displayModeName(r.mode);
  root["render"]["flame"] = writeSettings(flameSettingsTable(), r.flame);
  // Written when it says something: files that never used shading save as they always have.
  if (r.mode == DisplayMode::Shaded || !(r.shading == ShadingSettings{}))
    root["render"]["shading"] = writeShadingSettings(r.shading);
  ordered_json functions = ordered_json::array();
  for (const Function& f : project.functions) functions.push_back(writeFunction(f));
  free_form_io::writeSpace(project, root);
  root["functions"] = functions;
  if (project.final_function) root["final"] = writeFunction(*project.final_function);
  if (!project.transitions.empty()) root["transitions"] = project.transitions;
  volume_io::writeVolume(project, root);
  writeAnimation(project, root);
  return root.dump(2) + "\n";
}

Project loadProject(const std::filesystem::path& file) {
  const std::optional<std::string> text = readBoundedFile(file, limits::kMaxFileBytes, "project file");
  if (!text) fail("", "the file is larger than 64 MiB");
  return parseProject(*text);
}

void saveProject(const Project& project, const std::filesystem::path& file) {
  namespace fs = std::filesystem;
  validateProject(project);  // never write a project that could not be read back
  AtomicFile out(file);
  out.write(serializeProject(project));
  std::error_code ec;
  if (fs::exists(file, ec)) {
    fs::path backup = file;
    backup += "~";
    fs::copy_file(file, backup, fs::copy_options::overwrite_existing, ec);
    if (ec) throw IoError("cannot keep a backup of " + file.string() + ": " + ec.message());
  }
  out.commit();
}

}  // namespace gridifs
