// "Did you mean ...?": the candidate nearest to a mistyped word by edit distance, for the messages that
// refuse an unknown key, scene, field or flag.
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace sph {

/// Levenshtein distance (insertions, deletions, substitutions; an adjacent swap counts as one edit).
std::size_t edit_distance(std::string_view a, std::string_view b);

/// The candidate nearest to `word` (case-insensitive), or "" when none is close: at most a third of the
/// word's length in edits (at least one), measured against the whole candidate or its name after the
/// group's dot (so "n_lef" finds "scene.n_left"); a candidate whose name the word begins ("scene.n" for
/// "scene.n_side") is nearer than any edit. Ties go to the earliest candidate.
std::string nearest(std::string_view word, const std::vector<std::string>& candidates);

/// " (did you mean X?)" for nearest(word, candidates), or "" when nothing is close.
std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates);

}  // namespace sph
