#pragma once
// The wind along a keyed path (Colonna, "Animation of fractal objects", §3.2: the sample point
// moves by δx(t), the wind's displacement). With a constant wind the displacement is wind·t; when
// a component of the wind is keyed, the displacement is ∫₀ᵗ wind(τ) dτ of its track, so the
// field drifts the way the keyed wind blows at each moment instead of jumping with the value at t.
//
// Thread-safety: pure function of its argument.
#include "model/project.h"

namespace gridifs {

/// Sets the `drift` of every field (the field operations and volume.field) whose wind a track
/// keys to ∫₀ᵗ wind at project.time (exact: model/keyframe_track's integral), and clears it on
/// every other field (which then drift by wind·t). Tracks that name no number are ignored.
void applyWindDrift(Project& project);

}  // namespace gridifs
