#include "sph/suggest.h"

#include <algorithm>
#include <cctype>
#include <numeric>

namespace sph {
namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // Optimal string alignment: three rows of the dynamic programme (Damerau's adjacent swap included).
  const std::size_t n = b.size();
  std::vector<std::size_t> prev2(n + 1), prev(n + 1), row(n + 1);
  std::iota(prev.begin(), prev.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    row[0] = i;
    for (std::size_t j = 1; j <= n; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      row[j] = std::min({prev[j] + 1, row[j - 1] + 1, prev[j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) row[j] = std::min(row[j], prev2[j - 2] + 1);
    }
    prev2.swap(prev);
    prev.swap(row);
  }
  return prev[n];
}

std::string nearest(std::string_view word, const std::vector<std::string>& candidates) {
  const std::string w = lower(word);
  if (w.empty()) return {};
  const std::size_t limit = std::max<std::size_t>(1, w.size() / 3);
  const std::size_t wdot = w.rfind('.');
  const std::string wtail = wdot == std::string::npos ? w : w.substr(wdot + 1);
  // score = 2 x edits, or 1 when the typed name starts the candidate's ("scene.n" for scene.n_side)
  std::string best;
  std::size_t best_score = 2 * limit + 1;
  for (const std::string& c : candidates) {
    const std::string lc = lower(c);
    if (lc == w) return c;
    const std::size_t dot = lc.rfind('.');
    const std::string tail = dot == std::string::npos ? lc : lc.substr(dot + 1);
    std::size_t score = 2 * std::min(edit_distance(w, lc), edit_distance(wtail, tail));
    if (!wtail.empty() && tail.starts_with(wtail) && lc.starts_with(w.substr(0, wdot == std::string::npos ? 0 : wdot)))
      score = std::min<std::size_t>(score, 1);
    if (score < best_score) {
      best_score = score;
      best = c;
    }
  }
  return best;
}

std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates) {
  const std::string n = nearest(word, candidates);
  return n.empty() ? std::string() : " (did you mean " + n + "?)";
}

}  // namespace sph
