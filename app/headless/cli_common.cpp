#include "cli_common.h"

#include "exit_codes.h"
#include "sph/key_value.h"
#include "sph/world.h"
#ifdef SPH_HAVE_FRAMES
#include "frame_size.h"
#endif

#include <cmath>
#include <cstdio>
#include <sstream>


namespace sph::cli {

std::vector<double> parse_number_list(const std::string& text, const std::string& flag) {
  std::vector<double> out;
  for (const std::string& item : split_names(text)) {
    std::size_t used = 0;
    double v = 0.0;
    try {
      v = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != item.size() || !std::isfinite(v)) throw ConfigError(flag + ": '" + item + "' is not a number");
    out.push_back(v);
  }
  return out;
}

std::vector<std::string> split_names(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  for (std::string item; std::getline(ss, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

void apply_sets(RunConfig& cfg, const std::vector<std::string>& sets) {
  for (const auto& kv : sets) apply_key_value(cfg, "--set", kv);
}

bool make_output_dir(const std::filesystem::path& dir, bool* existed) {
  std::error_code ec;
  *existed = std::filesystem::exists(dir, ec);
  std::filesystem::create_directories(dir, ec);
  return !ec && std::filesystem::is_directory(dir, ec);
}

int guarded_runs(const char* command, const std::filesystem::path& dir, bool existed, const std::function<void()>& work) {
  int rc = kOk;
  try {
    work();
  } catch (const ConfigError& e) {
    std::fprintf(stderr, "sph: %s: %s\n", command, e.what());
    rc = kInvalidScene;
  } catch (const DivergedError& e) {
    std::fprintf(stderr, "sph: %s: a run diverged: %s (nothing written)\n", command, e.what());
    rc = kDiverged;
  }
  std::error_code ec;
  if (rc != kOk && !existed) std::filesystem::remove(dir, ec);
  return rc;
}

bool parse_plot_size(const std::string& size, int* width, int* height) {
#ifdef SPH_HAVE_FRAMES
  if (render::parse_frame_size(size, width, height)) return true;
  std::fprintf(stderr, "sph: --size %s: expected WIDTHxHEIGHT, e.g. 1280x720\n", size.c_str());
  return false;
#else
  (void)size;
  *width = *height = 0;
  return true;
#endif
}

}  // namespace sph::cli
