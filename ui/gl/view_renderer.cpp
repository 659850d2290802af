#include "ui/gl/view_renderer.h"

#include <algorithm>
#include <cstring>
#include <glm/gtc/type_ptr.hpp>

namespace gridifs::ui {

ViewRenderer::ViewRenderer()
    : lines_("lines.vert.glsl", "lines.frag.glsl"),
      nodes_("nodes.vert.glsl", "nodes.frag.glsl"),
      background_("fullscreen.vert.glsl", "view_background.frag.glsl"),
      blit_("fullscreen.vert.glsl", "preview_blit.frag.glsl") {
  glGenVertexArrays(1, &emptyVao_);  // core profile: a draw needs a bound VAO even without attributes
  // Software rasterizers pay for every full-view pass; keep the gradient for real GPUs.
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  gradient_ = !(renderer && (std::strstr(renderer, "llvmpipe") || std::strstr(renderer, "softpipe") ||
                             std::strstr(renderer, "SwiftShader")));
}

void ViewRenderer::drawScene(const RenderTarget& target, const glm::mat4& viewProjection, const ViewScene& scene,
                             float pointScale, const glm::vec3& top, const glm::vec3& bottom) {
  target.bind();
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_DEPTH_TEST);
  glClearColor(bottom.x, bottom.y, bottom.z, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (gradient_) {  // a full-view shader pass: skipped where fill rate is scarce (llvmpipe)
    glUseProgram(background_.id());
    glUniform4f(background_.uniform("uRect"), -1.f, -1.f, 1.f, 1.f);
    glUniform3f(background_.uniform("uTop"), top.x, top.y, top.z);
    glUniform3f(background_.uniform("uBottom"), bottom.x, bottom.y, bottom.z);
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }

  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glUseProgram(lines_.id());
  glUniformMatrix4fv(lines_.uniform("uViewProjection"), 1, GL_FALSE, glm::value_ptr(viewProjection));
  stream_.draw(GL_LINES, scene.lines);

  glEnable(GL_PROGRAM_POINT_SIZE);
  glUseProgram(nodes_.id());
  glUniformMatrix4fv(nodes_.uniform("uViewProjection"), 1, GL_FALSE, glm::value_ptr(viewProjection));
  glUniform1f(nodes_.uniform("uPointScale"), pointScale);
  stream_.draw(GL_POINTS, scene.points);

  glDisable(GL_DEPTH_TEST);
  glUseProgram(lines_.id());
  stream_.draw(GL_LINES, scene.overlayLines);
  glUseProgram(nodes_.id());
  stream_.draw(GL_POINTS, scene.overlayPoints);
  glUseProgram(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void ViewRenderer::drawImage(const RenderTarget& target, GLuint image, int imageWidth, int imageHeight,
                             const glm::vec3& background) {
  target.bind();
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glClearColor(background.x, background.y, background.z, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (image && imageWidth > 0 && imageHeight > 0) {
    // Fit the image inside the target, centered, aspect preserved.
    const double ta = double(target.width()) / target.height(), ia = double(imageWidth) / imageHeight;
    double sx = 1.0, sy = 1.0;
    if (ia > ta)
      sy = ta / ia;
    else
      sx = ia / ta;
    glUseProgram(blit_.id());
    glUniform4f(blit_.uniform("uRect"), float(-sx), float(-sy), float(sx), float(sy));
    glUniform1i(blit_.uniform("uImage"), 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, image);
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glUseProgram(0);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace gridifs::ui
