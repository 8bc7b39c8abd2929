// The five seed documents that "seed NNN eq. X" cites (README, "Bibliography"), so that every text a
// student reads with such a citation (`sph help`, `sph params`, `sph list`, the GUI's help window) can
// say which document it means.
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace sph {

struct SeedDocument {
  std::string_view id;        ///< "000" .. "004"
  std::string_view citation;  ///< author(s), year, title
};

/// The seed documents in order.
const std::vector<SeedDocument>& seed_documents();

/// "Seed documents cited above:" and "  seed NNN: citation" for each seed that `text` names as "seed NNN",
/// in order, wrapped at 100 columns as the help texts are; "" when it names none.
std::string seed_citations(std::string_view text);

/// `text`, then a blank line and seed_citations(text) when it names a seed.
std::string with_seed_citations(std::string text);

}  // namespace sph
