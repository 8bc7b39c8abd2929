#include "overlay_pass.h"

#include <cstddef>
#include <cstdint>

namespace sph::render {

namespace {

const void* offset(std::size_t bytes) { return reinterpret_cast<const void*>(static_cast<std::uintptr_t>(bytes)); }

// Float attributes (location, component count, byte offset) of one interleaved vertex buffer.
struct Attr {
  GLuint loc;
  GLint size;
  std::size_t offset;
};

void make_vao(const GlApi& gl, GLuint* vao, GLuint* vbo, GLsizei stride, std::initializer_list<Attr> attrs) {
  gl.GenVertexArrays(1, vao);
  gl.GenBuffers(1, vbo);
  gl.BindVertexArray(*vao);
  gl.BindBuffer(GL_ARRAY_BUFFER, *vbo);
  for (const Attr& a : attrs) {
    gl.EnableVertexAttribArray(a.loc);
    gl.VertexAttribPointer(a.loc, a.size, GL_FLOAT, GL_FALSE, stride, offset(a.offset));
  }
  gl.BindVertexArray(0);
}

}  // namespace

bool OverlayPass::init(const GlApi& gl, const FontAtlas& font, std::string* err) {
  if (!lines_.build(gl, "lines.vert", "lines.frag", "", err)) return false;
  if (!text_.build(gl, "text.vert", "text.frag", "", err)) return false;
  make_vao(gl, &shape_vao_, &shape_vbo_, sizeof(ShapeVertex),
           {{0, 2, offsetof(ShapeVertex, x)}, {1, 4, offsetof(ShapeVertex, r)}, {2, 2, offsetof(ShapeVertex, dist)}});
  make_vao(gl, &text_vao_, &text_vbo_, sizeof(TextVertex),
           {{0, 2, offsetof(TextVertex, x)}, {1, 2, offsetof(TextVertex, u)}, {2, 4, offsetof(TextVertex, r)}});

  gl.GenTextures(1, &font_tex_);
  gl.BindTexture(GL_TEXTURE_2D, font_tex_);
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl.TexImage2D(GL_TEXTURE_2D, 0, GL_R8, font.width(), font.height(), 0, GL_RED, GL_UNSIGNED_BYTE,
                font.coverage().data());
  // Nearest: glyphs are drawn at integer scales on whole pixels, so texels map to pixel blocks.
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  gl.BindTexture(GL_TEXTURE_2D, 0);
  return true;
}

void OverlayPass::destroy(const GlApi& gl) {
  lines_.destroy(gl);
  text_.destroy(gl);
  const GLuint buffers[2] = {shape_vbo_, text_vbo_};
  const GLuint arrays[2] = {shape_vao_, text_vao_};
  if (shape_vbo_) gl.DeleteBuffers(2, buffers);
  if (shape_vao_) gl.DeleteVertexArrays(2, arrays);
  if (font_tex_) gl.DeleteTextures(1, &font_tex_);
  shape_vao_ = shape_vbo_ = text_vao_ = text_vbo_ = font_tex_ = 0;
}

void OverlayPass::draw_shapes(const GlApi& gl, const ShapeBatch& batch, int width, int height) {
  const auto& v = batch.vertices();
  if (v.empty()) return;
  gl.UseProgram(lines_.id());
  gl.Uniform2f(lines_.uniform(gl, "u_viewport"), static_cast<float>(width), static_cast<float>(height));
  gl.BindVertexArray(shape_vao_);
  gl.BindBuffer(GL_ARRAY_BUFFER, shape_vbo_);
  gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(ShapeVertex)), v.data(), GL_STREAM_DRAW);
  gl.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(v.size()));
  gl.BindVertexArray(0);
  gl.UseProgram(0);
}

void OverlayPass::draw_text(const GlApi& gl, const TextBatch& batch, int width, int height) {
  const auto& v = batch.vertices();
  if (v.empty()) return;
  gl.UseProgram(text_.id());
  gl.Uniform2f(text_.uniform(gl, "u_viewport"), static_cast<float>(width), static_cast<float>(height));
  gl.Uniform1i(text_.uniform(gl, "u_font"), 0);
  gl.ActiveTexture(GL_TEXTURE0);
  gl.BindTexture(GL_TEXTURE_2D, font_tex_);
  gl.BindVertexArray(text_vao_);
  gl.BindBuffer(GL_ARRAY_BUFFER, text_vbo_);
  gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(TextVertex)), v.data(), GL_STREAM_DRAW);
  gl.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(v.size()));
  gl.BindVertexArray(0);
  gl.BindTexture(GL_TEXTURE_2D, 0);
  gl.UseProgram(0);
}

}  // namespace sph::render
