#include "schema/live_binding.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

#include "anim/track_path.h"
#include "base/errors.h"

namespace gridifs {
namespace {

// A whole number in [lo, hi] spelt with digits only.
std::optional<int> wholeIn(const std::string& text, int lo, int hi) {
  if (text.empty() || text.size() > 4) return std::nullopt;
  for (const char c : text)
    if (!std::isdigit(static_cast<unsigned char>(c))) return std::nullopt;
  const int n = std::atoi(text.c_str());
  if (n < lo || n > hi) return std::nullopt;
  return n;
}

std::string bindingItem(std::size_t index, const char* key) { return "bindings[" + std::to_string(index) + "]." + key; }

constexpr const char* kSourceForms =
    "expected a source like \"audio:0\", \"osc:/knob1\", \"midi:cc:7\" or \"midi:1:cc:7\"";

}  // namespace

std::optional<BindingSource> parseBindingSource(const std::string& text) {
  BindingSource source;
  if (text.rfind("audio:", 0) == 0) {
    const auto band = wholeIn(text.substr(6), 0, 63);
    if (!band) return std::nullopt;
    source.kind = BindingSource::Kind::Audio;
    source.band = *band;
    return source;
  }
  if (text.rfind("osc:", 0) == 0) {
    // OSC addresses start with '/' and hold no spaces, '#' or the pattern characters.
    const std::string address = text.substr(4);
    if (address.size() < 2 || address.size() > 256 || address[0] != '/') return std::nullopt;
    for (const char c : address)
      if (std::isspace(static_cast<unsigned char>(c)) || c == '#' || c == '*' || c == '?' || c == ',' || c == '[' ||
          c == ']' || c == '{' || c == '}' || !std::isprint(static_cast<unsigned char>(c)))
        return std::nullopt;
    source.kind = BindingSource::Kind::Osc;
    source.address = address;
    return source;
  }
  if (text.rfind("midi:", 0) == 0) {
    std::string rest = text.substr(5);
    source.kind = BindingSource::Kind::Midi;
    if (rest.rfind("cc:", 0) != 0) {
      const std::size_t colon = rest.find(':');
      if (colon == std::string::npos) return std::nullopt;
      const auto channel = wholeIn(rest.substr(0, colon), 1, 16);
      if (!channel) return std::nullopt;
      source.channel = *channel;
      rest = rest.substr(colon + 1);
      if (rest.rfind("cc:", 0) != 0) return std::nullopt;
    }
    const auto controller = wholeIn(rest.substr(3), 0, 127);
    if (!controller) return std::nullopt;
    source.controller = *controller;
    return source;
  }
  return std::nullopt;
}

ProjectParameter boundParameter(const Project& project, std::size_t index) {
  const Binding& b = project.bindings[index];
  const std::optional<TrackPath> parsed = TrackPath::parse(b.path);
  if (!parsed) throw ModelError(bindingItem(index, "path"), "is not a parameter path like functions[0].ops[1].k");
  const FoundParameter found = findParameter(project, *parsed);
  if (found.lookup == ParameterLookup::NotANumber)
    throw ModelError(bindingItem(index, "path"), "names a parameter that is not a number, so it cannot be bound");
  if (found.lookup == ParameterLookup::Missing)
    throw ModelError(bindingItem(index, "path"), "names no parameter of this project (" + b.path + ")");
  if (found.parameter.isTime())
    throw ModelError(bindingItem(index, "path"), "\"time\" is the moment itself and cannot be bound");
  return found.parameter;
}

void checkBindings(const Project& project) {
  for (std::size_t i = 0; i < project.bindings.size(); ++i) {
    const Binding& b = project.bindings[i];
    const ProjectParameter parameter = boundParameter(project, i);
    const std::optional<BindingSource> source = parseBindingSource(b.source);
    if (!source) throw ModelError(bindingItem(i, "source"), kSourceForms + std::string(", not \"") + b.source + "\"");
    if (source->kind == BindingSource::Kind::Audio) {
      if (!project.audio)
        throw ModelError(bindingItem(i, "source"), b.source + " needs the project's \"audio\", and it has none");
      if (source->band >= int(project.audio->bands.size()))
        throw ModelError(bindingItem(i, "source"), b.source + " names band " + std::to_string(source->band) +
                                                       ", but \"audio\" has " +
                                                       std::to_string(project.audio->bands.size()) + " bands");
    }
    if (!(b.smooth >= 0.0 && b.smooth <= 60.0))
      throw ModelError(bindingItem(i, "smooth"), "expected a number of seconds between 0 and 60");
    // Both ends must be values the parameter takes, with the parameter's own words.
    for (const auto& [key, value] : {std::pair{"min", b.min}, std::pair{"max", b.max}}) {
      Project probe = project;
      try {
        parameter.set(probe, parameter.wholeNumber() ? std::round(value) : value);
      } catch (const ModelError& e) {
        throw ModelError(bindingItem(i, key), e.message() + " (the range of " + b.path + ")");
      }
    }
  }
}

std::size_t dropUnresolvedBindings(Project& project) {
  const std::size_t before = project.bindings.size();
  auto& list = project.bindings;
  list.erase(std::remove_if(list.begin(), list.end(),
                            [&](const Binding& b) {
                              const std::optional<TrackPath> parsed = TrackPath::parse(b.path);
                              return !parsed || findParameter(project, *parsed).lookup != ParameterLookup::Number;
                            }),
             list.end());
  return before - list.size();
}

double boundValue(const Binding& binding, const ProjectParameter& parameter, double v) {
  v = v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0;  // NaN → 0
  const double value = binding.min + v * (binding.max - binding.min);
  return parameter.wholeNumber() ? std::round(value) : value;
}

}  // namespace gridifs
