#pragma once
// Compiling a shader stage and linking a program, with the driver's log when it refuses: the one
// copy behind the GPU renderer's compute shader and the modeller's view shaders. Each caller
// words the failure itself (a GPU renderer that is unavailable, a view that cannot draw). Use on
// the thread that owns the GL context.
#include <epoxy/gl.h>

#include <initializer_list>
#include <string>

namespace gridifs::gl {

/// A compiled shader stage or a linked program: `id` is 0 when the driver refused it, and `log`
/// then holds the driver's reason (at most 2047 characters).
struct ShaderBuild {
  GLuint id = 0;
  std::string log;
};

/// Compiles `source` as a shader of `stage` (GL_COMPUTE_SHADER, GL_VERTEX_SHADER, ...); a stage
/// that does not compile is deleted.
ShaderBuild compileShader(GLenum stage, const char* source);

/// Links the compiled `shaders` into a program and deletes them; a program that does not link is
/// deleted too.
ShaderBuild linkProgram(std::initializer_list<GLuint> shaders);

}  // namespace gridifs::gl
