#include "run_checkpoint.h"

#include <limits>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "exit_codes.h"
#include "run_signals.h"

#include <csignal>
#include <cstdio>

namespace sph::cli {

std::string checkpoint_path(const std::string& dir) { return dir + "/checkpoint.sph"; }

namespace {

/// A frame folder or video as the checkpoint keeps it: relative to the --out folder when inside it (sph
/// resume takes the folder where it is now), else absolute (sph resume may run from another directory).
std::string kept_path(const std::string& path, const std::string& out) {
  if (path.empty()) return path;
  std::error_code ec;
  const auto p = std::filesystem::absolute(path, ec).lexically_normal();
  const auto rel = p.lexically_relative(std::filesystem::absolute(out, ec).lexically_normal());
  return !rel.empty() && *rel.begin() != ".." ? rel.string() : p.string();
}

/// The path kept_path made, for the --out folder `out`.
std::string found_path(const std::string& kept, const std::string& out) {
  if (kept.empty() || std::filesystem::path(kept).is_absolute()) return kept;
  return (std::filesystem::path(out) / kept).string();
}

}  // namespace

std::string options_json(const RunOptions& opt) {
  nlohmann::ordered_json j;
  std::error_code ec;  // a scene file by its absolute path: sph resume may run from another directory
  j["scene"] = std::filesystem::is_regular_file(opt.scene, ec) ? std::filesystem::absolute(opt.scene, ec).string()
                                                                : opt.scene;
  j["set"] = opt.sets;
  j["until"] = opt.until;
  j["out"] = opt.out;
  j["threads"] = opt.threads;
  j["quiet"] = opt.quiet;
  j["csv_comments"] = opt.csv_comments;
  j["vtu"] = opt.vtu;
  j["splash"] = opt.splash;
  j["hdf5"] = opt.hdf5;
  j["checkpoint_every"] = opt.checkpoint_every;
  if (!opt.frames.empty()) {
    nlohmann::ordered_json f;
    f["dir"] = kept_path(opt.frames, opt.out);
    f["every"] = opt.every;
    f["size"] = opt.size;
    f["color_by"] = opt.color_by;
    f["cmap"] = opt.cmap;
    f["range"] = opt.range;
    f["log"] = opt.log_scale;
    f["linear"] = opt.linear;
    f["residuals"] = opt.residuals;
    f["high_contrast"] = opt.high_contrast;
    f["hide_walls"] = opt.hide_walls;
    f["cut"] = opt.cut;
    f["profile_axis"] = opt.profile_axis;
    f["panels"] = opt.panels;
    f["video"] = kept_path(opt.video, opt.out);
    f["fps"] = opt.fps;
    f["gl"] = opt.gl;
    f["tree_probe"] = opt.tree_probe;
    j["frames"] = f;
  }
  return j.dump();
}

namespace {

/// A whole number of type T from the checkpoint's JSON: an integer within T's range, else a json
/// type_error (a double such as 1e110, or -1 for a count, would be undefined behaviour in get<T>()).
template <class T>
T whole(const nlohmann::json& v) {
  if (v.is_number_unsigned()) {
    const auto u = v.get<std::uint64_t>();
    if (u <= static_cast<std::uint64_t>(std::numeric_limits<T>::max())) return static_cast<T>(u);
  } else if (v.is_number_integer()) {
    const auto i = v.get<std::int64_t>();
    if (i >= static_cast<std::int64_t>(std::numeric_limits<T>::min()) &&
        (i < 0 || static_cast<std::uint64_t>(i) <= static_cast<std::uint64_t>(std::numeric_limits<T>::max())))
      return static_cast<T>(i);
  }
  throw nlohmann::json::type_error::create(302, "expected a whole number in range, not " + v.dump(), &v);
}

}  // namespace

RunOptions options_from_json(const std::string& text, const std::string& path) {
  try {
    const auto j = nlohmann::json::parse(text);
    if (j.contains("program") && j["program"] == "sph-gui")
      throw CheckpointError("checkpoint " + path + ": a state saved by sph-gui (no run directory to continue); "
                            "load it in sph-gui's State panel");
    RunOptions o;
    o.scene = j.at("scene").get<std::string>();
    o.sets = j.at("set").get<std::vector<std::string>>();
    o.until = j.at("until").get<double>();
    o.out = j.at("out").get<std::string>();
    o.threads = whole<int>(j.at("threads"));
    o.quiet = j.at("quiet").get<bool>();
    o.csv_comments = j.at("csv_comments").get<bool>();
    o.vtu = j.at("vtu").get<bool>();
    o.splash = j.at("splash").get<bool>();
    o.hdf5 = j.at("hdf5").get<bool>();
    o.checkpoint_every = j.at("checkpoint_every").get<double>();
    if (j.contains("frames")) {
      const auto& f = j.at("frames");
      o.frames = f.at("dir").get<std::string>();
      o.every = f.at("every").get<double>();
      o.size = f.at("size").get<std::string>();
      o.color_by = f.at("color_by").get<std::string>();
      o.cmap = f.at("cmap").get<std::string>();
      o.range = f.at("range").get<std::string>();
      o.log_scale = f.at("log").get<bool>();
      o.linear = f.value("linear", false);  // checkpoints written before --linear existed
      o.residuals = f.value("residuals", false);
      o.high_contrast = f.value("high_contrast", false);  // checkpoints written before --high-contrast existed
      o.hide_walls = f.value("hide_walls", false);
      o.cut = f.value("cut", std::string());
      o.profile_axis = f.at("profile_axis").get<std::string>();
      o.panels = f.at("panels").get<std::string>();
      o.video = f.at("video").get<std::string>();
      o.fps = whole<int>(f.at("fps"));
      o.gl = f.at("gl").get<std::string>();
      o.tree_probe = whole<long long>(f.at("tree_probe"));
    }
    return o;
  } catch (const nlohmann::json::exception& e) {
    throw CheckpointError("checkpoint " + path + ": its run options cannot be read (" + e.what() + ")");
  }
}

namespace {

nlohmann::ordered_json manifest_json(const std::vector<ManifestEntry>& entries) {
  nlohmann::ordered_json manifest = nlohmann::ordered_json::array();
  for (const ManifestEntry& e : entries) manifest.push_back({e.name, e.stamp.bytes, e.stamp.crc32});
  return manifest;
}

std::vector<ManifestEntry> manifest_from(const nlohmann::json& a) {
  std::vector<ManifestEntry> out;
  for (const auto& e : a)
    out.push_back({e.at(0).get<std::string>(), FileStamp{whole<std::uint64_t>(e.at(1)), whole<std::uint32_t>(e.at(2))}});
  return out;
}

std::string extra_json(const OutputResume& r, int next_out, std::int64_t next_checkpoint, double t_end,
                       const FrameResume& frames) {
  nlohmann::ordered_json j;
  j["t_end"] = t_end;
  j["next_out"] = next_out;
  j["next_checkpoint"] = next_checkpoint;
  j["files"] = r.files;
  nlohmann::ordered_json series = nlohmann::ordered_json::array();
  for (const PvdEntry& e : r.series) series.push_back({e.t, e.file});
  j["series"] = series;
  j["steps"] = r.steps;
  j["diag"] = {r.diag.bytes, r.diag.crc32};
  j["errors"] = {r.errors.bytes, r.errors.crc32};
  j["manifest"] = manifest_json(r.manifest);
  if (frames.active)  // doubles round-trip exactly through the JSON text
    j["frames"] = {{"next_frame", frames.next_frame}, {"written", frames.written}, {"first_t", frames.first_t},
                   {"next_t", frames.next_t}, {"manifest", manifest_json(frames.manifest)}};
  return j.dump();
}

void read_extra(const std::string& text, ResumePoint& rp) {
  try {
    const auto j = nlohmann::json::parse(text);
    rp.t_end = j.at("t_end").get<double>();
    rp.next_out = whole<int>(j.at("next_out"));
    rp.next_checkpoint = whole<std::int64_t>(j.at("next_checkpoint"));
    rp.output.files = whole<int>(j.at("files"));
    for (const auto& e : j.at("series")) rp.output.series.push_back({e.at(0).get<double>(), e.at(1).get<std::string>()});
    for (const auto& e : j.at("steps")) rp.output.steps.push_back(whole<std::int64_t>(e));
    const auto stamp = [](const nlohmann::json& a) {
      return FileStamp{whole<std::uint64_t>(a.at(0)), whole<std::uint32_t>(a.at(1))};
    };
    rp.output.diag = stamp(j.at("diag"));
    rp.output.errors = stamp(j.at("errors"));
    rp.output.manifest = manifest_from(j.at("manifest"));
    if (j.contains("frames")) {
      const auto& f = j.at("frames");
      rp.frames.active = true;
      rp.frames.next_frame = whole<int>(f.at("next_frame"));
      rp.frames.written = whole<int>(f.at("written"));
      rp.frames.first_t = f.at("first_t").get<double>();
      rp.frames.next_t = f.at("next_t").get<double>();
      rp.frames.manifest = manifest_from(f.at("manifest"));
    }
  } catch (const nlohmann::json::exception& e) {
    throw CheckpointError("checkpoint " + rp.path + ": its output state cannot be read (" + e.what() + ")");
  }
}

/// The growing CSV `name` in dir (NAME.part while its run goes on, NAME once a stopped run finished it)
/// must hold at least what it held at the checkpoint.
void check_output(const std::string& dir, const std::string& name, std::uint64_t bytes, const std::string& ck) {
  if (bytes == 0) return;
  std::string path = dir + "/" + name + ".part";
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) path = dir + "/" + name;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) throw CheckpointError("checkpoint " + ck + ": the output it continues, " + path + ", is missing");
  if (size < bytes)
    throw CheckpointError("checkpoint " + ck + ": " + path + " is shorter than at the checkpoint (" +
                          std::to_string(size) + " of " + std::to_string(bytes) + " bytes)");
}

