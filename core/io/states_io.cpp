#include "io/states_io.h"

#include <algorithm>
#include <string>

#include "io/json_read.h"

namespace gridifs::states_io {
namespace {

using json_read::item;
using json_read::readInteger;
using json_read::typeName;

using json = nlohmann::json;
using ordered_json = nlohmann::ordered_json;

[[noreturn]] void fail(const std::string& path, const std::string& message) { throw ModelError(path, message); }

std::uint32_t readFunctionRef(const json& j, const std::string& path, const std::vector<Function>& functions) {
  if (j.is_string()) {
    const std::string& name = j.get_ref<const std::string&>();
    std::size_t found = functions.size(), count = 0;
    for (std::size_t f = 0; f < functions.size(); ++f)
      if (functions[f].name == name && count++ == 0) found = f;
    if (count == 0) fail(path, "no function is named \"" + name.substr(0, 64) + "\"");
    if (count > 1) fail(path, std::to_string(count) + " functions are named \"" + name + "\"; use an index instead");
    return std::uint32_t(found);
  }
  if (!j.is_number_integer() && !j.is_number_unsigned())
    fail(path, std::string("expected a function index or name, found ") + typeName(j));
  const std::int64_t f = j.get<std::int64_t>();
  if (f < 0 || std::size_t(f) >= functions.size())
    fail(path, "function " + std::to_string(f) + " does not exist (the project has " +
                   std::to_string(functions.size()) + " functions)");
  return std::uint32_t(f);
}

std::vector<std::uint32_t> readStateList(const json& obj, const char* key, std::size_t n) {
  const std::string path = std::string("states.") + key;
  auto it = obj.find(key);
  if (it == obj.end() || it->is_null()) fail(path, std::string("the ") + key + " state set is missing");
  if (!it->is_array()) fail(path, std::string("expected an array of state indices, found ") + typeName(*it));
  if (it->size() > kMaxFileStates) fail(path, "more than " + std::to_string(kMaxFileStates) + " states");
  std::vector<std::uint32_t> out;
  for (std::size_t k = 0; k < it->size(); ++k) {
    const std::int64_t q = readInteger((*it)[k], item(path, k), 0, std::int64_t(kMaxFileStates) - 1);
    if (std::size_t(q) >= n)
      fail(item(path, k),
           "state " + std::to_string(q) + " does not exist (the matrix has " + std::to_string(n) + " states)");
    out.push_back(std::uint32_t(q));
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace

std::optional<IfsStates> readStates(const json& root, const std::vector<Function>& functions) {
  auto it = root.find("states");
  if (it == root.end() || it->is_null()) return std::nullopt;
  if (!it->is_object()) fail("states", "expected an object with \"matrix\", \"initial\" and \"final\"");
  auto matrix = it->find("matrix");
  if (matrix == it->end()) fail("states.matrix", "the states have no matrix");
  if (!matrix->is_array()) fail("states.matrix", std::string("expected an array of rows, found ") + typeName(*matrix));
  const std::size_t n = matrix->size();
  if (n == 0) fail("states.matrix", "the matrix needs at least one state");
  if (n > kMaxFileStates) fail("states.matrix", "more than " + std::to_string(kMaxFileStates) + " states");
  IfsStates s;
  for (std::size_t i = 0; i < n; ++i) {
    const json& row = (*matrix)[i];
    const std::string rp = item("states.matrix", i);
    if (!row.is_array()) fail(rp, std::string("expected an array of entries, found ") + typeName(row));
    if (row.size() != n)
      fail(rp,
           "expected " + std::to_string(n) + " entries (the matrix is square), found " + std::to_string(row.size()));
    s.matrix.emplace_back();
    for (std::size_t j = 0; j < n; ++j) {
      const json& entry = row[j];
      const std::string ep = item(rp, j);
      if (!entry.is_array()) fail(ep, std::string("expected an array of functions, found ") + typeName(entry));
      if (entry.size() > functions.size() + 64) fail(ep, "too many functions in one entry");
      std::vector<std::uint32_t> fs;
      for (std::size_t k = 0; k < entry.size(); ++k) fs.push_back(readFunctionRef(entry[k], item(ep, k), functions));
      std::sort(fs.begin(), fs.end());
      fs.erase(std::unique(fs.begin(), fs.end()), fs.end());
      s.matrix.back().push_back(std::move(fs));
    }
  }
  s.initial = readStateList(*it, "initial", n);
  s.final = readStateList(*it, "final", n);
  return s;
}

void writeStates(const Project& project, ordered_json& root) {
  if (!project.states) return;
  ordered_json states = ordered_json::object();
  states["matrix"] = project.states->matrix;
  states["initial"] = project.states->initial;
  states["final"] = project.states->final;
  root["states"] = std::move(states);
}

}  // namespace gridifs::states_io
