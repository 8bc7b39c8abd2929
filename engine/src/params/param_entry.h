// How one entry of the parameter table (sph/param_table.h) is made: its key, unit, meaning and owning
// stage, and the get/set pair of a number in a range, an enumeration or a physics slot. Used by the
// table's declarations in params/param_table.cpp.
#pragma once
#include <cmath>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "text/number_text.h"
#include "sph/param_table.h"

namespace sph::param_entry {

using Active = std::function<bool(const Params&)>;

/// What every entry declares: key, unit, meaning, old flat key, the stage that uses it, and whether a
/// change takes effect while the scene runs.
struct Common {
  std::string_view key, unit, what, alias = {};
  /// Which stage a parameter belongs to: the words that name it in messages, its slot, and when it is used.
  struct Owner {
    std::string_view stage = {};
    Slot slot = Slot::Count;
    Active active = nullptr;
  } owner = {};
  bool live = true;
};

ParamInfo base(const Common& c);

/// The message of a choice that names none of `names`.
std::string not_one_of(std::string_view key, const std::string& text, const std::vector<std::string>& names);

/// A value as text: doubles exactly (they read back the same), integers as they are.
inline std::string value_text(double v) { return exact_text(v); }
inline std::string value_text(int v) { return std::to_string(v); }

/// A number of type T (double or int) in [lo, hi], at ref(params).
template <class T, class Ref>
ParamInfo ranged(const Common& c, Ref ref, T lo, T hi) {
  constexpr bool kInteger = std::is_same_v<T, int>;
  ParamInfo p = base(c);
  p.integer = kInteger;
  p.min = lo;
  p.max = hi;
  p.get = [ref](const Params& prm) { return value_text(ref(const_cast<Params&>(prm))); };
  p.set = [ref, lo, hi, key = c.key](Params& prm, const std::string& text, std::string& err) {
    double v = 0.0;
    if (!parse_number(text, v) || (kInteger && v != std::floor(v))) {
      err = "'" + text + (kInteger ? "' is not an integer" : "' is not a number");
      return false;
    }
    if (v < lo || v > hi) {
      err = std::string(key) + " = " + text + " is out of range [" + value_text(lo) + ", " + value_text(hi) + "]";
      return false;
    }
    ref(prm) = static_cast<T>(v);
    return true;
  };
  return p;
}

template <class Ref>
ParamInfo real(const Common& c, Ref ref, double lo, double hi) {
  return ranged<double>(c, ref, lo, hi);
}

template <class Ref>
ParamInfo integer(const Common& c, Ref ref, int lo, int hi) {
  return ranged<int>(c, ref, lo, hi);
}

/// An enumeration E, one of `values`, at ref(params).
template <class E, class Ref>
ParamInfo choice(const Common& c, Ref ref, std::vector<E> values) {
  ParamInfo p = base(c);
  for (E e : values) p.choices.emplace_back(to_string(e));
  p.get = [ref](const Params& prm) { return std::string(to_string(ref(const_cast<Params&>(prm)))); };
  p.set = [ref, key = c.key, names = p.choices](Params& prm, const std::string& text, std::string& err) {
    E e{};
    if (!parse(text, e)) {
      err = not_one_of(key, text, names);
      return false;
    }
    ref(prm) = e;
    return true;
  };
  return p;
}

/// The entry of a physics slot (physics.KEY), `alias` its flat key of earlier versions.
ParamInfo slot(const SlotInfo& s, std::string_view key, std::string_view alias);

}  // namespace sph::param_entry