/// Every frame the checkpoint counts must be on disk as it was written (its size).
void check_frames(const RunOptions& opt, const FrameResume& f, const std::string& ck) {
  if (f.active != !opt.frames.empty())
    throw CheckpointError("checkpoint " + ck + ": its run options and its frame state disagree");
  for (const ManifestEntry& e : f.manifest) {
    const std::string path = opt.frames + "/" + e.name;
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) throw CheckpointError("checkpoint " + ck + ": the frame it continues, " + path + ", is missing");
    if (size != e.stamp.bytes)
      throw CheckpointError("checkpoint " + ck + ": " + path + " is not the frame it wrote (" + std::to_string(size) +
                            " bytes, not " + std::to_string(e.stamp.bytes) + ")");
  }
}

}  // namespace

ResumePoint load_resume_point(const std::string& dir, RunOptions* opt) {
  ResumePoint rp;
  rp.path = checkpoint_path(dir);
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec))
    throw CheckpointError("sph resume " + dir + ": no such directory (give the --out DIR of the run)");
  rp.ck = read_checkpoint(rp.path);
  *opt = options_from_json(rp.ck.run_options, rp.path);
  opt->out = dir;  // the directory may have moved since, and the frames inside it with it
  opt->frames = found_path(opt->frames, dir);
  opt->video = found_path(opt->video, dir);
  read_extra(rp.ck.extra, rp);
  check_output(dir, "diagnostics.csv", rp.output.diag.bytes, rp.path);
  check_output(dir, "errors.csv", rp.output.errors.bytes, rp.path);
  check_frames(*opt, rp.frames, rp.path);
  return rp;
}

