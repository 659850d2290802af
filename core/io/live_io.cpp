#include "io/live_io.h"

#include "base/errors.h"
#include "io/json_read.h"

namespace gridifs::live_io {

using namespace json_read;

void readLive(const json& root, Project& project) {
  if (auto it = root.find("audio"); it != root.end()) {
    requireObject(*it, "audio");
    AudioSettings audio;
    auto file = it->find("file");
    if (file == it->end()) fail("audio.file", "the audio has no file");
    audio.file = readString(*file, "audio.file", 4096);
    if (audio.file.empty()) fail("audio.file", "expected the name of a sound file");
    auto bands = it->find("bands");
    if (bands == it->end()) fail("audio.bands", "expected a list of frequency bands such as [[20, 200], [200, 2000]]");
    if (!bands->is_array() || bands->empty())
      fail("audio.bands", "expected a list of frequency bands such as [[20, 200], [200, 2000]]");
    if (bands->size() > kMaxAudioBands) fail("audio.bands", "more than " + std::to_string(kMaxAudioBands) + " bands");
    for (std::size_t b = 0; b < bands->size(); ++b) {
      const json& band = (*bands)[b];
      const std::string p = item("audio.bands", b);
      if (!band.is_array() || band.size() != 2) fail(p, "expected [low, high] in Hz");
      const double lo = readNumber(band[0], item(p, 0), 0.0, 1e6);
      const double hi = readNumber(band[1], item(p, 1), 0.0, 1e6);
      if (!(hi > lo)) fail(p, "the band's high frequency must be above its low one");
      audio.bands.push_back({lo, hi});
    }
    project.audio = audio;
  }
  if (auto it = root.find("bindings"); it != root.end()) {
    if (!it->is_array()) fail("bindings", std::string("expected an array of bindings, found ") + typeName(*it));
    if (it->size() > kMaxBindings) fail("bindings", "more than " + std::to_string(kMaxBindings) + " bindings");
    for (std::size_t i = 0; i < it->size(); ++i) {
      const json& entry = (*it)[i];
      const std::string p = item("bindings", i);
      requireObject(entry, p);
      Binding b;
      auto path = entry.find("path");
      if (path == entry.end()) fail(join(p, "path"), "the binding has no parameter path");
      b.path = readString(*path, join(p, "path"), 256);
      auto source = entry.find("source");
      if (source == entry.end()) fail(join(p, "source"), "the binding has no source");
      b.source = readString(*source, join(p, "source"), 300);
      auto min = entry.find("min"), max = entry.find("max");
      if (min == entry.end()) fail(join(p, "min"), "the binding has no min");
      if (max == entry.end()) fail(join(p, "max"), "the binding has no max");
      b.min = readFinite(*min, join(p, "min"));
      b.max = readFinite(*max, join(p, "max"));
      if (auto smooth = entry.find("smooth"); smooth != entry.end())
        b.smooth = readNumber(*smooth, join(p, "smooth"), 0.0, 60.0);
      project.bindings.push_back(b);
    }
  }
}

void writeLive(const Project& project, nlohmann::ordered_json& root) {
  if (project.audio) {
    nlohmann::ordered_json audio;
    audio["file"] = project.audio->file;
    audio["bands"] = project.audio->bands;
    root["audio"] = audio;
  }
  if (!project.bindings.empty()) {
    nlohmann::ordered_json bindings = nlohmann::ordered_json::array();
    for (const Binding& b : project.bindings) {
      nlohmann::ordered_json entry;
      entry["path"] = b.path;
      entry["source"] = b.source;
      entry["min"] = b.min;
      entry["max"] = b.max;
      if (b.smooth != 0.0) entry["smooth"] = b.smooth;
      bindings.push_back(entry);
    }
    root["bindings"] = bindings;
  }
}

}  // namespace gridifs::live_io
