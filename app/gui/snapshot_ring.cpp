#include "snapshot_ring.h"

namespace sph::gui {
namespace {

std::size_t snapshot_bytes(const Snapshot& s) {
  std::size_t n = s.x.size() + s.y.size() + s.z.size() + s.h.size();
  for (const SnapshotField& f : s.fields) n += f.values.size();
  return n * sizeof(float) + s.kind.size();
}

}  // namespace

std::size_t SnapshotRing::frame_bytes(const StepperFrame& f) {
  return snapshot_bytes(f.snapshot) + (f.comparing ? snapshot_bytes(f.compare.snapshot) : 0);
}

void SnapshotRing::push(const StepperFrame& f) {
  if (!frames_.empty() && f.world_serial != world_) clear();
  world_ = f.world_serial;
  if (!frames_.empty() && frames_.back().snapshot.step == f.snapshot.step) return;  // the same state
  StepperFrame copy = f;  // view-only: the plots' history, warnings and the inspection stay with the live frame
  copy.history.clear();
  copy.compare.history.clear();
  copy.warnings.clear();
  copy.inspection.reset();
  copy.compare.inspection.reset();
  bytes_ += frame_bytes(copy);
  frames_.push_back(std::move(copy));
  while (frames_.size() > 1 && (frames_.size() > max_frames_ || bytes_ > max_bytes_)) {
    bytes_ -= frame_bytes(frames_.front());
    frames_.pop_front();
  }
}

void SnapshotRing::clear() {
  frames_.clear();
  bytes_ = 0;
}

}  // namespace sph::gui
