// Fuzzes `--set key=value` (cli::apply_sets -> RunConfig::set) on a built-in scene chosen by the first
// byte; the rest is one override per line. Each must be applied or refused with a ConfigError.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "cli_common.h"
#include "sph/config.h"
#include "sph/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const auto& scenes = sph::scene_registry();
  const std::string name = scenes[data[0] % scenes.size()].name;
  std::vector<std::string> sets;
  std::stringstream lines(std::string(reinterpret_cast<const char*>(data + 1), size - 1));
  for (std::string line; std::getline(lines, line);) sets.push_back(line);
  try {
    sph::RunConfig cfg = sph::RunConfig::from_scene(name);
    sph::cli::apply_sets(cfg, sets);
    cfg.validate();
    (void)cfg.to_json();
  } catch (const sph::ConfigError&) {
  }
  return 0;
}
