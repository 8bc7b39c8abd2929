// A background thread writing the frames' PNG files one at a time, while the next frame is rendered.
#pragma once
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "sph/output_manifest.h"

namespace sph::cli {

/// One background thread that writes one PNG at a time: the next frame is rendered while the
/// previous one is compressed. submit() waits for the previous write (so at most two frames are in
/// memory) and hands over the pixels.
class AsyncPngWriter {
 public:
  explicit AsyncPngWriter(sph::OutputManifest* manifest);
  ~AsyncPngWriter();

  /// Queues rgba for `path` (swapping buffers with the caller); false with the previous write's error.
  bool submit(const std::string& path, int width, int height, std::vector<std::uint8_t>* rgba, std::string* err);
  /// Waits for the write in flight; false with its error.
  bool wait(std::string* err);

 private:
  bool take_error(std::string* err);
  void run();

  sph::OutputManifest* manifest_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  bool busy_ = false, quit_ = false;
  std::string path_, error_;
  int width_ = 0, height_ = 0;
  std::vector<std::uint8_t> pixels_;
  std::thread thread_;  // last: starts after the members it uses exist
};

}  // namespace sph::cli
