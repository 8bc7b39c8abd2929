// Fuzzes the scene file parser (RunConfig::from_json_text, then validate and the memory check): any
// input must either load or be refused with a ConfigError; nothing else may escape, crash or hang.
#include <cstddef>
#include <cstdint>
#include <string>

#include "sph/config.h"
#include "sph/memory_budget.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    sph::RunConfig cfg = sph::RunConfig::from_json_text(text, "fuzz.json");
    cfg.validate();
    (void)cfg.to_json();
    (void)sph::estimated_particles(cfg);
  } catch (const sph::ConfigError&) {
    // refused with a message: the expected outcome for bad input
  }
  return 0;
}
