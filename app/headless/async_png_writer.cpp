// AsyncPngWriter: the hand-over of one frame's pixels to the PNG thread, and that thread's loop.
#include "async_png_writer.h"

#include "error_out.h"
#include "png_file.h"

namespace sph::cli {

AsyncPngWriter::AsyncPngWriter(sph::OutputManifest* manifest) : manifest_(manifest), thread_([this] { run(); }) {}

AsyncPngWriter::~AsyncPngWriter() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    quit_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

bool AsyncPngWriter::submit(const std::string& path, int width, int height, std::vector<std::uint8_t>* rgba,
                            std::string* err) {
  std::unique_lock<std::mutex> lock(mutex_);
  done_.wait(lock, [&] { return !busy_; });
  if (!error_.empty()) return take_error(err);
  path_ = path;
  width_ = width;
  height_ = height;
  pixels_.swap(*rgba);
  busy_ = true;
  wake_.notify_all();
  return true;
}

bool AsyncPngWriter::wait(std::string* err) {
  std::unique_lock<std::mutex> lock(mutex_);
  done_.wait(lock, [&] { return !busy_; });
  return error_.empty() || take_error(err);
}

bool AsyncPngWriter::take_error(std::string* err) {
  fail(err, error_);
  error_.clear();
  return false;
}

void AsyncPngWriter::run() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    wake_.wait(lock, [&] { return busy_ || quit_; });
    if (!busy_ && quit_) return;
    lock.unlock();
    std::string err;
    const bool ok = write_png(path_, width_, height_, pixels_, &err, manifest_);  // the job is ours while busy_
    lock.lock();
    if (!ok) error_ = err;
    busy_ = false;
    done_.notify_all();
  }
}

}  // namespace sph::cli
