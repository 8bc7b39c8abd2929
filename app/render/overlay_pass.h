// GL side of the overlay: uploads ShapeBatch triangles (lines.vert/.frag) and TextBatch glyph quads
// (text.vert/.frag, font atlas texture) and draws them in frame pixels.
#pragma once
#include <string>

#include "font_atlas.h"
#include "gl_api.h"
#include "gl_program.h"
#include "shape_batch.h"
#include "text_batch.h"

namespace sph::render {

class OverlayPass {
 public:
  bool init(const GlApi& gl, const FontAtlas& font, std::string* err);
  void destroy(const GlApi& gl);
  /// Both draw with the full frame as viewport (width x height pixels).
  void draw_shapes(const GlApi& gl, const ShapeBatch& batch, int width, int height);
  void draw_text(const GlApi& gl, const TextBatch& batch, int width, int height);

 private:
  GlProgram lines_, text_;
  GLuint shape_vao_ = 0, shape_vbo_ = 0, text_vao_ = 0, text_vbo_ = 0, font_tex_ = 0;
};

}  // namespace sph::render
