// Triple buffer: one writer, one reader, neither ever waits. The writer fills its back slot and swaps it
// with the middle slot; the reader swaps its front slot with the middle slot when the middle holds a
// newer value. A value is always read whole (the reader owns its slot until its next acquire).
#pragma once
#include <array>
#include <atomic>

namespace sph::detail {

template <class T>
class TripleBuffer {
 public:
  /// Writer: the slot to fill (the writer's own until publish()).
  T& back() { return slots_[back_]; }
  /// Writer: makes back() the newest value and takes the old middle slot as the new back slot.
  void publish() { back_ = middle_.exchange(back_ | kFresh, std::memory_order_acq_rel) & kIndex; }
  /// Writer or reader: a published value has not been taken by the reader yet.
  bool unread() const { return (middle_.load(std::memory_order_acquire) & kFresh) != 0; }

  /// Reader: takes the newest value if there is one; false (front unchanged) otherwise.
  bool acquire() {
    if ((middle_.load(std::memory_order_relaxed) & kFresh) == 0) return false;
    front_ = middle_.exchange(front_, std::memory_order_acq_rel) & kIndex;
    return true;
  }
  /// Reader: the value taken by the last successful acquire().
  const T& front() const { return slots_[front_]; }

 private:
  static constexpr unsigned kIndex = 3u, kFresh = 4u;
  std::array<T, 3> slots_{};
  unsigned back_ = 0, front_ = 2;       // private to the writer / the reader
  std::atomic<unsigned> middle_{1u};    // index of the shared slot, plus the kFresh bit
};

}  // namespace sph::detail
