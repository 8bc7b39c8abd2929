// Fuzzes the checkpoint reader (sph/checkpoint.h, `sph resume`, the GUI's "load state"). A random byte
// string almost never passes the checksum, so the first byte chooses which layer the rest reaches:
//   0: the container itself (decode_checkpoint: magic, version, sizes, sections, checksum, end marker);
//   1: the world state (World::restore_state) of a small Sod tube, behind a valid container;
//   2: the run's own sections (`sph resume`'s run options and output state, split at the first newline),
//      wrapped in a valid checkpoint file and read back with load_resume_point.
// Every input must be taken or refused with a CheckpointError; nothing else may escape, crash or leak.
// Seed corpus (tests/fuzz/corpus/checkpoint/), from `sph run sod --set scene.n_left=20 --until 0.004
// --checkpoint-every 0.002 --out D`: container = 0x00 + D/checkpoint.sph, world = 0x01 + its world
// section, run = 0x02 + its run options + newline + its output state (tests/fuzz/make_checkpoint_corpus.py).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "run_checkpoint.h"
#include "sph/checkpoint.h"
#include "sph/config.h"
#include "sph/world.h"

namespace {

/// The scene the corpus' world state was saved from.
sph::RunConfig tiny_sod() {
  sph::RunConfig cfg = sph::RunConfig::from_scene("sod");
  cfg.set("scene.n_left", "20", "fuzz");
  cfg.validate();
  return cfg;
}

/// A folder of this process for mode 2's checkpoint file.
const std::string& work_dir() {
  static const std::string dir = [] {
    const auto d = std::filesystem::temp_directory_path() / ("sph_fuzz_checkpoint_" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    return d.string();
  }();
  return dir;
}

void container(const std::string& bytes) { (void)sph::decode_checkpoint(bytes, "fuzz.sph"); }

void world_state(const std::string& bytes) {
  static const sph::RunConfig cfg = tiny_sod();
  sph::World world(cfg);
  world.restore_state(bytes, "fuzz.sph");
  (void)world.save_state();  // a state taken over must be whole enough to be saved again
}

void run_sections(const std::string& bytes) {
  static const sph::RunConfig cfg = tiny_sod();
  static const std::string world = sph::World(cfg).save_state();
  const auto cut = bytes.find('\n');
  sph::Checkpoint ck;
  ck.config_json = cfg.to_json();
  ck.run_options = bytes.substr(0, cut);
  ck.world = world;
  ck.extra = cut == std::string::npos ? std::string() : bytes.substr(cut + 1);
  const std::string err = sph::write_checkpoint(sph::cli::checkpoint_path(work_dir()), ck);
  if (!err.empty()) __builtin_trap();  // the fuzzer's own folder must be writable
  sph::cli::RunOptions opt;
  (void)sph::cli::load_resume_point(work_dir(), &opt);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string rest(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    switch (data[0] % 3) {
      case 0: container(rest); break;
      case 1: world_state(rest); break;
      default: run_sections(rest); break;
    }
  } catch (const sph::CheckpointError&) {
    // refused with a message naming the file: the expected outcome for damaged input
  }
  return 0;
}
