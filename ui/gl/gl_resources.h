#pragma once
// Small RAII wrappers over OpenGL 3.3 core objects (through libepoxy): shader programs built
// from the embedded shaders/ sources, an offscreen render target per view, and a streamed
// vertex buffer. Use on the thread that owns the GL context.
#include <epoxy/gl.h>

#include <string>
#include <vector>

namespace gridifs::ui {

/// The source of an embedded shader by file name ("lines.vert.glsl"); throws std::runtime_error.
const char* embeddedShader(const std::string& name);

class ShaderProgram {
 public:
  ShaderProgram() = default;
  /// Compiles and links; throws std::runtime_error with the driver's log on failure.
  ShaderProgram(const std::string& vertexName, const std::string& fragmentName);
  ~ShaderProgram();
  ShaderProgram(ShaderProgram&& other) noexcept;
  ShaderProgram& operator=(ShaderProgram&& other) noexcept;
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  GLuint id() const { return program_; }
  GLint uniform(const char* name) const { return glGetUniformLocation(program_, name); }

 private:
  GLuint program_ = 0;
};

/// A color texture plus depth renderbuffer that one view draws into; shown with ImGui::Image.
class RenderTarget {
 public:
  RenderTarget() = default;
  ~RenderTarget();
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;

  /// (Re)allocates when the size changes. Sizes below 1 are raised to 1.
  void resize(int width, int height);
  /// Binds the framebuffer and sets the viewport to the whole target.
  void bind() const;
  GLuint texture() const { return color_; }
  /// Copies the whole target into the window's framebuffer with its lower-left corner at (x, y).
  void blitTo(int x, int y) const;
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  GLuint framebuffer_ = 0, color_ = 0, depth_ = 0;
  int width_ = 0, height_ = 0;
};

/// Interleaved vertex: position, RGBA color, point size (lines ignore the size).
struct Vertex {
  float x, y, z;
  float r, g, b, a;
  float size;
};

/// A vertex array whose buffer is refilled every time it is drawn (the scenes are small).
class VertexStream {
 public:
  VertexStream();
  ~VertexStream();
  VertexStream(const VertexStream&) = delete;
  VertexStream& operator=(const VertexStream&) = delete;
  void draw(GLenum mode, const std::vector<Vertex>& vertices);

 private:
  GLuint vao_ = 0, vbo_ = 0;
  std::size_t capacity_ = 0;
};

/// A 2D RGBA8 texture updated from CPU memory (the preview image).
class StreamTexture {
 public:
  StreamTexture() = default;
  ~StreamTexture();
  StreamTexture(const StreamTexture&) = delete;
  StreamTexture& operator=(const StreamTexture&) = delete;
  void upload(int width, int height, const unsigned char* rgba);
  GLuint id() const { return texture_; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  GLuint texture_ = 0;
  int width_ = 0, height_ = 0;
};

}  // namespace gridifs::ui
