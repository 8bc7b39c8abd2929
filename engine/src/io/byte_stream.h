// Little-endian binary writer and bounds-checked reader for checkpoints: numbers keep every bit
// (doubles are copied, never printed), vectors carry their length. A read past the end or a length
// that cannot fit throws CheckpointError: a damaged file never leaves a half-read state behind.
#pragma once
#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "sph/checkpoint.h"

namespace sph {

static_assert(std::endian::native == std::endian::little, "checkpoints are written little-endian");

/// Appends values to a byte string.
class ByteWriter {
 public:
  template <class T>
  void put(T v) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* b = reinterpret_cast<const char*>(&v);
    out_.append(b, sizeof(T));
  }
  void put_bool(bool b) { put<std::uint8_t>(b ? 1 : 0); }
  void put_string(const std::string& s) {
    put<std::uint64_t>(s.size());
    out_.append(s);
  }
  /// A vector of plain values: its length, then its elements.
  template <class T>
  void put_vec(const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    put<std::uint64_t>(v.size());
    if (!v.empty()) out_.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
  const std::string& bytes() const { return out_; }
  std::string take() { return std::move(out_); }

 private:
  std::string out_;
};

/// Reads what ByteWriter wrote; `what` names the source in errors.
class ByteReader {
 public:
  ByteReader(const char* data, std::size_t size, std::string what) : p_(data), end_(data + size), what_(std::move(what)) {}
  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    need(sizeof(T));
    T v;
    std::memcpy(&v, p_, sizeof(T));
    p_ += sizeof(T);
    return v;
  }
  bool get_bool() {
    const auto b = get<std::uint8_t>();
    if (b > 1) fail("a flag is neither 0 nor 1");
    return b == 1;
  }
  std::string get_string() {
    const auto n = get<std::uint64_t>();
    need(n);
    std::string s(p_, static_cast<std::size_t>(n));
    p_ += n;
    return s;
  }
  template <class T>
  std::vector<T> get_vec() {
    const auto n = get<std::uint64_t>();
    if (n > static_cast<std::uint64_t>(end_ - p_) / sizeof(T)) fail("an array is longer than the data left");
    std::vector<T> v(static_cast<std::size_t>(n));
    if (n > 0) std::memcpy(v.data(), p_, static_cast<std::size_t>(n) * sizeof(T));
    p_ += n * sizeof(T);
    return v;
  }
  std::size_t left() const { return static_cast<std::size_t>(end_ - p_); }
  [[noreturn]] void fail(const std::string& why) const { throw CheckpointError(what_ + ": " + why); }

 private:
  void need(std::uint64_t n) const {
    if (n > static_cast<std::uint64_t>(end_ - p_)) fail("the data ends early");
  }
  const char* p_;
  const char* end_;
  std::string what_;
};

}  // namespace sph
