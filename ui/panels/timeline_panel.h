#pragma once
// The timeline under the preview: play/pause, a scrub bar with the project's keys, the current
// time and frame, and the animation's range, frame rate and loop. The playhead (project.time) is
// not recorded in the undo history: artists scrub and play without filling it; the range, frame
// rate and loop are edits, one undo step each.
#include "ui/base/edit_queue.h"
#include "ui/base/modeller_state.h"

namespace gridifs::ui {

/// The timeline of `project` (the defaults when it has none yet).
AnimationSettings timelineOf(const Project& project);

/// Draws the timeline in the current window, as wide as it is; enqueues edits.
void drawTimelinePanel(ModellerState& state, EditQueue& edits);
/// The height the timeline took when last drawn (its row wraps in a narrow preview), or what one
/// row and the scrub bar need before it was drawn.
float timelinePanelHeight(const ModellerState& state);

/// Starts or stops playback (Alt+A, the Play button) once this frame's edits are applied.
void togglePlayback(ModellerState& state, EditQueue& edits);
/// The same at once (outside the UI build).
void togglePlaybackNow(ModellerState& state);
/// Moves the playhead by whole frames (Left/Right arrows), or to the start / end (Shift).
void stepFrames(ModellerState& state, EditQueue& edits, int frames);
void jumpToEnd(ModellerState& state, EditQueue& edits, bool end);
/// While playing, moves the playhead to the frame due now (call once a frame, before the UI is
/// built). Playback runs at the timeline's frame rate, dropping frames rather than slowing.
void advancePlayback(ModellerState& state);

}  // namespace gridifs::ui
