#include "io/project_io.h"

#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>
#include <sstream>

#include "base/atomic_file.h"
#include "base/bounded_read.h"
#include "construction/construction_evaluation.h"
#include "freeform/transition_matrix.h"
#include "io/animation_json.h"
#include "io/construction_io.h"
#include "io/free_form_io.h"
#include "io/json_read.h"
#include "io/live_io.h"
#include "io/operation_json.h"
#include "io/settings_json.h"
#include "io/shading_io.h"
#include "io/states_io.h"
#include "io/variation_io.h"
#include "io/volume_io.h"
#include "io/volume_render_io.h"
#include "schema/live_binding.h"
#include "schema/operation_table.h"
#include "schema/project_time.h"
#include "schema/settings_tables.h"
#include "schema/validation.h"

namespace gridifs {
namespace {

using json = nlohmann::json;
using ordered_json = nlohmann::ordered_json;

using namespace json_read;

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

Center readCenter(const json& obj, const std::string& path) {
  Center c;
  auto it = obj.find("center");
  if (it == obj.end()) return c;
  const std::string p = join(path, "center");
  if (it->is_string()) {
    const std::string s = it->get<std::string>();
    if (s == "grid")
      c.kind = Center::Kind::Grid;
    else if (s == "selection")
      c.kind = Center::Kind::Selection;
    else
      fail(p, "expected \"grid\", \"selection\" or a point [x, y, z]");
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
  for (const ParamSpec& param : spec->params) operation_json::readParam(param, o, path, op.params);
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
    const FieldInfo& resolution = gridResolutionField();
    for (int d = 0; d < 3; ++d)
      fn.resolution[d] =
          int(readInteger((*it)[d], item(p, d), std::int64_t(resolution.min), std::int64_t(resolution.max)));
  }
  readSettingFields(functionTable(), f, path, &fn);
  if (auto it = f.find("placement"); it != f.end()) {
    readSettingFields(placementTable(), *it, join(path, "placement"), &fn.placement);
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
  variation_io::readFunctionFields(f, path, fn);
  return fn;
}

/// Rejects nesting deeper than the format needs before handing text to the parser.
void checkDepth(const std::string& text) {
  int depth = 0;
  bool inString = false, escaped = false;
  for (char ch : text) {
    if (inString) {
      if (escaped)
        escaped = false;
      else if (ch == '\\')
        escaped = true;
      else if (ch == '"')
        inString = false;
      continue;
    }
    if (ch == '"')
      inString = true;
    else if (ch == '[' || ch == '{') {
      if (++depth > limits::kMaxJsonDepth)
        fail("", "the JSON is nested more than " + std::to_string(limits::kMaxJsonDepth) + " levels deep");
    } else if (ch == ']' || ch == '}')
      --depth;
  }
}

ordered_json writeVec3(const Vec3& v) { return ordered_json::array({v.x, v.y, v.z}); }

ordered_json writeOperation(const Operation& op) {
  ordered_json o;
  const OperationSpec& spec = operationSpec(op.params);
  o["type"] = spec.type;
  for (const ParamSpec& param : spec.params) o[param.key] = operation_json::writeParam(param, op.params);
  if (op.center.kind == Center::Kind::Grid)
    o["center"] = "grid";
  else if (op.center.kind == Center::Kind::Selection)
    o["center"] = "selection";
  else
    o["center"] = writeVec3(op.center.point);
  ordered_json selection = ordered_json::array();
  for (const SelectionBox& b : op.selection)
    selection.push_back(
        {{"i", {b.i[0], b.i[1]}}, {"j", {b.j[0], b.j[1]}}, {"k", {b.k[0], b.k[1]}}, {"op", selectionOpName(b.op)}});
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
  writeSettingFields(functionTable(), &f, o);
  o["placement"] = writeSettings(placementTable(), f.placement);
  ordered_json ops = ordered_json::array();
  for (const Operation& op : f.ops) ops.push_back(writeOperation(op));
  o["ops"] = ops;
  free_form_io::writeGridFunctionFields(f, o);
  variation_io::writeFunctionFields(f, o);
  return o;
}

std::string lineColumn(const std::string& text, std::size_t byte) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n')
      ++line, column = 1;
    else
      ++column;
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

/// Everything but the format and version: a project's object, or a construction part's (its
/// functions, transitions and space; a part holds no construction of its own).
/// "lineage": {"parents": [files], "seed": S, "strength": X} (written by gridifs random and mutate).
std::optional<Lineage> readLineage(const json& root) {
  auto it = root.find("lineage");
  if (it == root.end() || it->is_null()) return std::nullopt;
  requireObject(*it, "lineage");
  Lineage lineage;
  if (auto parents = it->find("parents"); parents != it->end()) {
    if (!parents->is_array())
      fail("lineage.parents", std::string("expected an array of file names, found ") + typeName(*parents));
    if (parents->size() > 16) fail("lineage.parents", "more than 16 parents");
    for (std::size_t i = 0; i < parents->size(); ++i)
      lineage.parents.push_back(readString((*parents)[i], item("lineage.parents", i), 4096));
  }
  if (auto seed = it->find("seed"); seed != it->end()) lineage.seed = readSeed(*seed, "lineage.seed");
  if (auto strength = it->find("strength"); strength != it->end())
    lineage.strength = readNumber(*strength, "lineage.strength", 0.0, 1.0);
  return lineage;
}

/// "camera": its table's fields, the optional "stereo" block, and "ortho": true from files older
/// than "projection", which still means an orthographic camera.
Camera readCamera(const json& object, const std::string& path) {
  Camera camera;
  readSettingFields(cameraTable(), object, path, &camera);
  if (auto ortho = object.find("ortho"); ortho != object.end() && !object.contains("projection"))
    if (readBoolean(*ortho, join(path, "ortho"))) camera.projection = CameraProjection::Orthographic;
  if (auto stereo = object.find("stereo"); stereo != object.end() && !stereo->is_null())
    camera.stereo = readSettings(stereoTable(), *stereo, join(path, "stereo"));
  validateCamera(camera, path);
  return camera;
}

/// "ortho" stays in every file, so files of flat cameras save as they always have and older
/// readers still read them; "projection" is written only for the panoramic ones.
ordered_json writeCamera(const Camera& camera) {
  const ordered_json table = writeSettings(cameraTable(), camera);
  ordered_json out = ordered_json::object();
  for (const auto& [key, value] : table.items())
    if (key != "projection") out[key] = value;
  out["ortho"] = camera.orthographic();
  if (camera.panoramic()) out["projection"] = table["projection"];
  if (camera.stereo) out["stereo"] = writeSettings(stereoTable(), *camera.stereo);
  return out;
}

Project readProjectBody(const json& root, bool withConstruction) {
  Project project;
  if (auto it = root.find("camera"); it != root.end()) project.camera = readCamera(*it, "camera");
  if (auto it = root.find("render"); it != root.end()) {
    RenderSettings& r = project.render;
    readSettingFields(renderSettingsTable(), *it, "render", &r);
    if (auto m = it->find("mode"); m != it->end()) {
      if (!parseDisplayMode(readString(*m, "render.mode", 32), r.mode))
        fail("render.mode", "expected \"zbuffer\", \"flame\" or \"shaded\"");
    }
    if (auto fl = it->find("flame"); fl != it->end()) r.flame = readSettings(flameSettingsTable(), *fl, "render.flame");
    if (auto sh = it->find("shading"); sh != it->end()) r.shading = readShadingSettings(*sh, "render.shading");
    if (auto vr = it->find("volume"); vr != it->end())
      r.volume = volume_render_io::readVolumeRender(*vr, "render.volume");
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
      const FieldInfo& weight = transitionWeightField();
      for (std::size_t j = 0; j < row.size(); ++j)
        weights.push_back(readNumber(row[j], item(p, j), weight.min, weight.max));
      project.transitions.push_back(std::move(weights));
    }
  }
  project.states = states_io::readStates(root, project.functions);
  readAnimation(root, project);
  project.space = free_form_io::readSpace(root);
  project.volume = volume_io::readVolume(root);
  project.preview_mode = volume_render_io::readPreviewMode(root);
  if (withConstruction) project.lineage = readLineage(root);
  if (withConstruction) live_io::readLive(root, project);
  if (withConstruction) {
    project.construction = construction_io::readConstruction(root, [](const json& part, const std::string& path) {
      try {
        return readProjectBody(part, false);
      } catch (const ModelError& e) {
        throw e.under(path);
      }
    });
  }
  validateProject(project);
  checkTrackPaths(project);
  checkBindings(project);
  return project;
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
    fail("", std::string(truncated ? "the JSON ends too early (truncated?)" : "the file is not valid JSON") + " at " +
                 lineColumn(text, e.byte == 0 ? 0 : e.byte - 1));
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
  return readProjectBody(root, true);
}

std::string serializeProject(const Project& project) {
  ordered_json root;
  root["format"] = "gridifs";
  root["version"] = kProjectFormatVersion;
  root["camera"] = writeCamera(project.camera);
  const RenderSettings& r = project.render;
  root["render"] = writeSettings(renderSettingsTable(), r);
  root["render"]["mode"] = displayModeName(r.mode);
  root["render"]["flame"] = writeSettings(flameSettingsTable(), r.flame);
  // Written when it says something: files that never used shading save as they always have.
  if (r.mode == DisplayMode::Shaded || !(r.shading == ShadingSettings{}))
    root["render"]["shading"] = writeShadingSettings(r.shading);
  if (r.volume) root["render"]["volume"] = volume_render_io::writeVolumeRender(*r.volume);
  ordered_json functions = ordered_json::array();
  for (const Function& f : project.functions) functions.push_back(writeFunction(f));
  free_form_io::writeSpace(project, root);
  root["functions"] = functions;
  if (project.final_function) root["final"] = writeFunction(*project.final_function);
  if (!project.transitions.empty()) root["transitions"] = project.transitions;
  states_io::writeStates(project, root);
  volume_io::writeVolume(project, root);
  volume_render_io::writeView(project, root);
  writeAnimation(project, root);
  if (project.lineage) {
    ordered_json lineage;
    lineage["parents"] = project.lineage->parents;
    lineage["seed"] = project.lineage->seed;
    if (project.lineage->strength) lineage["strength"] = *project.lineage->strength;
    root["lineage"] = lineage;
  }
  live_io::writeLive(project, root);
  construction_io::writeConstruction(project, root, [](const Project& part, ordered_json& out) {
    ordered_json functions = ordered_json::array();
    for (const Function& f : part.functions) functions.push_back(writeFunction(f));
    free_form_io::writeSpace(part, out);
    out["functions"] = functions;
    if (!part.transitions.empty()) out["transitions"] = part.transitions;
  });
  return root.dump(2) + "\n";
}

namespace {

/// Reads `file` and the leaves of its construction tree; `chain` holds the files being read
/// around it, this one included.
Project loadProjectIn(const std::filesystem::path& file, std::vector<std::filesystem::path>& chain) {
  const std::optional<std::string> text = readBoundedFile(file, limits::kMaxFileBytes, "project file");
  if (!text) fail("", "the file is larger than 64 MiB");
  Project project = parseProject(*text);
  if (project.construction) {
    construction_io::readLeafFiles(*project.construction, file.parent_path(), chain, loadProjectIn);
    // The leaves may have changed since the file was saved: its functions are the tree's value now.
    reevaluateConstruction(project);
    validateProject(project);
  }
  return project;
}

}  // namespace

Project loadProject(const std::filesystem::path& file) {
  std::vector<std::filesystem::path> chain{construction_io::chainKey(file)};
  return loadProjectIn(file, chain);
}

void readConstructionLeaves(Project& project, const std::filesystem::path& projectFile) {
  if (!project.construction) return;
  std::vector<std::filesystem::path> chain;
  if (!projectFile.empty()) chain.push_back(construction_io::chainKey(projectFile));
  const std::filesystem::path folder = projectFile.empty() ? std::filesystem::path(".") : projectFile.parent_path();
  construction_io::readLeafFiles(*project.construction, folder, chain, loadProjectIn);
  reevaluateConstruction(project);
  validateProject(project);
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
