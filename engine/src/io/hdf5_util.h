// Small RAII and read/write helpers over the HDF5 C library (Debian's libhdf5-dev), shared by the
// snapshot writer and the initial-condition reader. Every failure throws std::runtime_error naming the
// object; HDF5's own error printing is switched off (the messages here say what went wrong).
#pragma once
#include <hdf5.h>

#include <cstdint>
#include <string>
#include <vector>

namespace sph::h5 {

/// An open HDF5 object (file, group, dataset, attribute, dataspace, property list), closed once.
class Handle {
 public:
  Handle() = default;
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  Handle(Handle&& o) noexcept : id_(o.id_), close_(o.close_) { o.id_ = H5I_INVALID_HID; }
  Handle& operator=(Handle&& o) noexcept;
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() { reset(); }
  void reset();
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }

 private:
  hid_t id_ = H5I_INVALID_HID;
  herr_t (*close_)(hid_t) = nullptr;
};

/// Switches HDF5's automatic error printing off for this process (messages come from the callers).
void quiet();

/// A file image built in memory (the core driver, no backing store); bytes() after the writes.
Handle create_memory_file();
/// The finished file's bytes (flushes first).
std::string file_bytes(hid_t file);
/// Opens a file read-only; an invalid handle if it cannot be opened as HDF5.
Handle open_file(const std::string& path);

Handle create_group(hid_t loc, const char* name);
/// Opens a group; an invalid handle when there is none (or the path names a dataset).
Handle open_group(hid_t loc, const char* path);
bool exists(hid_t loc, const char* path);

void write_attr(hid_t obj, const char* name, const std::vector<double>& values);
void write_attr(hid_t obj, const char* name, double value);
void write_attr_ints(hid_t obj, const char* name, const std::vector<long long>& values, hid_t file_type);
void write_attr_int(hid_t obj, const char* name, long long value);
void write_attr(hid_t obj, const char* name, const std::string& text);

bool has_attr(hid_t obj, const char* name);
/// Every element of a numeric attribute (scalar or array, any numeric type), converted to double.
std::vector<double> read_attr(hid_t obj, const char* name);
/// A string attribute (fixed or variable length).
std::string read_attr_string(hid_t obj, const char* name);

/// A dataset of rows x cols doubles (cols = 1: one dimension).
void write_dataset(hid_t group, const char* name, const std::vector<double>& values, std::size_t cols);
void write_dataset(hid_t group, const char* name, const std::vector<std::uint64_t>& values);
void write_dataset(hid_t group, const char* name, const std::vector<std::uint8_t>& values);

/// A numeric dataset read as doubles with its shape (rows; cols = 1 for one dimension).
struct Table {
  std::vector<double> values;
  std::size_t rows = 0, cols = 1;
};
Table read_table(hid_t group, const char* name);
/// An integer dataset (ParticleIDs) read as 64-bit integers (no rounding through double).
std::vector<std::int64_t> read_ints(hid_t group, const char* name);

}  // namespace sph::h5
