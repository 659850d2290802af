#pragma once
// Draws the views' scenes (grid lines, nodes, handles) and the preview image into render
// targets with the shaders of shaders/. One instance per GL context.
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "ui/gl/gl_resources.h"

namespace gridifs::ui {

/// What one view shows this frame: world-space line segments (pairs of vertices) and points.
struct ViewScene {
  std::vector<Vertex> lines;
  std::vector<Vertex> points;
  /// Drawn after `lines` without depth test (selection boxes, handles' guides).
  std::vector<Vertex> overlayLines;
  std::vector<Vertex> overlayPoints;
  void clear() {
    lines.clear();
    points.clear();
    overlayLines.clear();
    overlayPoints.clear();
  }
};

class ViewRenderer {
 public:
  ViewRenderer();
  /// Clears `target` to a vertical gradient and draws `scene` with `viewProjection`.
  void drawScene(const RenderTarget& target, const glm::mat4& viewProjection, const ViewScene& scene, float pointScale,
                 const glm::vec3& top, const glm::vec3& bottom);
  /// Clears `target` to `background` and draws `image` (imageWidth × imageHeight) centered,
  /// keeping its aspect ratio.
  void drawImage(const RenderTarget& target, GLuint image, int imageWidth, int imageHeight,
                 const glm::vec3& background);

 private:
  ShaderProgram lines_, nodes_, background_, blit_;
  VertexStream stream_;
  GLuint emptyVao_ = 0;
  bool gradient_ = true;
};

}  // namespace gridifs::ui
