#pragma once
// The deterministic preview mode (Gröller & Wegenkittl 1994, §3.2 and figure 2): F^n(A) of a cube or a
// sphere drawn as a lit mesh in the preview window, so the artist sees an initial shape converge
// to the attractor as n grows. The mesh is built on a worker thread (cancelled and restarted when
// the functions, the depth or the base change); the UI thread only plans, uploads and draws.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "base/background_job.h"
#include "edit/document.h"
#include "mesh/base_mesh.h"
#include "mesh/deterministic_ifs.h"
#include "ui/gl/gl_resources.h"

namespace gridifs::ui {

/// Above this many faces the preview refuses a depth (the export has its own, larger limits).
inline constexpr std::uint64_t kMaxPreviewFaces = 1'500'000;

/// Vertex of the preview mesh: position and packed RGBA8 color (normals come from the
/// fragment's screen-space derivatives: each face is lit flat, as the copies are not welded).
struct MeshPreviewVertex {
  float x, y, z;
  std::uint32_t rgba;
};

class MeshPreview {
 public:
  MeshPreview();
  ~MeshPreview();  // cancels and joins the worker
  MeshPreview(const MeshPreview&) = delete;
  MeshPreview& operator=(const MeshPreview&) = delete;

  // What to build (the toolbar edits these; UI state, not saved in the project).
  int depth = 3;
  bool sphere = false;

  /// UI thread, every frame in mesh mode: when the functions, the depth or the base changed,
  /// plans the new mesh and restarts the worker on it. Never waits.
  void update(const Document& document);
  /// UI thread with the GL context: uploads a finished mesh; returns true when there is a new one.
  bool upload();
  /// Draws the current mesh into `target` with the project camera; clears to `background`.
  void draw(const RenderTarget& target, const Camera& camera, const glm::vec3& background);

  bool building() const { return job_.busy(); }
  double progress() const { return job_.progress().fraction; }
  /// Largest depth whose mesh stays under kMaxPreviewFaces and the memory budget (≥ 0).
  int maxDepth() const { return maxDepth_; }
  /// Faces of the mesh on screen (0 when none).
  std::uint64_t faces() const { return shownFaces_; }
  int shownDepth() const { return shownDepth_; }
  double buildMs() const { return buildMs_; }
  /// Why the current request cannot be shown ("" when it can).
  const std::string& error() const { return error_; }
  bool hasMesh() const { return indexCount_ > 0; }

 private:
  struct Request {
    DeterministicIfs ifs;
    BaseMeshSpec spec;
    int depth = 0;
  };
  struct Result {
    std::vector<MeshPreviewVertex> vertices;
    std::vector<std::uint32_t> indices;
    std::uint64_t faces = 0;
    int depth = 0;
    double ms = 0.0;
    std::string error;
  };
  using BuildJob = BackgroundJob<Request, Result>;
  /// Worker thread: builds the mesh of `request`; publishes nothing when superseded.
  static void build(const Request& request, BuildJob::Context& context);

  // UI-thread state.
  std::uint64_t revision_ = 0;  // Document::revisions().geometry of the last request
  bool haveRequest_ = false;
  int requestedDepth_ = -1;
  bool requestedSphere_ = false;
  int maxDepth_ = 0;
  std::string error_;
  std::uint64_t shownFaces_ = 0;
  int shownDepth_ = -1;
  double buildMs_ = 0.0;

  // GL.
  std::optional<ShaderProgram> program_;
  GLuint vao_ = 0, vbo_ = 0, ebo_ = 0;
  std::size_t indexCount_ = 0;

  // Last: destroyed first, it stops and joins the worker before the rest goes.
  BuildJob job_{&MeshPreview::build};
};

}  // namespace gridifs::ui
