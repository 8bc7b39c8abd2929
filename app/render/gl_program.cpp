#include "gl_program.h"

#include <vector>

#include "shader_sources.h"

namespace sph::render {

namespace {

// Inserts the defines after the first line (#version must stay first).
std::string with_defines(std::string_view text, std::string_view defines) {
  const std::size_t eol = text.find('\n');
  if (eol == std::string_view::npos) return std::string(text);
  std::string s(text.substr(0, eol + 1));
  s += defines;
  s += text.substr(eol + 1);
  return s;
}

GLuint compile(const GlApi& gl, GLenum type, std::string_view file, std::string_view defines,
               std::string* err) {
  const std::string_view text = shader_source(file);
  if (text.empty()) {
    if (err) *err = "shader not embedded: " + std::string(file);
    return 0;
  }
  const std::string src = with_defines(text, defines);
  const char* ptr = src.c_str();
  const GLuint shader = gl.CreateShader(type);
  gl.ShaderSource(shader, 1, &ptr, nullptr);
  gl.CompileShader(shader);
  GLint ok = GL_FALSE;
  gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint len = 0;
    gl.GetShaderiv(shader, GL_INFO_LOG_LENGTH, &len);
    std::vector<char> log(static_cast<std::size_t>(len > 1 ? len : 1), '\0');
    gl.GetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
    if (err) *err = "compiling " + std::string(file) + ": " + log.data();
    gl.DeleteShader(shader);
    return 0;
  }
  return shader;
}

}  // namespace

bool GlProgram::build(const GlApi& gl, std::string_view vert, std::string_view frag,
                      std::string_view defines, std::string* err) {
  destroy(gl);
  const GLuint vs = compile(gl, GL_VERTEX_SHADER, vert, defines, err);
  if (vs == 0) return false;
  const GLuint fs = compile(gl, GL_FRAGMENT_SHADER, frag, defines, err);
  if (fs == 0) {
    gl.DeleteShader(vs);
    return false;
  }
  id_ = gl.CreateProgram();
  gl.AttachShader(id_, vs);
  gl.AttachShader(id_, fs);
  gl.LinkProgram(id_);
  gl.DeleteShader(vs);  // flagged; freed with the program
  gl.DeleteShader(fs);
  GLint ok = GL_FALSE;
  gl.GetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint len = 0;
    gl.GetProgramiv(id_, GL_INFO_LOG_LENGTH, &len);
    std::vector<char> log(static_cast<std::size_t>(len > 1 ? len : 1), '\0');
    gl.GetProgramInfoLog(id_, static_cast<GLsizei>(log.size()), nullptr, log.data());
    if (err) *err = "linking " + std::string(vert) + " + " + std::string(frag) + ": " + log.data();
    destroy(gl);
    return false;
  }
  return true;
}

void GlProgram::destroy(const GlApi& gl) {
  if (id_ != 0) gl.DeleteProgram(id_);
  id_ = 0;
}

}  // namespace sph::render
