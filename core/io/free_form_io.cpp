#include "io/free_form_io.h"

#include <cmath>

#include "freeform/free_form.h"
#include "io/json_read.h"
#include "io/settings_json.h"
#include "schema/settings_tables.h"

namespace gridifs::free_form_io {
namespace {

using json = nlohmann::json;
using ordered_json = nlohmann::ordered_json;

[[noreturn]] void fail(const std::string& path, const std::string& message) { throw ModelError(path, message); }
std::string item(const std::string& path, std::size_t index) { return path + "[" + std::to_string(index) + "]"; }

/// A number of `field`'s range, in the words the parameter paths use for it.
double readInRange(const json& j, const std::string& path, const FieldInfo& field) {
  return json_read::readNumber(j, path, field.min, field.max);
}

std::string readWord(const json& j, const std::string& path) {
  if (!j.is_string() || j.get_ref<const std::string&>().size() > 32) fail(path, "expected a short string");
  return j.get<std::string>();
}

}  // namespace

std::optional<FreeFormSpace> readSpace(const json& root) {
  auto it = root.find("space");
  if (it == root.end() || it->is_null()) return std::nullopt;
  if (!it->is_object()) fail("space", "expected an object with \"control_points\"");
  auto points = it->find("control_points");
  if (points == it->end()) fail("space.control_points", "the space has no control points");
  if (!points->is_array()) fail("space.control_points", "expected an array of [x, y, z] points");
  if (points->size() > std::size_t(limits::kMaxControlPoints) ||
      points->size() < std::size_t(limits::kMinControlPoints))
    fail("space.control_points", "expected between " + std::to_string(limits::kMinControlPoints) + " and " +
                                     std::to_string(limits::kMaxControlPoints) + " control points, found " +
                                     std::to_string(points->size()));
  FreeFormSpace space;
  const FieldInfo& point = controlPointField();
  for (std::size_t j = 0; j < points->size(); ++j) {
    const json& p = (*points)[j];
    const std::string path = item("space.control_points", j);
    if (!p.is_array() || p.size() != 3) fail(path, "expected an array of 3 numbers");
    space.control_points.push_back(Vec3{readInRange(p[0], item(path, 0), point),
                                        readInRange(p[1], item(path, 1), point),
                                        readInRange(p[2], item(path, 2), point)});
  }
  return space;
}

void readFunctionFields(const json& f, const std::string& path, Function& fn) {
  if (auto it = f.find("kind"); it != f.end()) {
    const std::string kind = readWord(*it, path + ".kind");
    if (kind == "grid")
      fn.kind = FunctionKind::Grid;
    else if (kind == "matrix")
      fn.kind = FunctionKind::Matrix;
    else if (kind == "condensation")
      fn.kind = FunctionKind::Condensation;
    else if (kind == "median")
      fn.kind = FunctionKind::Median;
    else
      fail(path + ".kind", "expected \"grid\", \"matrix\", \"condensation\" or \"median\", found \"" + kind + "\"");
  }
  if (auto it = f.find("interpolation"); it != f.end()) {
    const std::string word = readWord(*it, path + ".interpolation");
    if (word == "trilinear")
      fn.interpolation = LatticeInterpolation::Trilinear;
    else if (word == "bezier")
      fn.interpolation = LatticeInterpolation::Bezier;
    else
      fail(path + ".interpolation", "expected \"trilinear\" or \"bezier\", found \"" + word + "\"");
  }
  if (fn.kind == FunctionKind::Matrix) {
    for (const char* gridField : {"resolution", "placement", "ops"})
      if (f.contains(gridField))
        fail(path + "." + gridField, "a \"matrix\" function has no grid, so no \"" + std::string(gridField) + "\"");
    auto it = f.find("matrix");
    if (it == f.end()) fail(path + ".matrix", "a \"matrix\" function needs its m×m matrix");
    const std::string p = path + ".matrix";
    if (!it->is_array()) fail(p, "expected an array of rows");
    if (it->size() > std::size_t(limits::kMaxControlPoints))
      fail(p, "more than " + std::to_string(limits::kMaxControlPoints) + " rows");
    for (std::size_t i = 0; i < it->size(); ++i) {
      const json& row = (*it)[i];
      const std::string rp = item(p, i);
      if (!row.is_array()) fail(rp, "expected an array of numbers");
      if (row.size() > std::size_t(limits::kMaxControlPoints))
        fail(rp, "more than " + std::to_string(limits::kMaxControlPoints) + " entries");
      std::vector<double> values;
      for (std::size_t j = 0; j < row.size(); ++j)
        values.push_back(readInRange(row[j], item(rp, j), barycentricEntryField()));
      fn.matrix.push_back(std::move(values));
    }
  } else if (f.contains("matrix")) {
    fail(path + ".matrix", "only a function of kind \"matrix\" has a matrix");
  }
}

ordered_json writeMatrixFunction(const Function& fn) {
  ordered_json o;
  o["name"] = fn.name;
  o["kind"] = functionKindName(fn.kind);
  o["matrix"] = fn.matrix;
  for (const char* key : {"weight", "color", "palette_index", "color_speed", "muted"})
    writeSettingField(functionTable().field(key), &fn, o);
  return o;
}

void writeGridFunctionFields(const Function& fn, ordered_json& out) {
  if (fn.interpolation != LatticeInterpolation::Trilinear)
    out["interpolation"] = latticeInterpolationName(fn.interpolation);
}

void writeSpace(const Project& project, ordered_json& root) {
  if (!project.space) return;
  ordered_json points = ordered_json::array();
  for (const Vec3& p : project.space->control_points) points.push_back(ordered_json::array({p.x, p.y, p.z}));
  root["space"] = {{"control_points", points}};
}

}  // namespace gridifs::free_form_io
