#pragma once
// The modeller's preview as core decides it: after an edit or a resize, whether the chaos game
// starts over, whether the IFS is compiled again, and whether only the picture is developed
// anew; and the preview's prepared render, the steps of prepareRender (job/prepared_render.h)
// with the preview's differences. Headless, so that the decision is unit-tested and the time from
// an edit to the first image is measured without a window (tests/bench/bench_preview_edit.cpp).
#include <cstdint>
#include <filesystem>
#include <memory>

#include "edit/document.h"
#include "job/prepared_render.h"

namespace gridifs {

/// What the preview last started from: the document's revisions, the preview's size and threads.
struct PreviewInputs {
  Revisions revisions{0, 0, 0, 0};
  int width = 0, height = 0, threads = 0;
  bool started = false;  // false: nothing published yet, or forced (the next decision restarts)
  bool haveIfs = false;  // the last start compiled an IFS (false after a failed compile)
};

/// What an edit asks of the preview.
struct PreviewDecision {
  /// The chaos game starts over: the functions, a render input (size, samples, seed, skip,
  /// palette, shaded lights) or the camera changed, or the size or threads did.
  bool restart = false;
  /// The IFS is compiled again: the functions changed (or there is none). Otherwise the restart
  /// reuses the last one, and a restart that changes only the shadowed lights keeps the camera's
  /// buffers (ChaosRenderer::restart).
  bool recompile = false;
  /// Only how the buffers become a picture changed (background, depth cue, display mode, tone
  /// mapping): the running render is developed again, without a restart.
  bool redisplay = false;
};

/// The decision for `now` (the document's revisions) at `width`×`height` with `threads`, against
/// what the preview last started from.
PreviewDecision decidePreview(const PreviewInputs& last, const Revisions& now, int width, int height, int threads);

/// The preview's size never falls below this many pixels a side.
constexpr int kMinPreviewSide = 16;

/// Condensation sets read from files are voxelized at 128³ for the preview: coarser than a
/// render's 256³, so that an edit restarts the preview quickly.
constexpr int kPreviewSetResolution = 128;

/// The preview's prepared render of `document` at `width`×`height` on `threads`: its tracks as
/// they are (the document is at its time), low priority threads, colour sums in every mode (the
/// switch to the flame display needs no restart), the flame histogram at the preview's own pixels,
/// the default palette while the project's cannot be read, and the shaded display's lights.
/// `reuse`: the IFS of the last start when decidePreview said no recompile. Validated like every
/// render: throws RenderJobError naming the JSON path of the cause.
PreparedRender preparePreview(const Document& document, int width, int height, int threads,
                              std::shared_ptr<const CompiledIfs> reuse = nullptr);

}  // namespace gridifs