Checkpointer::Checkpointer(const RunOptions& opt, const RunConfig& cfg, const ResumePoint* resume)
    : path_(checkpoint_path(opt.out)), tmp_(path_ + ".tmp"), options_(options_json(opt)), config_(cfg.to_json()),
      every_(opt.checkpoint_every), next_(resume ? resume->next_checkpoint : 1) {
  set_partial_file(tmp_.c_str());
}

Checkpointer::~Checkpointer() { set_partial_file(nullptr); }

bool Checkpointer::due(double t) const {
  return every_ > 0.0 && t >= static_cast<double>(next_) * every_ * (1.0 - 1e-12);
}

void Checkpointer::write(const World& world, RunOutput& out, int next_out, const FrameResume& frames) {
  if (every_ > 0.0)
    while (due(world.time())) ++next_;
  Checkpoint ck;
  ck.config_json = config_;
  ck.run_options = options_;
  ck.world = world.save_state();
  ck.extra = extra_json(out.resume_state(), next_out, next_, world.config().params.time.t_end, frames);
  const std::string err = write_checkpoint(path_, ck);
  if (!err.empty()) throw IoError(err);
}

std::string checkpoint_unsupported(const RunOptions& opt) {
  if (opt.out.empty()) return "--checkpoint-every needs --out DIR (the checkpoint goes beside the CSVs)";
  if (!opt.compare.scene.empty() || !opt.compare.sets.empty() || !opt.sweep.empty())
    return std::string("--checkpoint-every does not cover ") + (opt.sweep.empty() ? "--compare" : "--sweep") + " runs";
  return "";
}

int report_stop(int sig, const World& world, const RunOptions& opt, bool checkpointed) {
  const char* name = sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : "a signal";
  std::fprintf(stderr, "sph: stopped by %s at t = %.6g after step %lld\n", name, world.time(),
               static_cast<long long>(world.steps()));
  if (checkpointed)
    std::fprintf(stderr, "sph: checkpoint %s written; continue with:\n  sph resume %s\n",
                 checkpoint_path(opt.out).c_str(), opt.out.c_str());
  else if (opt.out.empty())  // e.g. a run that only writes frames: nothing about a flag it did not use
    std::fprintf(stderr, "sph: no checkpoint (a run with --out DIR writes one when it is stopped)\n");
  else
    std::fprintf(stderr, "sph: no checkpoint (runs with --compare or --sweep are not checkpointed)\n");
  return sig == SIGTERM ? kTerminated : kInterrupted;
}

}  // namespace sph::cli
