#include "io/operation_json.h"

#include <stdexcept>

#include "io/json_read.h"

namespace gridifs::operation_json {
namespace {

using json = nlohmann::json;
using ordered_json = nlohmann::ordered_json;
using namespace json_read;

double number(const json& obj, const char* key, const std::string& path, double fallback) {
  auto it = obj.find(key);
  if (it == obj.end()) return fallback;
  return readNumber(*it, join(path, key), -limits::kMaxCoordinate, limits::kMaxCoordinate);
}

ordered_json vec3Json(const Vec3& v) { return ordered_json::array({v.x, v.y, v.z}); }

CalculatorVar readCalculatorVar(const json& v, const std::string& path) {
  requireObject(v, path);
  CalculatorVar var;
  var.min = number(v, "min", path, var.min);
  var.max = number(v, "max", path, var.max);
  var.value = number(v, "value", path, var.value);
  if (var.min > var.max) fail(join(path, "min"), "the slider minimum is larger than its maximum");
  return var;
}

}  // namespace

void readParam(const ParamSpec& s, const json& o, const std::string& opPath, OpParams& params) {
  auto it = o.find(s.key);
  if (it == o.end()) return;
  const std::string path = join(opPath, s.key);
  switch (s.type) {
    case ParamType::Number:
      s.setNumber(params, 0, readNumber(*it, path, s.min, s.max));
      break;
    case ParamType::Integer:
      s.setNumber(params, 0, double(readInteger(*it, path, std::int64_t(s.min), std::int64_t(s.max))));
      break;
    case ParamType::Seed:
      s.value<std::uint64_t>(params) = readSeed(*it, path);
      break;
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
    case ParamType::Expression:
      s.value<std::string>(params) = readString(*it, path, s.maxLength);
      break;
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
      if (!it->is_array())
        fail(path, std::string("expected an array of [i, j, k, [dx, dy, dz]], found ") + typeName(*it));
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
    case ParamType::Count:
    case ParamType::Boolean:
    case ParamType::OptionalNumber:
      throw std::logic_error(std::string("operation parameter ") + s.key + " has a type operations cannot hold");
  }
}

ordered_json writeParam(const ParamSpec& s, const OpParams& params) {
  switch (s.type) {
    case ParamType::Number:
      return s.value<double>(params);
    case ParamType::Integer:
      return s.value<int>(params);
    case ParamType::Seed:
      return s.value<std::uint64_t>(params);
    case ParamType::Vector: {
      ordered_json a = ordered_json::array();
      for (int c = 0; c < s.components; ++c) a.push_back(s.number(params, c));
      return a;
    }
    case ParamType::Choice:
      return s.choices->names[std::size_t(s.choice(params))];
    case ParamType::Expression:
      return s.value<std::string>(params);
    case ParamType::CalculatorVars: {
      ordered_json vars;
      const auto& v = s.value<std::array<CalculatorVar, 3>>(params);
      for (int i = 0; i < 3; ++i)
        vars["v" + std::to_string(i + 1)] = {
            {"value", v[std::size_t(i)].value}, {"min", v[std::size_t(i)].min}, {"max", v[std::size_t(i)].max}};
      return vars;
    }
    case ParamType::MorphPairs: {
      ordered_json pairs = ordered_json::array();
      for (const MorphPair& pair : s.value<std::vector<MorphPair>>(params))
        pairs.push_back({vec3Json(pair.from), vec3Json(pair.to)});
      return pairs;
    }
    case ParamType::NodeMoves: {
      ordered_json moves = ordered_json::array();
      for (const NodeMove& m : s.value<std::vector<NodeMove>>(params))
        moves.push_back({m.index[0], m.index[1], m.index[2], vec3Json(m.displacement)});
      return moves;
    }
    case ParamType::Count:
    case ParamType::Boolean:
    case ParamType::OptionalNumber:
      break;  // no operation has these
  }
  return nullptr;
}

}  // namespace gridifs::operation_json
