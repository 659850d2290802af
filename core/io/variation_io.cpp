#include "io/variation_io.h"

#include <algorithm>
#include <string_view>
#include <vector>

#include "io/json_read.h"
#include "io/settings_json.h"
#include "schema/settings_tables.h"
#include "schema/validation.h"

namespace gridifs::variation_io {

using namespace json_read;
using ordered_json = nlohmann::ordered_json;

namespace {

std::map<std::string, double> readNumbers(const json& j, const std::string& path) {
  requireObject(j, path);
  std::map<std::string, double> out;
  for (const auto& [key, value] : j.items()) out[key] = readFinite(value, join(path, key));
  return out;
}

ordered_json writeNumbers(const std::map<std::string, double>& values) {
  ordered_json o = ordered_json::object();
  for (const auto& [key, value] : values) o[key] = value;
  return o;
}

}  // namespace

void readFunctionFields(const json& f, const std::string& path, Function& fn) {
  if (auto it = f.find("variations"); it != f.end()) fn.variations = readNumbers(*it, join(path, "variations"));
  if (auto it = f.find("variation_params"); it != f.end())
    fn.variation_params = readNumbers(*it, join(path, "variation_params"));
  if (auto it = f.find("post"); it != f.end() && !it->is_null()) {
    const std::string p = join(path, "post");
    requireObject(*it, p);
    PostTransform post;
    if (auto m = it->find("matrix"); m != it->end()) {
      const std::string mp = join(p, "matrix");
      if (!m->is_array() || m->size() != 3) fail(mp, "expected 3 rows of 4 numbers");
      std::array<std::array<double, 4>, 3> rows{};
      for (std::size_t r = 0; r < 3; ++r) {
        const json& row = (*m)[r];
        if (!row.is_array() || row.size() != 4) fail(item(mp, r), "expected a row of 4 numbers");
        const FieldInfo& entry = postMatrixEntryField();
        for (std::size_t c = 0; c < 4; ++c) rows[r][c] = readNumber(row[c], item(item(mp, r), c), entry.min, entry.max);
      }
      post.matrix = rows;
    } else {
      readSettingFields(placementTable(), *it, p, &post.placement);
    }
    fn.post = post;
  }
}

void writeFunctionFields(const Function& fn, ordered_json& out) {
  if (!fn.variations.empty()) out["variations"] = writeNumbers(fn.variations);
  if (!fn.variation_params.empty()) out["variation_params"] = writeNumbers(fn.variation_params);
  if (fn.post) {
    ordered_json post = ordered_json::object();
    if (fn.post->matrix) {
      ordered_json rows = ordered_json::array();
      for (const auto& row : *fn.post->matrix) rows.push_back({row[0], row[1], row[2], row[3]});
      post["matrix"] = rows;
    } else {
      // The post map's keys have always been written in alphabetical order.
      std::vector<const SettingSpec*> fields;
      for (const SettingSpec& field : placementTable().fields) fields.push_back(&field);
      std::sort(fields.begin(), fields.end(),
                [](const SettingSpec* a, const SettingSpec* b) { return std::string_view(a->key) < b->key; });
      for (const SettingSpec* field : fields) writeSettingField(*field, &fn.post->placement, post);
    }
    out["post"] = post;
  }
}

}  // namespace gridifs::variation_io
