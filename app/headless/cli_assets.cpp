#include "cli_assets.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "exit_codes.h"
#include "sph/config.h"
#include "sph/scene_asset.h"

namespace sph::cli {

int scene_json_command(const std::string& name) {
  try {
    std::fputs(scene_asset_json(name).c_str(), stdout);
  } catch (const ConfigError& e) {
    std::fprintf(stderr, "sph: scene-json: %s\n", e.what());
    return kInvalidScene;
  }
  return kOk;
}

int write_assets_command(const std::string& dir) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) {
    std::fprintf(stderr, "sph: write-assets: %s is not a directory\n", dir.c_str());
    return kIoError;
  }
  int written = 0;
  for (const SceneSpec& s : scene_registry()) {
    const std::filesystem::path path = std::filesystem::path(dir) / (s.name + ".json");
    std::ofstream out(path, std::ios::binary);
    out << scene_asset_json(s.name);
    out.close();
    if (!out) {
      std::fprintf(stderr, "sph: write-assets: cannot write %s\n", path.string().c_str());
      return kIoError;
    }
    ++written;
  }
  std::printf("wrote %d scene files to %s\n", written, dir.c_str());
  return kOk;
}

}  // namespace sph::cli
