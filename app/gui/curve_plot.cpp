#include "curve_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "ui_look.h"

namespace sph::gui {

namespace {

/// The plot box on screen: data x in [x0, x1] and y in [lo, hi] mapped onto the corners a (top left)
/// and b (bottom right) [pixels].
struct Box {
  ImVec2 a, b;
  float x0, x1, lo, hi;
  float X(float x) const { return a.x + (x - x0) / (x1 - x0) * (b.x - a.x); }
  float Y(float y) const { return b.y - (y - lo) / (hi - lo) * (b.y - a.y); }
};

/// The value range over all curves (with 0 unless left out), a constant centred, padded by 6%;
/// returns the pad.
float value_range(const std::vector<Curve>& curves, bool include_zero, float& lo, float& hi) {
  lo = include_zero ? 0.f : INFINITY;
  hi = include_zero ? 0.f : -INFINITY;
  for (const Curve& c : curves)
    for (float v : c.y)
      if (std::isfinite(v)) { lo = std::min(lo, v); hi = std::max(hi, v); }
  if (lo > hi) lo = hi = 0.f;  // no finite value
  if (hi - lo < 1e-6f * std::max(std::abs(lo), std::abs(hi)) || hi - lo < 1e-30f) {
    const float d = std::max(std::abs(lo) * 1e-3f, 1e-6f);  // constant: centred
    lo -= d;
    hi += d;
  }
  const float pad = 0.06f * (hi - lo);
  lo -= pad;
  hi += pad;
  return pad;
}

/// x tick labels at every second, third or sixth grid line, the densest that keep a space between
/// them (at 1.5x four labels ran into each other), and the x label between the last two if it fits.
void x_ticks(ImDrawList* dl, const Box& box, const char* x_label, ImU32 axis, float fh) {
  const float gap = 0.5f * fh;
  char buf[32];
  auto tick_text = [&](int k) {
    std::snprintf(buf, sizeof buf, "%.3g", box.x0 + (box.x1 - box.x0) * k / 6.f);
    return std::string(buf);
  };
  auto tick_left = [&](int k, float tw) {
    return std::clamp(box.X(box.x0 + (box.x1 - box.x0) * k / 6.f) - 0.5f * tw, box.a.x, box.b.x - tw);
  };
  int every = 6;
  for (int step : {2, 3}) {
    bool fits = true;
    float right = -INFINITY;
    for (int k = 0; k <= 6 && fits; k += step) {
      const float tw = ImGui::CalcTextSize(tick_text(k).c_str()).x, l = tick_left(k, tw);
      fits = l >= right + gap;
      right = l + tw;
    }
    if (fits) {
      every = step;
      break;
    }
  }
  float last_right = box.a.x, prev_right = box.a.x, last_left = box.b.x;
  for (int k = 0; k <= 6; k += every) {
    const std::string t = tick_text(k);
    const float tw = ImGui::CalcTextSize(t.c_str()).x, l = tick_left(k, tw);
    dl->AddText(ImVec2(l, box.b.y + 2.f), axis, t.c_str());
    prev_right = last_right;
    last_left = l;
    last_right = l + tw;
  }
  const float xs = ImGui::CalcTextSize(x_label).x, xm = 0.5f * (prev_right + last_left) - 0.5f * xs;
  if (xm >= prev_right + gap && xm + xs <= last_left - gap) dl->AddText(ImVec2(xm, box.b.y + 2.f), axis, x_label);
}

/// The curves, clipped to the box; a dashed curve skips every other run of three segments.
void draw_curves(ImDrawList* dl, const Box& box, const std::vector<Curve>& curves) {
  dl->PushClipRect(box.a, box.b, true);
  for (const Curve& c : curves) {
    const int n = static_cast<int>(c.y.size());
    for (int i = 0; i + 1 < n; ++i) {
      if (c.dashed && (i / 3) % 2 == 1) continue;
      if (!std::isfinite(c.y[i]) || !std::isfinite(c.y[i + 1])) continue;
      const float xa = box.x0 + (box.x1 - box.x0) * i / (n - 1), xb = box.x0 + (box.x1 - box.x0) * (i + 1) / (n - 1);
      dl->AddLine(ImVec2(box.X(xa), box.Y(c.y[i])), ImVec2(box.X(xb), box.Y(c.y[i + 1])), c.color, 2.f);
    }
  }
  dl->PopClipRect();
}

/// The legend, top right: a title too long for the box loses its " = value", then letters (the value
/// labels give it).
void legend(ImDrawList* dl, const Box& box, const std::vector<Curve>& curves, ImU32 text, float fh) {
  float ly = box.a.y + 4.f;
  for (const Curve& c : curves) {
    const float room = box.b.x - box.a.x - 34.f;
    std::string label = c.label;
    if (ImGui::CalcTextSize(label.c_str()).x > room && label.find(" = ") != std::string::npos)
      label = label.substr(0, label.find(" = "));
    if (ImGui::CalcTextSize(label.c_str()).x > room) {
      while (label.size() > 1 && ImGui::CalcTextSize((label + "..").c_str()).x > room) label.pop_back();
      label += "..";
    }
    const float w = ImGui::CalcTextSize(label.c_str()).x;
    const float lx = std::max(box.a.x + 4.f, box.b.x - w - 30.f);
    dl->AddLine(ImVec2(lx, ly + 0.5f * fh), ImVec2(lx + 20.f, ly + 0.5f * fh), c.color, 2.f);
    dl->AddText(ImVec2(lx + 24.f, ly), text, label.c_str());
    ly += fh + 2.f;
  }
}

}  // namespace

void curve_plot(const char* id, const char* x_label, float x0, float x1, const std::vector<Curve>& curves,
                ImVec2 size, bool include_zero) {
  if (size.x <= 0.f) size.x = ImGui::GetContentRegionAvail().x;
  const float fh = ImGui::GetFontSize();
  // tall enough for the legend inside the box and three value labels beside it (the legend of three
  // curves ran over the tick labels under a short box)
  const float legend_h = static_cast<float>(curves.size()) * (fh + 2.f) + 8.f;
  size.y = std::max(size.y, std::max(legend_h, 3.f * fh + 4.f) + 4.f + 1.4f * fh);
  const ImVec2 p0 = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton(id, size);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const PlotLook look = plot_look();
  const ImU32 axis = look.axis, grid = look.grid;
  float lo = 0.f, hi = 0.f;
  const float pad = value_range(curves, include_zero, lo, hi);
  // Value labels: enough digits to tell the ends apart (a sparkline's E_tot differs in the 6th digit).
  const float big = std::max(std::abs(lo), std::abs(hi));
  const int digits = std::clamp(static_cast<int>(std::ceil(std::log10(std::max(1.f, big / (hi - lo))))) + 2, 3, 7);
  auto text_of = [&](float v) {
    char t[32];
    std::snprintf(t, sizeof t, "%.*g", digits, v);
    return std::string(t);
  };
  const std::string top = text_of(hi - pad), bottom = text_of(lo + pad), middle = text_of(0.5f * (lo + hi));
  const float label_w = std::max({ImGui::CalcTextSize(top.c_str()).x, ImGui::CalcTextSize(bottom.c_str()).x,
                                  ImGui::CalcTextSize(middle.c_str()).x, 2.7f * fh});
  // Plot box, leaving room for the value labels and the x label.
  const Box box{ImVec2(p0.x + label_w + 6.f, p0.y + 4.f), ImVec2(p0.x + size.x - 4.f, p0.y + size.y - 1.4f * fh),
                x0, x1, lo, hi};
  const ImVec2 a = box.a, b = box.b;
  dl->AddRectFilled(a, b, look.fill);
  if (lo < 0.f && hi > 0.f) dl->AddLine(ImVec2(a.x, box.Y(0.f)), ImVec2(b.x, box.Y(0.f)), grid);
  for (int k = 1; k < 6; ++k) {
    const float x = x0 + (x1 - x0) * k / 6.f;
    dl->AddLine(ImVec2(box.X(x), a.y), ImVec2(box.X(x), b.y), grid);
  }
  dl->AddRect(a, b, axis);
  dl->AddText(ImVec2(p0.x, a.y), axis, top.c_str());
  dl->AddText(ImVec2(p0.x, b.y - fh), axis, bottom.c_str());
  // "0" where it leaves the top and bottom labels a line clear (at 0.053 of 0.76 it sat on "0.053")
  const float y0 = box.Y(0.f);
  if (include_zero && lo < -pad && hi > pad && y0 - 0.5f * fh > a.y + fh && y0 + 0.5f * fh < b.y - fh)
    dl->AddText(ImVec2(p0.x, y0 - 0.5f * fh), axis, "0");
  if (!include_zero) dl->AddText(ImVec2(p0.x, 0.5f * (a.y + b.y) - 0.5f * fh), axis, middle.c_str());
  x_ticks(dl, box, x_label, axis, fh);
  draw_curves(dl, box, curves);
  legend(dl, box, curves, look.text, fh);
}

}  // namespace sph::gui
