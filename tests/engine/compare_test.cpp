// A/B comparisons' configurations (engine/src/params/compare.cpp): run B is A with its overrides, a bad
// override is refused naming it, labels give each run's value of the overridden keys, and the
// differences of two configurations are listed key by key; a sweep typed as KEY=V1,V2 is a key and its values.
#include <gtest/gtest.h>

#include "sph/compare.h"

namespace sph {
namespace {

TEST(Compare, ForkAppliesTheOverrides) {
  const RunConfig a = RunConfig::from_scene("sod");
  const RunConfig b = fork_config(a, {"kernel.type=M6", "scene.n_left=800", "visc.alpha=0"});
  EXPECT_EQ(b.params.kernel.type, KernelType::M6);
  EXPECT_EQ(b.values.at("n_left"), 800.0);
  EXPECT_EQ(b.params.visc.alpha, 0.0);
  EXPECT_EQ(a.params.kernel.type, KernelType::M4);
  EXPECT_THROW(fork_config(a, {"kernel.type=M9"}), ConfigError);
  EXPECT_THROW(fork_config(a, {"M6"}), ConfigError);
  EXPECT_THROW(fork_config(a, {"xsph.eps=0.5"}), ConfigError);  // a stage sod does not run
}

TEST(Compare, LabelsAndDifferences) {
  const RunConfig a = RunConfig::from_scene("sod");
  const std::vector<std::string> o = {"kernel.type=M6", "scene.n_left=800"};
  const RunConfig b = fork_config(a, o);
  EXPECT_EQ(compare_label(a, o), "kernel.type=M4, scene.n_left=400");
  EXPECT_EQ(compare_label(b, o), "kernel.type=M6, scene.n_left=800");
  EXPECT_EQ(differences(a, b), o);
  EXPECT_TRUE(differences(a, a).empty());
}

TEST(Compare, ASweepIsAKeyAndItsValues) {
  std::string key, err;
  std::vector<std::string> values;
  ASSERT_TRUE(split_sweep("kernel.eta=1.0, 1.5;2", &key, &values, &err));
  EXPECT_EQ(key, "kernel.eta");
  EXPECT_EQ(values, (std::vector<std::string>{"1.0", "1.5", "2"}));
  EXPECT_EQ(sweep_values(" 1.0 1.5,\n2 "), (std::vector<std::string>{"1.0", "1.5", "2"}));
  for (const char* bad : {"kernel.eta", "kernel.eta=", "=1,2", "kernel.eta= , "}) {
    EXPECT_FALSE(split_sweep(bad, &key, &values, &err)) << bad;
    EXPECT_NE(err.find("is not KEY=V1,V2"), std::string::npos) << err;
  }
  EXPECT_FALSE(split_sweep("kernel.eta=1,1.1,1.2,1.3,1.4,1.5", &key, &values, &err));
  EXPECT_EQ(err, "6 values of kernel.eta, at most 5");
}

}  // namespace
}  // namespace sph
