#include "ui/views/mesh_preview.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <glm/gtc/type_ptr.hpp>

#include "render/camera.h"
#include "volume/condensation_mesh.h"

namespace gridifs::ui {
namespace {

std::uint32_t packColor(const OpenMesh::Vec4f& c) {
  auto b = [](float v) { return std::uint32_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
  return b(c[0]) | (b(c[1]) << 8) | (b(c[2]) << 16) | (255u << 24);
}

}  // namespace

MeshPreview::MeshPreview() = default;

MeshPreview::~MeshPreview() {
  if (ebo_) glDeleteBuffers(1, &ebo_);
  if (vbo_) glDeleteBuffers(1, &vbo_);
  if (vao_) glDeleteVertexArrays(1, &vao_);
}

void MeshPreview::update(const Document& document) {
  const bool settingsChanged = depth != requestedDepth_ || sphere != requestedSphere_;
  // Only the functions change the mesh: camera and render edits leave the geometry revision alone.
  if (!settingsChanged && haveRequest_ && document.revisions().geometry == revision_) return;
  revision_ = document.revisions().geometry;
  haveRequest_ = true;
  requestedDepth_ = depth;
  requestedSphere_ = sphere;

  Request request;
  request.spec.shape = sphere ? BaseShape::Sphere : BaseShape::Cube;
  // The cube's flat faces bend under nonlinear functions: one flat subdivision keeps copies smooth
  // enough to read; the sphere is already fine at level 0.
  request.spec.subdivision = sphere ? 0 : 1;
  try {
    request.ifs = snapshotDeterministicIfs(document.project(), document.evaluation());
    // Condensation sets enter A_n = C ∪ F(A_{n−1}) as their surface meshes (read here, once per edit).
    const std::filesystem::path folder = document.path().parent_path();
    loadCondensationMeshes(request.ifs, document.project(), folder.empty() ? std::filesystem::path(".") : folder);
    // The safe maximum: the deepest n within the preview's face cap and the memory budget.
    DeterministicOptions options;
    const MeshCounts base = predictBaseCounts(loadCoarseBase(request.spec), request.spec);
    maxDepth_ = 0;
    for (int n = 1; n <= 64; ++n) {
      options.depth = n;
      const DeterministicPlan plan = planDeterministic(request.ifs, base, options);
      if (plan.overLimit || plan.overBudget || plan.total.faces > kMaxPreviewFaces) break;
      maxDepth_ = n;
    }
    depth = std::clamp(depth, 0, maxDepth_);  // the slider follows the safe maximum
    requestedDepth_ = depth;
    request.depth = depth;
    error_.clear();
  } catch (const std::exception& e) {
    error_ = e.what();
    maxDepth_ = 0;
    return;
  }
  job_.submit(std::move(request));  // stale work stops at its next progress poll
}

void MeshPreview::build(const Request& request, BuildJob::Context& context) {
  Result result;
  result.depth = request.depth;
  const auto start = std::chrono::steady_clock::now();
  try {
    DeterministicOptions options;
    options.depth = request.depth;
    options.threads = 1;  // the chaos-game preview is paused, but the UI keeps a core
    DeterministicMesh mesh;
    runDeterministic(
        request.ifs, request.spec, options, mesh,
        [&](double f) {
          context.progress(f * 0.9);
          return !context.stale();
        },
        context.stopFlag());
    const IfsMesh& m = mesh.mesh;
    result.vertices.resize(m.n_vertices());
    for (auto vh : m.vertices()) {
      const auto& q = m.point(vh);
      result.vertices[std::size_t(vh.idx())] = {q[0], q[1], q[2], packColor(m.color(vh))};
    }
    result.indices.reserve(m.n_faces() * 6);
    for (auto fh : m.faces()) {
      if (context.stale()) throw DeterministicCancelled();
      // Fan triangulation of each (convex) face.
      std::uint32_t first = 0, prev = 0;
      int k = 0;
      for (auto fv : m.fv_range(fh)) {
        const auto idx = std::uint32_t(fv.idx());
        if (k == 0)
          first = idx;
        else if (k >= 2)
          result.indices.insert(result.indices.end(), {first, prev, idx});
        prev = idx;
        ++k;
      }
    }
    result.faces = m.n_faces();
    context.progress(1.0);
  } catch (const DeterministicCancelled&) {
    return;  // a newer request follows
  } catch (const std::exception& e) {
    result.error = e.what();
  }
  result.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (context.stale()) return;  // a newer request follows
  context.publish(std::move(result));
}

bool MeshPreview::upload() {
  std::optional<BuildJob::Result> published = job_.poll();
  if (!published) return false;
  Result* result = &published->value;
  if (!result->error.empty()) {
    error_ = result->error;
    return true;
  }
  if (!vao_) {
    glGenVertexArrays(1, &vao_);
    glGenBuffers(1, &vbo_);
    glGenBuffers(1, &ebo_);
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(MeshPreviewVertex),
                          reinterpret_cast<void*>(offsetof(MeshPreviewVertex, x)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(MeshPreviewVertex),
                          reinterpret_cast<void*>(offsetof(MeshPreviewVertex, rgba)));
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_);
    glBindVertexArray(0);
  }
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(result->vertices.size() * sizeof(MeshPreviewVertex)),
               result->vertices.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(result->indices.size() * sizeof(std::uint32_t)),
               result->indices.data(), GL_STATIC_DRAW);
  glBindVertexArray(0);
  indexCount_ = result->indices.size();
  shownFaces_ = result->faces;
  shownDepth_ = result->depth;
  buildMs_ = result->ms;
  return true;
}

void MeshPreview::draw(const RenderTarget& target, const Camera& camera, const glm::vec3& background) {
  target.bind();
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_BLEND);
  glClearColor(background.x, background.y, background.z, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (indexCount_ > 0) {
    if (!program_) program_.emplace("mesh.vert.glsl", "mesh.frag.glsl");
    try {
      const OrbitCamera cam(camera, target.width(), target.height());
      const glm::mat4 view = cam.viewF(), viewProjection = cam.projectionF() * view;
      glEnable(GL_DEPTH_TEST);
      glDepthFunc(GL_LESS);
      glUseProgram(program_->id());
      glUniformMatrix4fv(program_->uniform("uViewProjection"), 1, GL_FALSE, glm::value_ptr(viewProjection));
      glUniformMatrix4fv(program_->uniform("uView"), 1, GL_FALSE, glm::value_ptr(view));
      glBindVertexArray(vao_);
      glDrawElements(GL_TRIANGLES, GLsizei(indexCount_), GL_UNSIGNED_INT, nullptr);
      glBindVertexArray(0);
      glUseProgram(0);
      glDisable(GL_DEPTH_TEST);
    } catch (const std::exception&) {
      // A degenerate camera (validated elsewhere) draws nothing.
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace gridifs::ui
