#pragma once
// Everything the modeller window knows besides the Document: which function and op are
// active, the artist's current node selection (UI state, not saved, as in Gröller & Wegenkittl 1994, §4.4:
// "as long as a subset is active, all following operations are applied only to it"),
// messages, and window toggles: what several panels and views share. What one panel alone keeps
// between frames (a typed index box, an expression being typed, a display cache) lives in that
// panel (its state struct in ui/panels/panels.h, or its class). Owned by the UI thread; panels read it
// and enqueue edits.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "edit/document.h"
#include "live/audio_envelope.h"
#include "live/sound_output.h"
#include "model/function_ref.h"
#include "model/grid.h"
#include "render/chaos_renderer.h"
#include "ui/base/set_outline_cache.h"
#include "ui/base/test_probe.h"

namespace gridifs::ui {

/// What the preview shows; later modes (flame display, deterministic mesh) join this list.
enum class PreviewMode { ZBuffer, Flame, Mesh, Shaded, Volume };  // Mesh: F^n(A); Volume: the measure attractor

class ModellerState {
 public:
  ModellerState();

  Document document;
  /// The function every panel and grid view edits: one of the IFS's, or the final function.
  FunctionRef activeFunction;
  int activeOp = -1;  // index in the active function's stack, -1 when none
  /// The artist's node selection for each function (empty: nothing selected).
  std::vector<Selection> selections;
  Selection finalSelection;  // the same for the final function
  /// The center of transformation placed in a view (Alt+click), used by ops whose center is a point.
  Vec3 pointCenter{0.0};
  /// Which center new operations get.
  Center::Kind newOpCenter = Center::Kind::Grid;

  /// Keeps the indices valid after any document change (undo can remove functions or ops, or
  /// the final function: the last function is then active).
  void clampIndices();
  /// After the document was replaced (new, open, import, recovery): the first function active,
  /// no operation, no selections, no final-function message.
  void forgetDocumentViewState();
  /// The active function (call clampIndices() first after a document change).
  const Function& function() const { return activeFunction.in(document.project()); }
  /// Makes `function` active, with no active op when it was not already.
  void activate(FunctionRef function);
  const Operation* op() const;
  Selection& selection();
  /// Per-node membership of the current selection (all zero when nothing is selected).
  const std::vector<unsigned char>& selectionMask();
  bool hasSelection();

  /// The active function's grid after its stack, before placement (what the grid views
  /// show and edit). Re-evaluated only when the function changes; on an evaluation error
  /// the last good grid is kept and gridError says why.
  const Grid& localGrid();
  std::string gridError;

  // Messages for the status bar (errors stay until the next message).
  void info(const std::string& text);
  void error(const std::string& text);
  std::string statusText;
  bool statusIsError = false;
  /// Why the Functions panel refused a change of the final function (a Bézier lattice with too
  /// many nodes); shown there until the artist changes its resolution or interpolation.
  std::string finalFunctionMessage;
  double statusTime = 0.0;
  /// Context help for the status line (Gröller & Wegenkittl 1994, §4.2), set each frame by the hovered widget or view.
  std::string contextHelp;

  // Windows and modes.
  bool showHelp = false;
  bool showMatrices = false;      // the Matrices window (transitions, free-form control points and matrices)
  bool showConstruction = false;  // the Construction tree window (leaves and matrix operations)
  int maximizedGridView = -1;     // -1: the four views; 0..3: one of them fills the window
  PreviewMode previewMode = PreviewMode::ZBuffer;
  /// Bumped when a project is opened or made (forgetDocumentViewState): what the preview mode was
  /// set to then is the project's, not the artist's choice.
  std::uint64_t documentOpens = 0;
  bool previewPaused = false;
  /// The timeline (ui/panels/timeline_panel.cpp): whether it plays, and from which time at which clock.
  struct Playback {
    bool playing = false;
    double startTime = 0.0, startClock = 0.0;
  } playback;
  float timelineHeight = 0.0f;       // what the timeline under the preview took in the last frame
  bool showRenderAnimation = false;  // File > Render animation...
  bool showCombine = false;          // File > Combine...
  bool showCamera = false;           // View > Camera: the Camera window (projection, orbit, stereo)
  bool showLive = false;             // View > Live: bindings, their values and the OSC input
  /// The project's sound as analysed for its bindings (live/audio_envelope.h), for the timeline's
  /// waveform; null when the project has none (ui/panels/live_panel.cpp keeps it current).
  std::shared_ptr<const AudioEnvelope> sound;
  /// Where the timeline's playback sounds (live/sound_output.h); null on a silent clock, whose
  /// reason soundOutputProblem gives.
  std::unique_ptr<SoundOutput> soundOutput;
  std::string soundOutputProblem;
  /// A key button's "Bind…": the parameter path the next moved control (MIDI, or an OSC address
  /// nothing listens to yet) is bound to; empty when not learning.
  std::string learnPath;
  bool showExplore = false;    // View > Explore (E): toggles the Explore window
  bool exploreRandom = false;  // File > New random world: Explore draws random worlds
  int renderThreads = 1;
  RenderStats previewStats;
  std::string previewDevice = "cpu";  // which renderer fills the preview ("cpu", "gpu (...)")
  /// The volume mode's progress for the status line ("" in the other modes).
  std::string volumeStatus;
  /// Key presses since the last frame, recorded by a GLFW callback: ImGui 1.86 has no input
  /// queue, so a press and release within one frame would otherwise be lost.
  struct KeyPress {
    int key = 0, mods = 0;
  };
  std::vector<KeyPress> keyPresses;

  UiProbe probe;
  /// The drawings of the condensation sets (views and set editor).
  SetOutlineCache setOutlines;
  /// The folder that the project's relative file paths (meshes, VDBs) start from.
  std::filesystem::path projectFolder() const {
    return document.path().parent_path().empty() ? std::filesystem::path(".") : document.path().parent_path();
  }
  double now = 0.0;  // seconds since start, set each frame
  float uiScale = 1.0f;

 private:
  Function cachedFunction_;
  bool haveCache_ = false;
  Grid localGrid_;
  Selection maskSelection_;
  Index3 maskResolution_{0, 0, 0};
  bool haveMask_ = false;
  std::vector<unsigned char> mask_;
};

}  // namespace gridifs::ui
