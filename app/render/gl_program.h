// A linked GLSL program built from two embedded shader files, with optional #defines.
#pragma once
#include <string>
#include <string_view>

#include "gl_api.h"

namespace sph::render {

class GlProgram {
 public:
  /// Compiles shaders/<vert> and shaders/<frag>; `defines` ("#define X 1\n" lines) go right after
  /// each file's #version line. On failure *err holds the file name and the driver's log.
  bool build(const GlApi& gl, std::string_view vert, std::string_view frag, std::string_view defines,
             std::string* err);
  void destroy(const GlApi& gl);

  GLuint id() const { return id_; }
  GLint uniform(const GlApi& gl, const char* name) const { return gl.GetUniformLocation(id_, name); }

 private:
  GLuint id_ = 0;
};

}  // namespace sph::render
