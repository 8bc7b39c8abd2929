// Checks on PNGs written by sph-gui (run by ctest after the program, see smoke.cmake):
//   gui_image_check screenshot FILE   - the whole-window screenshot shows the panels (text and widgets on
//                                       the left and below) and the particle view (coloured particles and
//                                       the exact curve, drawn in the colour map's contrast colour);
//   gui_image_check compare A B       - two renderings of the same frame match within a small tolerance;
//   gui_image_check ab FILE           - an A/B comparison with the inspector open: the view (top middle)
//                                       shows dots in both run colours, the inspector column (top right)
//                                       text and a table.
//   gui_image_check text_scale A B K   - the status line's text in B is K times as tall as in A (projector
//                                       mode), within 20%.
// Prints what it measured; exit code 0 if the checks pass.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#include <stb/stb_image.h>

#include "colormap.h"
#include "frame_scene.h"

namespace {

struct Image {
  int w = 0, h = 0;
  unsigned char* px = nullptr;
  explicit Image(const char* path) {
    int n = 0;
    px = stbi_load(path, &w, &h, &n, 3);
    if (!px) std::fprintf(stderr, "cannot read %s\n", path);
  }
  ~Image() { stbi_image_free(px); }
  const unsigned char* at(int x, int y) const { return px + 3 * (static_cast<std::size_t>(y) * w + x); }
};

/// Fraction of pixels in [x0,x1) x [y0,y1) (fractions of the size) for which pred(rgb) holds.
template <class Pred>
double fraction(const Image& im, double x0, double x1, double y0, double y1, Pred pred) {
  const int a = static_cast<int>(x0 * im.w), b = static_cast<int>(x1 * im.w);
  const int c = static_cast<int>(y0 * im.h), d = static_cast<int>(y1 * im.h);
  long hit = 0, all = 0;
  for (int y = c; y < d; ++y)
    for (int x = a; x < b; ++x, ++all) hit += pred(im.at(x, y)) ? 1 : 0;
  return all ? static_cast<double>(hit) / static_cast<double>(all) : 0.0;
}

bool check(const char* what, double value, double min) {
  const bool ok = value >= min;
  std::printf("%-58s %.4f (need >= %.4f) %s\n", what, value, min, ok ? "ok" : "FAIL");
  return ok;
}

int screenshot(const char* path) {
  const Image im(path);
  if (!im.px) return 1;
  std::printf("%s: %d x %d\n", path, im.w, im.h);
  // Far from the dark background: light text, widget frames, plot lines.
  auto lit = [](const unsigned char* p) { return p[0] + p[1] + p[2] > 3 * 70; };
  // Saturated colour: colour-mapped particles, the exact curve.
  auto colourful = [](const unsigned char* p) {
    const int mx = std::max({int{p[0]}, int{p[1]}, int{p[2]}}), mn = std::min({int{p[0]}, int{p[1]}, int{p[2]}});
    return mx - mn > 60;
  };
  const sph::render::Rgb c = sph::render::colormap_contrast(sph::render::Colormap::Viridis);
  const int cr = static_cast<int>(std::lround(255 * c.r)), cg = static_cast<int>(std::lround(255 * c.g)),
            cb = static_cast<int>(std::lround(255 * c.b));
  auto exact = [&](const unsigned char* p) {
    return std::abs(p[0] - cr) < 40 && std::abs(p[1] - cg) < 40 && std::abs(p[2] - cb) < 40;
  };
  bool ok = true;
  ok &= check("controls column (left): text and widgets", fraction(im, 0.01, 0.20, 0.03, 0.90, lit), 0.04);
  ok &= check("bottom panels (diagnostics, kernel): text and plots", fraction(im, 0.30, 0.99, 0.65, 0.93, lit), 0.03);
  ok &= check("particle view (top right): colour-mapped particles", fraction(im, 0.30, 0.99, 0.02, 0.58, colourful), 0.01);
  ok &= check("particle view: exact-curve colour", fraction(im, 0.30, 0.99, 0.02, 0.58, exact), 0.0005);
  return ok ? 0 : 1;
}

int compare(const char* a_path, const char* b_path) {
  const Image a(a_path), b(b_path);
  if (!a.px || !b.px) return 1;
  if (a.w != b.w || a.h != b.h) {
    std::printf("sizes differ: %dx%d vs %dx%d\n", a.w, a.h, b.w, b.h);
    return 1;
  }
  double sum = 0.0;
  long off = 0;
  const long n = static_cast<long>(a.w) * a.h;
  for (long i = 0; i < 3 * n; ++i) {
    const int d = std::abs(a.px[i] - b.px[i]);
    sum += d;
    off += d > 24 ? 1 : 0;
  }
  const double mean = sum / (3.0 * n), frac = static_cast<double>(off) / (3.0 * n);
  std::printf("mean |difference| %.4f per channel (need <= 1.0); channels off by > 24: %.5f (need <= 0.002)\n", mean,
              frac);
  return mean <= 1.0 && frac <= 0.002 ? 0 : 1;
}

int ab_screenshot(const char* path) {
  const Image im(path);
  if (!im.px) return 1;
  std::printf("%s: %d x %d\n", path, im.w, im.h);
  auto near_colour = [](sph::render::Rgba c) {
    const int r = static_cast<int>(std::lround(255 * c.r)), g = static_cast<int>(std::lround(255 * c.g)),
              b = static_cast<int>(std::lround(255 * c.b));
    return [=](const unsigned char* p) { return std::abs(p[0] - r) < 30 && std::abs(p[1] - g) < 30 && std::abs(p[2] - b) < 30; };
  };
  auto lit = [](const unsigned char* p) { return p[0] + p[1] + p[2] > 3 * 70; };
  bool ok = true;
  // the layout: controls to 26% of the width, the view to the inspector column, both above 63% of the height
  ok &= check("view: run A's dots (orange)", fraction(im, 0.27, 0.69, 0.02, 0.58, near_colour(sph::render::kRunColors[0])), 0.002);
  ok &= check("view: run B's dots (sky blue)", fraction(im, 0.27, 0.69, 0.02, 0.58, near_colour(sph::render::kRunColors[1])), 0.002);
  ok &= check("inspector column (top right): text and table", fraction(im, 0.71, 0.99, 0.02, 0.58, lit), 0.03);
  ok &= check("diagnostics: both runs' curves (orange)", fraction(im, 0.40, 0.67, 0.64, 0.95, near_colour(sph::render::kRunColors[0])), 0.001);
  return ok ? 0 : 1;
}

/// Height of the status line's text [px]: the bottom-most run of consecutive rows, in the left third of
/// the image, that hold a light text pixel (the status line is the window's last line of text).
int status_text_height(const Image& im) {
  int run = 0;
  for (int y = im.h - 1; y >= im.h - im.h / 10; --y) {
    bool lit = false;
    for (int x = 0; x < im.w / 3 && !lit; ++x) {
      const unsigned char* p = im.at(x, y);
      lit = p[0] + p[1] + p[2] > 3 * 150;
    }
    if (lit) ++run;
    else if (run > 0) break;
  }
  return run;
}

int text_scale(const char* a_path, const char* b_path, double k) {
  const Image a(a_path), b(b_path);
  if (!a.px || !b.px) return 1;
  const int ha = status_text_height(a), hb = status_text_height(b);
  const double ratio = ha > 0 ? static_cast<double>(hb) / ha : 0.0;
  const bool ok = ha >= 8 && ratio >= 0.8 * k && ratio <= 1.2 * k;
  std::printf("status line text: %d px in %s, %d px in %s: ratio %.3f (need %.2f +- 20%%) %s\n", ha, a_path, hb, b_path,
              ratio, k, ok ? "ok" : "FAIL");
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "screenshot" && argc == 3) return screenshot(argv[2]);
  if (mode == "compare" && argc == 4) return compare(argv[2], argv[3]);
  if (mode == "ab" && argc == 3) return ab_screenshot(argv[2]);
  if (mode == "text_scale" && argc == 5) return text_scale(argv[2], argv[3], std::atof(argv[4]));
  std::fprintf(stderr, "usage: gui_image_check screenshot FILE | compare A B | ab FILE | text_scale A B K\n");
  return 2;
}
