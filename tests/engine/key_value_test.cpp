// The one "key=value" split of the overrides, and applying one to a RunConfig.
#include <gtest/gtest.h>

#include "sph/key_value.h"

namespace sph {
namespace {

TEST(ConfigKeyValue, SplitsAtTheFirstEquals) {
  const auto kv = split_key_value("kernel.type=M6");
  ASSERT_TRUE(kv.has_value());
  EXPECT_EQ(kv->key, "kernel.type");
  EXPECT_EQ(kv->value, "M6");
  const auto more = split_key_value("scene.label=a=b");
  ASSERT_TRUE(more.has_value());
  EXPECT_EQ(more->key, "scene.label");
  EXPECT_EQ(more->value, "a=b");
  const auto empty_value = split_key_value("visc.alpha=");
  ASSERT_TRUE(empty_value.has_value());
  EXPECT_EQ(empty_value->value, "");
}

TEST(ConfigKeyValue, RefusesTextWithoutAKey) {
  EXPECT_FALSE(split_key_value("M6").has_value());
  EXPECT_FALSE(split_key_value("=M6").has_value());
  EXPECT_FALSE(split_key_value("").has_value());
}

TEST(ConfigKeyValue, AppliesToARunConfigAndNamesTheFlag) {
  RunConfig cfg = RunConfig::load("sod");
  apply_key_value(cfg, "--set", "visc.alpha=0.5");
  EXPECT_EQ(cfg.params.visc.alpha, 0.5);
  try {
    apply_key_value(cfg, "--compare-set", "M6");
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_STREQ(e.what(), "--compare-set M6: expected key=value");
  }
  EXPECT_THROW(apply_key_value(cfg, "--set", "kernel.type=M9"), ConfigError);
}

}  // namespace
}  // namespace sph
