// The seed documents' citations (sph/seed_documents.h) and the help texts that name them: every "seed NNN"
// a student reads in `sph help`, `sph params` or the GUI's help window comes with the document it means.
#include "sph/seed_documents.h"

#include <gtest/gtest.h>

#include "sph/config.h"
#include "sph/help_text.h"
#include "sph/scene.h"

namespace sph {
namespace {

TEST(SeedDocuments, CitesOnlyTheSeedsATextNames) {
  EXPECT_EQ(seed_citations("no citation here"), "");
  const std::string c = seed_citations("seed 003 eq. 2.43 and seed 000 eq. 3.2.17");
  EXPECT_EQ(c.find("Seed documents cited above:\n"), 0u);
  const std::size_t s0 = c.find("  seed 000: A. Madrigal Lucatero (2017)"), s3 = c.find("  seed 003: F. Castellanos");
  ASSERT_NE(s0, std::string::npos) << c;
  ASSERT_NE(s3, std::string::npos) << c;
  EXPECT_LT(s0, s3);  // in the documents' order
  EXPECT_EQ(c.find("seed 001"), std::string::npos);
  EXPECT_EQ(seed_documents().size(), 5u);
  const std::string all = seed_citations("seed 000 seed 001 seed 002 seed 003 seed 004");
  std::size_t start = 0, lines = 0;
  for (std::size_t end; (end = all.find('\n', start)) != std::string::npos; start = end + 1, ++lines)
    EXPECT_LE(end - start, 100u) << all.substr(start, end - start);  // bytes: accented letters count twice
  EXPECT_GT(lines, 6u);  // the long titles wrap
}

/// Every "seed NNN" in `text` has its citation line after the text.
void expect_every_seed_named(const std::string& text, const std::string& what) {
  for (const SeedDocument& d : seed_documents()) {
    const std::string name = "seed " + std::string(d.id);
    const std::size_t first = text.find(name), line = text.find("  " + name + ": ");
    if (first == std::string::npos) continue;
    EXPECT_NE(line, std::string::npos) << what << " cites " << name << " without naming it";
  }
}

TEST(SeedDocuments, EveryHelpTextNamesTheSeedsItCites) {
  expect_every_seed_named(params_help(), "sph params");
  expect_every_seed_named(scenes_help(), "sph help");
  for (const SceneSpec& s : scene_registry()) expect_every_seed_named(scene_help(RunConfig::from_scene(s.name)), s.name);
  EXPECT_NE(params_help().find("Seed documents cited above:"), std::string::npos);  // it cites seeds
}

}  // namespace
}  // namespace sph
