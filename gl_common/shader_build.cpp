#include "gl_common/shader_build.h"

namespace gridifs::gl {
namespace {

constexpr GLsizei kLogCapacity = 2048;

}  // namespace

ShaderBuild compileShader(GLenum stage, const char* source) {
  ShaderBuild build;
  build.id = glCreateShader(stage);
  glShaderSource(build.id, 1, &source, nullptr);
  glCompileShader(build.id);
  GLint ok = 0;
  glGetShaderiv(build.id, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[kLogCapacity] = {};
    glGetShaderInfoLog(build.id, kLogCapacity, nullptr, log);
    glDeleteShader(build.id);
    build = {0, log};
  }
  return build;
}

ShaderBuild linkProgram(std::initializer_list<GLuint> shaders) {
  ShaderBuild build;
  build.id = glCreateProgram();
  for (GLuint shader : shaders) glAttachShader(build.id, shader);
  glLinkProgram(build.id);
  for (GLuint shader : shaders) glDeleteShader(shader);
  GLint ok = 0;
  glGetProgramiv(build.id, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[kLogCapacity] = {};
    glGetProgramInfoLog(build.id, kLogCapacity, nullptr, log);
    glDeleteProgram(build.id);
    build = {0, log};
  }
  return build;
}

}  // namespace gridifs::gl
