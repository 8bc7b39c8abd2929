#include "renderer.h"

#include <algorithm>
#include <cmath>

#include "chrome.h"
#include "compare_view.h"
#include "font_atlas.h"
#include "frame_build.h"
#include "highlight.h"
#include "orbit_view.h"
#include "overlay_pass.h"
#include "palette.h"
#include "particle_pass.h"
#include "plane_view.h"
#include "profile_axis.h"
#include "profile_view.h"
#include "sph/snapshot.h"
#include "sph/trail_log.h"

namespace sph::render {

struct Renderer::Impl {
  GlApi gl;
  FontAtlas font;
  ParticlePass particles;
  OverlayPass overlay;
  FrameBuild frame{font};  // reused between frames (keeps its buffers' capacity)
  sph::SnapshotField log_field;  // the shown field as log10, when the view asks for it
  sph::Snapshot untrailed;       // a snapshot without its orbit trails (view.show_trails off)
  bool ready = false;
};

namespace {

/// The field as log10 of its values (non-positive values become NaN and are not drawn).
void log10_field(const sph::SnapshotField& in, sph::SnapshotField* out) {
  out->name = in.name;
  out->label = "log10 " + (in.label.empty() ? in.name : in.label);
  out->values.resize(in.values.size());
  for (std::size_t i = 0; i < in.values.size(); ++i)
    out->values[i] = in.values[i] > 0.f ? std::log10(in.values[i]) : std::nanf("");
  out->min = out->max = std::nanf("");  // resolve_range recomputes them over the finite values
}

/// The field shown and its range; `compared`: an A/B frame, whose shared range is linear unless the view
/// asks for log10 (no automatic log scale).
ShownField choose_field(const sph::Snapshot& snap, const ViewSettings& view, sph::SnapshotField* log_storage,
                        bool compared) {
  ShownField s;
  s.cmap = parse_colormap(view.cmap).value_or(Colormap::Viridis);
  if (!parse_colormap(view.cmap)) s.warning = "unknown colour map '" + view.cmap + "'";
  s.field = snap.find(view.color_by);
  if (s.field == nullptr && !snap.fields.empty()) {
    s.field = &snap.fields.front();
    s.warning = "no field '" + view.color_by + "'";
  }
  if (s.field == nullptr) return s;
  const bool auto_log = view.auto_log && !compared && view.auto_range && !draws_profile(snap.dim, view.profile_axis) &&
                        spans_decades(s.field->values, snap.kind);
  if (view.log_scale || auto_log) {
    log10_field(*s.field, log_storage);
    s.field = log_storage;
  }
  s.label = s.field->label.empty() ? s.field->name : s.field->label;
  s.range = resolve_range(*s.field, view, snap.kind);  // the fluid's range: walls are grey
  return s;
}

// glViewport/glScissor take the lower-left corner; layout rects are top-left based.
void set_viewport(const GlApi& gl, const PixelRect& r, int frame_height) {
  gl.Viewport(static_cast<GLint>(r.x), frame_height - static_cast<GLint>(r.bottom()), static_cast<GLsizei>(r.w),
              static_cast<GLsizei>(r.h));
}

}  // namespace

Renderer::Renderer() : impl_(std::make_unique<Impl>()) {}

Renderer::~Renderer() { shutdown(); }

bool Renderer::initialized() const { return impl_->ready; }
const FrameLayout& Renderer::last_layout() const { return impl_->frame.layout; }
const std::vector<TextSpan>& Renderer::last_texts() const { return impl_->frame.text.spans(); }
const GlApi& Renderer::gl() const { return impl_->gl; }
void Renderer::set_particle_path(ParticlePath path) { impl_->particles.set_path(path); }
bool Renderer::particles_on_cpu() const { return impl_->particles.uses_cpu(); }

bool Renderer::init(GetProcFn get_proc, std::string* err) {
  shutdown();
  Impl& d = *impl_;
  if (!d.gl.load(get_proc, err)) return false;
  if (!d.font.build(err)) return false;
  if (!d.particles.init(d.gl, err) || !d.overlay.init(d.gl, d.font, err)) {
    d.particles.destroy(d.gl);
    d.overlay.destroy(d.gl);
    return false;
  }
  d.ready = true;
  return true;
}

void Renderer::shutdown() {
  Impl& d = *impl_;
  if (!d.ready) return;
  d.particles.destroy(d.gl);
  d.overlay.destroy(d.gl);
  d.ready = false;
}

void Renderer::render(const sph::Snapshot& snap, const ViewSettings& view, int width, int height) {
  FrameScene scene;
  scene.a = &snap;
  render(scene, view, width, height);
}

void Renderer::render(const FrameScene& in, const ViewSettings& view, int width, int height) {
  Impl& d = *impl_;
  if (!d.ready || width <= 0 || height <= 0 || in.a == nullptr) return;
  FrameScene scene = in;
  const auto trail = [](const sph::Outline& o) { return o.label == sph::TrailLog::kLabel; };
  if (!view.show_trails && std::any_of(scene.a->outlines.begin(), scene.a->outlines.end(), trail)) {
    d.untrailed = *scene.a;  // the run's trails (sph::TrailLog) hidden
    std::erase_if(d.untrailed.outlines, trail);
    scene.a = &d.untrailed;
  }
  ShownField shown = choose_field(*scene.a, view, &d.log_field, scene.b != nullptr);
  if (scene.b && shown.field) shown.range = compare_range(*scene.a, *scene.b, view, *shown.field);
  compose(d.frame, scene, view, shown, width, height);
  draw(d, shown, width, height);
}

std::optional<Picked> Renderer::pick(float px, float py, float max_px) const {
  return pick_particle(impl_->frame, px, py, max_px);
}

std::optional<std::array<float, 2>> Renderer::pixel_of(int run, std::uint32_t index) const {
  return locate_particle(impl_->frame, run, index);
}

void Renderer::compose(FrameBuild& f, const FrameScene& scene, const ViewSettings& view, const ShownField& shown,
                       int width, int height) {
  const sph::Snapshot& snap = *scene.a;
  f.clear();
  f.pal = palette::chrome(view.high_contrast);
  const int axis = snap.dim == 1 ? 0 : view.profile_axis;
  const bool profile = draws_profile(snap.dim, axis);
  std::vector<std::string> fields = panel_fields(snap, view.panels);
  if (fields.empty()) fields.push_back(shown.field ? shown.field->name : view.color_by);
  // a comparison's or a sweep's profiles show the runs in their colours, not the colour map: no colour bar
  const bool several = scene.b || !scene.sweep.empty();
  const ShownField bar = profile && several ? ShownField{} : shown;
  layout_chrome(f, bar, width, height, view.text_scale);
  if (profile && !several && fields.size() <= 1)
    compose_profile(f, snap, view, shown, axis);
  else if (profile)
    compose_profile_panels(f, scene, view, shown, axis, fields);
  else if (scene.b)
    compose_compare(f, scene, view, shown);
  else if (snap.dim == 3)
    compose_orbit(f, snap, view, shown);
  else
    compose_plane(f, snap, view, shown);
  if (!profile && !scene.sweep.empty()) {  // a sweep's runs have no place in a particle view: say where they are
    const char* note = "sweep: its runs are drawn in the profile views";
    const PixelRect& p = f.layout.plot;
    const float room = p.w - f.text.line_height(1);
    const int ns = f.text.fitting_scale(note, room, f.layout.text_scale);
    const float lh = f.text.line_height(ns);
    if (f.text.measure(note, ns) <= room && p.h > 4.f * lh)  // else the Sweep panel alone says so
      f.text.add(note, p.x + 0.5f * f.text.line_height(1), p.bottom() - 1.5f * lh, ns, f.pal.dim_text);
  }
  add_colorbar(f, bar);
  add_title(f, snap, shown);
  add_highlight(f, scene.highlight, profile);
}

void Renderer::draw(Impl& d, const ShownField& shown, int width, int height) {
  const GlApi& gl = d.gl;
  const FrameBuild& f = d.frame;
  // Every state this frame depends on is set here (the GUI's own drawing changes it).
  auto scissor = [&](const PixelRect& r) {
    gl.Enable(GL_SCISSOR_TEST);
    gl.Scissor(static_cast<GLint>(r.x), height - static_cast<GLint>(r.bottom()), static_cast<GLsizei>(r.w),
               static_cast<GLsizei>(r.h));
  };
  gl.Disable(GL_SCISSOR_TEST);
  gl.Disable(GL_DEPTH_TEST);
  gl.Disable(GL_CULL_FACE);
  gl.Enable(GL_BLEND);
  gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  gl.Viewport(0, 0, width, height);
  const Rgba bg = f.pal.background, fill = f.pal.plot_fill;
  gl.ClearColor(bg.r, bg.g, bg.b, 1.f);
  gl.ClearDepth(1.0);
  gl.DepthMask(GL_TRUE);
  gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  auto clear_fill = [&](const PixelRect& r) {  // plot background: a scissored clear is the cheapest fill
    if (!(r.w > 0.f && r.h > 0.f)) return;
    scissor(r);
    gl.ClearColor(fill.r, fill.g, fill.b, 1.f);
    gl.Clear(GL_COLOR_BUFFER_BIT);
    gl.Disable(GL_SCISSOR_TEST);
  };
  clear_fill(f.fill);
  for (const ParticleBatch& b : f.batches) clear_fill(b.fill);

  d.overlay.draw_shapes(gl, f.under, width, height);

  const PixelRect& plot = f.layout.plot;
  if (!f.instances.empty()) {
    set_viewport(gl, plot, height);
    d.particles.draw(gl, ParticleDraw::primary(f), shown.cmap, shown.range,
                     {shown.field ? palette::kInvalid : palette::kNoField, palette::kWall});
    gl.Viewport(0, 0, width, height);
  }
  scissor(plot);
  d.overlay.draw_shapes(gl, f.clipped, width, height);
  gl.Disable(GL_SCISSOR_TEST);
  for (const ParticleBatch& b : f.batches) {  // the other plots: panels, run B, the difference map, an inset
    if (b.opaque) clear_fill(b.fill);
    set_viewport(gl, b.rect, height);
    d.particles.draw(gl, ParticleDraw::of(b), b.cmap, b.range, b.colors);
    gl.Viewport(0, 0, width, height);
    scissor(b.rect);
    d.overlay.draw_shapes(gl, b.clipped, width, height);
    gl.Disable(GL_SCISSOR_TEST);
  }

  d.overlay.draw_shapes(gl, f.over, width, height);
  d.overlay.draw_text(gl, f.text, width, height);
}

}  // namespace sph::render
