// The seed documents (sph/seed_documents.h): citations as the README's bibliography gives them.
#include "sph/seed_documents.h"

namespace sph {

const std::vector<SeedDocument>& seed_documents() {
  static const std::vector<SeedDocument> docs = {
      {"000", "A. Madrigal Lucatero (2017), Solución numérica de las ecuaciones de Euler usando el método SPH"},
      {"001", "L. Cueto-Felgueroso, G. Mosqueira, I. Colominas, F. Navarrina, M. Casteleiro (2002), Análisis de "
              "formulaciones numéricas SPH para la resolución de problemas de flujo con superficie libre"},
      {"002", "J. M. Ruiz V., D. A. León E. (2016), Una introducción al método libre de malla de conjuntos finitos de "
              "puntos"},
      {"003", "F. Castellanos Fuentes (2010), Estudios de sistemas astrofísicos hidrodinámicos utilizando el método de "
              "partículas suavizadas"},
      {"004", "D. Duque (2011), SPH (a section of a longer text)"},
  };
  return docs;
}

namespace {

/// `line` wrapped at spaces into lines of at most `width` columns (bytes), continuations indented.
std::string wrapped(const std::string& line, std::size_t width, const std::string& indent) {
  std::string out, rest = line;
  while (rest.size() > width) {
    const std::size_t cut = rest.rfind(' ', width);
    if (cut == std::string::npos || cut <= indent.size()) break;
    out += rest.substr(0, cut) + "\n";
    rest = indent + rest.substr(cut + 1);
  }
  return out + rest + "\n";
}

}  // namespace

std::string seed_citations(std::string_view text) {
  std::string out;
  for (const SeedDocument& d : seed_documents()) {
    const std::string name = "seed " + std::string(d.id);
    if (text.find(name) == std::string_view::npos) continue;
    if (out.empty()) out = "Seed documents cited above:\n";
    out += wrapped("  " + name + ": " + std::string(d.citation), 100, "      ");
  }
  return out;
}

std::string with_seed_citations(std::string text) {
  const std::string cited = seed_citations(text);
  return cited.empty() ? text : text + "\n" + cited;
}

}  // namespace sph
