// Checkpoint files (checkpoint.sph): a run's whole state, to continue it later with results bitwise
// identical to a run that never stopped. Layout, little-endian:
//   magic "SPHCHKPT" | u32 format version | u32 0 | u64 file size |
//   4 sections, each u64 length + bytes: the resolved scene and parameters (RunConfig::to_json), the
//   run's options (the caller's text), the world's state (World::save_state), the caller's own state |
//   u64 FNV-1a checksum of everything before it | end marker "ENDCHKPT".
// A file that is empty, truncated, damaged (checksum), of another version or not a checkpoint at all
// is refused whole with a CheckpointError naming it.
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>

namespace sph {

/// A checkpoint cannot be read (or a state cannot be restored from it); the message names the file.
struct CheckpointError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

inline constexpr std::uint32_t kCheckpointVersion = 3;  // 2: individual time steps, updates; 3: self-gravity's E_pot

struct Checkpoint {
  std::string config_json;  ///< RunConfig::to_json() of the run
  std::string run_options;  ///< how the run was started (the caller's format, e.g. JSON)
  std::string world;        ///< World::save_state()
  std::string extra;        ///< the caller's own state (e.g. output counters)
};

/// The file's bytes.
std::string encode_checkpoint(const Checkpoint& c);
/// Parses and checks a whole file's bytes; `path` names it in errors. Throws CheckpointError.
Checkpoint decode_checkpoint(const std::string& bytes, const std::string& path);
/// Writes `path` whole: to path.tmp, fsync, rename over path (then fsync of the directory), so a
/// crash leaves the old checkpoint or the new one, never part of one. Returns "" or what failed.
std::string write_checkpoint(const std::string& path, const Checkpoint& c);
/// Reads and checks `path`. Throws CheckpointError naming it (a directory, a missing file, damage).
Checkpoint read_checkpoint(const std::string& path);

/// 64-bit FNV-1a hash of `n` bytes (the checkpoint checksum).
std::uint64_t fnv1a64(const char* data, std::size_t n);

}  // namespace sph
