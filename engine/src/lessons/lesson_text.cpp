// Lessons as text (`sph lesson show`, the GUI's claim line).
#include "text/number_text.h"
#include "lesson_sets_text.h"
#include "sph/lesson.h"

namespace sph {
namespace {

std::string num(double v) { return g_text(v, 6); }

std::string sets_text(const LessonSets& sets) { return lessons::join_sets(sets, " ", "(defaults)"); }

/// "colour by vx; panels rho, v; log10 scale; profile along x", or "" when the step sets no view.
std::string view_text(const LessonView& v) {
  std::string out;
  const auto add = [&](const std::string& part) { out += (out.empty() ? "" : "; ") + part; };
  if (!v.color_by.empty()) add("colour by " + v.color_by);
  if (v.panels) {
    std::string list;
    for (const std::string& p : *v.panels) list += (list.empty() ? "" : ", ") + p;
    add(list.empty() ? "one panel" : "panels " + list);
  }
  if (v.log >= 0) add(v.log == 1 ? "log10 scale" : "linear scale");
  if (!v.profile_axis.empty()) add(v.profile_axis == "off" ? "the plane view" : "profile along " + v.profile_axis);
  if (v.range) add("range " + num(v.range->first) + " to " + num(v.range->second));
  if (v.zoom) add("centre (" + num((*v.zoom)[0]) + ", " + num((*v.zoom)[1]) + "), zoom " + num((*v.zoom)[2]));
  if (v.cut_axis >= 0) add(std::string("cutaway ") + "xyz"[v.cut_axis] + " <= " + num(v.cut_at));
  if (v.residuals >= 0) add(v.residuals == 1 ? "error strip" : "no error strip");
  return out;
}

}  // namespace

std::string metric_label(const LessonCheck& check) {
  return check.reduce == "end" ? check.metric : check.reduce + "(" + check.metric + ")";
}

std::string claim_text(const LessonStep& step) {
  const LessonCheck& k = step.check;
  const std::string m = metric_label(k);
  const std::string at = k.until > 0.0 ? " at t = " + num(k.until) : " at t_end";
  const std::string margin = k.factor > 1.0 ? " by at least " + num(k.factor) + "x" : "";
  switch (k.type) {
    case LessonCheck::Type::Falls: {
      std::string seq;
      for (double v : k.values) seq += (seq.empty() ? "" : " -> ") + num(v);
      return m + at + " falls" + margin + " at each step of " + k.key + " = " + seq;
    }
    case LessonCheck::Type::Compare: {
      const LessonSets& lo = k.smaller == 'a' ? k.a : k.b;
      const LessonSets& hi = k.smaller == 'a' ? k.b : k.a;
      return m + at + " with " + sets_text(lo) + " is smaller" + margin + " than with " + sets_text(hi);
    }
    case LessonCheck::Type::Below: return m + at + " < " + num(k.limit);
    case LessonCheck::Type::Above: return m + at + " > " + num(k.limit);
  }
  return {};
}

std::string lesson_text(const Lesson& l) {
  std::string s = l.title + "\n";
  if (!l.summary.empty()) s += l.summary + "\n";
  for (std::size_t i = 0; i < l.steps.size(); ++i) {
    const LessonStep& st = l.steps[i];
    s += "\nStep " + std::to_string(i + 1) + "/" + std::to_string(l.steps.size()) + ": " + st.title + "\n";
    s += "  " + st.text + "\n";
    if (!st.predict.empty()) s += "  predict first: " + st.predict + "\n  answer: " + st.answer + "\n";
    s += "  scene: " + st.scene + "  " + sets_text(st.sets) + "\n";
    if (!st.change.empty()) s += "  change: " + st.change + "\n";
    if (!st.look_at.empty()) s += "  look at: " + st.look_at + "\n";
    if (st.pause_at > 0.0) s += "  pauses at t = " + num(st.pause_at) + "\n";
    if (!st.sweep_key.empty()) {
      std::string values;
      for (const std::string& v : st.sweep_values) values += (values.empty() ? "" : ", ") + v;
      s += "  sweep: " + st.sweep_key + " = " + values + " beside run A, drawn together\n";
    }
    if (const std::string v = view_text(st.view); !v.empty()) s += "  view: " + v + "\n";
    s += "  claim: " + claim_text(st) + "\n";
  }
  return s;
}

}  // namespace sph
