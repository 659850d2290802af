#pragma once
// Bindings: a number of the project, named by its parameter path, driven by live
// input or by sound. A binding maps its source's value v ∈ [0, 1] to min + v·(max − min) and
// sets it over whatever the parameter's track says:
// - "audio:B": the energy of band B of the project's audio in each frame's window, divided by
//   the band's largest over the file (live/audio_envelope.h);
// - "osc:/ADDRESS": the last float sent to the address (0..1);
// - "midi:cc:N" or "midi:CH:cc:N": controller N (0..127, on channel CH 1..16, else any) / 127.
//
// Thread-safety: pure functions of their arguments.
#include <optional>
#include <string>

#include "model/project.h"
#include "schema/project_parameter.h"

namespace gridifs {

struct BindingSource {
  enum class Kind { Audio, Osc, Midi } kind = Kind::Audio;
  int band = 0;         // Audio
  std::string address;  // Osc: "/knob1"
  int channel = 0;      // Midi: 1..16, or 0 for any channel
  int controller = 0;   // Midi: 0..127
};

/// Parses a binding's source. Returns nothing when `text` is no source this format knows.
std::optional<BindingSource> parseBindingSource(const std::string& text);

/// Checks every binding of `project` as reading the file does: its path names a number of the
/// project, its source is known (an audio band the project's "audio" has), min and max are
/// numbers that parameter accepts, and smooth is in [0, 60] seconds. Throws ModelError at
/// "bindings[i].path" (".source", ".min", ...), with the parameter's own words for a bad range.
void checkBindings(const Project& project);

/// The parameter binding `index` of `project` drives. Expects checkBindings to have passed.
ProjectParameter boundParameter(const Project& project, std::size_t index);

/// Drops the bindings whose path names no number of `project` any more (the function or the
/// operation it named was removed), so that an edit never leaves a project the file reader
/// would refuse. Returns how many went.
std::size_t dropUnresolvedBindings(Project& project);

/// The value binding `binding` gives its parameter for v in [0, 1] (clamped; NaN counts as 0),
/// rounded to a whole number for whole-number parameters.
double boundValue(const Binding& binding, const ProjectParameter& parameter, double v);

}  // namespace gridifs
