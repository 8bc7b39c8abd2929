#include "io/hdf5_util.h"

#include <stdexcept>

namespace sph::h5 {
namespace {

[[noreturn]] void fail(const std::string& what) { throw std::runtime_error("HDF5: " + what); }

hid_t check(hid_t id, const std::string& what) {
  if (id < 0) fail(what);
  return id;
}

void check_status(herr_t status, const std::string& what) {
  if (status < 0) fail(what);
}

Handle dataspace(const std::vector<hsize_t>& dims) {
  if (dims.empty()) return {check(H5Screate(H5S_SCALAR), "scalar dataspace"), H5Sclose};
  return {check(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), "dataspace"), H5Sclose};
}

void attr(hid_t obj, const char* name, hid_t file_type, hid_t mem_type, const std::vector<hsize_t>& dims,
          const void* data) {
  Handle space = dataspace(dims);
  Handle a{check(H5Acreate2(obj, name, file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT), std::string("attribute ") + name),
           H5Aclose};
  check_status(H5Awrite(a.get(), mem_type, data), std::string("writing attribute ") + name);
}

void dataset(hid_t group, const char* name, hid_t file_type, hid_t mem_type, const std::vector<hsize_t>& dims,
             const void* data) {
  Handle space = dataspace(dims);
  Handle dcpl{check(H5Pcreate(H5P_DATASET_CREATE), "dataset creation list"), H5Pclose};
  check_status(H5Pset_obj_track_times(dcpl.get(), false), "no modification times");  // same run, same bytes
  Handle d{check(H5Dcreate2(group, name, file_type, space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT),
                 std::string("dataset ") + name),
           H5Dclose};
  check_status(H5Dwrite(d.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), std::string("writing ") + name);
}

/// Dimensions of a dataset or attribute's dataspace.
std::vector<hsize_t> extent(hid_t space) {
  const int rank = H5Sget_simple_extent_ndims(space);
  if (rank < 0) fail("dataspace rank");
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  if (rank > 0) H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  return dims;
}

}  // namespace

Handle& Handle::operator=(Handle&& o) noexcept {
  if (this != &o) {
    reset();
    id_ = o.id_;
    close_ = o.close_;
    o.id_ = H5I_INVALID_HID;
  }
  return *this;
}

void Handle::reset() {
  if (id_ >= 0 && close_) close_(id_);
  id_ = H5I_INVALID_HID;
}

void quiet() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

Handle create_memory_file() {
  quiet();
  Handle fapl{check(H5Pcreate(H5P_FILE_ACCESS), "file access list"), H5Pclose};
  check_status(H5Pset_fapl_core(fapl.get(), 1 << 20, 0), "core driver");
  return {check(H5Fcreate("sph-memory-image.hdf5", H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()), "in-memory file"),
          H5Fclose};
}

std::string file_bytes(hid_t file) {
  check_status(H5Fflush(file, H5F_SCOPE_GLOBAL), "flush");
  const ssize_t size = H5Fget_file_image(file, nullptr, 0);
  if (size < 0) fail("file image size");
  std::string bytes(static_cast<std::size_t>(size), '\0');
  if (H5Fget_file_image(file, bytes.data(), bytes.size()) != size) fail("file image");
  return bytes;
}

Handle open_file(const std::string& path) {
  quiet();
  if (H5Fis_hdf5(path.c_str()) <= 0) return {};
  return {H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose};
}

Handle create_group(hid_t loc, const char* name) {
  Handle gcpl{check(H5Pcreate(H5P_GROUP_CREATE), "group creation list"), H5Pclose};
  check_status(H5Pset_obj_track_times(gcpl.get(), false), "no modification times");  // same run, same bytes
  return {check(H5Gcreate2(loc, name, H5P_DEFAULT, gcpl.get(), H5P_DEFAULT), std::string("group ") + name), H5Gclose};
}

bool exists(hid_t loc, const char* path) {
  std::string partial;
  std::string p(path);
  std::size_t start = p.front() == '/' ? 1 : 0;
  for (;;) {  // every link along the path must exist (H5Lexists needs its parents)
    const std::size_t slash = p.find('/', start);
    partial = p.substr(0, slash);
    if (H5Lexists(loc, partial.c_str(), H5P_DEFAULT) <= 0) return false;
    if (slash == std::string::npos) return true;
    start = slash + 1;
  }
}

Handle open_group(hid_t loc, const char* path) {
  if (!exists(loc, path)) return {};
  return {H5Gopen2(loc, path, H5P_DEFAULT), H5Gclose};  // invalid when the path names a dataset
}

void write_attr(hid_t obj, const char* name, const std::vector<double>& values) {
  attr(obj, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {values.size()}, values.data());
}

void write_attr(hid_t obj, const char* name, double value) { attr(obj, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {}, &value); }

void write_attr_ints(hid_t obj, const char* name, const std::vector<long long>& values, hid_t file_type) {
  attr(obj, name, file_type, H5T_NATIVE_LLONG, {values.size()}, values.data());
}

void write_attr_int(hid_t obj, const char* name, long long value) {
  attr(obj, name, H5T_STD_I32LE, H5T_NATIVE_LLONG, {}, &value);
}

void write_attr(hid_t obj, const char* name, const std::string& text) {
  Handle type{check(H5Tcopy(H5T_C_S1), "string type"), H5Tclose};
  check_status(H5Tset_size(type.get(), text.empty() ? 1 : text.size()), "string size");
  check_status(H5Tset_strpad(type.get(), H5T_STR_NULLPAD), "string padding");
  const std::string data = text.empty() ? std::string(1, '\0') : text;
  attr(obj, name, type.get(), type.get(), {}, data.data());
}

bool has_attr(hid_t obj, const char* name) { return H5Aexists(obj, name) > 0; }

std::vector<double> read_attr(hid_t obj, const char* name) {
  Handle a{check(H5Aopen(obj, name, H5P_DEFAULT), std::string("attribute ") + name), H5Aclose};
  Handle type{H5Aget_type(a.get()), H5Tclose};
  const H5T_class_t cls = H5Tget_class(type.get());
  if (cls != H5T_INTEGER && cls != H5T_FLOAT) fail(std::string("attribute ") + name + " is not numeric");
  Handle space{H5Aget_space(a.get()), H5Sclose};
  const hssize_t n = H5Sget_simple_extent_npoints(space.get());
  if (n < 0) fail(std::string("attribute ") + name + " extent");
  std::vector<double> values(static_cast<std::size_t>(n));
  if (n > 0) check_status(H5Aread(a.get(), H5T_NATIVE_DOUBLE, values.data()), std::string("reading ") + name);
  return values;
}

std::string read_attr_string(hid_t obj, const char* name) {
  Handle a{check(H5Aopen(obj, name, H5P_DEFAULT), std::string("attribute ") + name), H5Aclose};
  Handle type{H5Aget_type(a.get()), H5Tclose};
  if (H5Tget_class(type.get()) != H5T_STRING) fail(std::string("attribute ") + name + " is not a string");
  if (H5Tis_variable_str(type.get()) > 0) {
    char* text = nullptr;
    Handle mem{H5Tcopy(H5T_C_S1), H5Tclose};
    H5Tset_size(mem.get(), H5T_VARIABLE);
    check_status(H5Aread(a.get(), mem.get(), &text), std::string("reading ") + name);
    std::string out = text ? text : "";
    H5free_memory(text);
    return out;
  }
  const std::size_t size = H5Tget_size(type.get());
  std::string out(size, '\0');
  check_status(H5Aread(a.get(), type.get(), out.data()), std::string("reading ") + name);
  out.resize(out.find('\0') == std::string::npos ? out.size() : out.find('\0'));
  return out;
}

void write_dataset(hid_t group, const char* name, const std::vector<double>& values, std::size_t cols) {
  std::vector<hsize_t> dims{values.size() / cols};
  if (cols > 1) dims.push_back(cols);
  dataset(group, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, dims, values.data());
}

void write_dataset(hid_t group, const char* name, const std::vector<std::uint64_t>& values) {
  dataset(group, name, H5T_STD_U64LE, H5T_NATIVE_UINT64, {values.size()}, values.data());
}

void write_dataset(hid_t group, const char* name, const std::vector<std::uint8_t>& values) {
  dataset(group, name, H5T_STD_U8LE, H5T_NATIVE_UINT8, {values.size()}, values.data());
}

Table read_table(hid_t group, const char* name) {
  Handle d{check(H5Dopen2(group, name, H5P_DEFAULT), std::string("dataset ") + name), H5Dclose};
  Handle type{H5Dget_type(d.get()), H5Tclose};
  const H5T_class_t cls = H5Tget_class(type.get());
  if (cls != H5T_INTEGER && cls != H5T_FLOAT) fail(std::string("dataset ") + name + " is not numeric");
  Handle space{H5Dget_space(d.get()), H5Sclose};
  const std::vector<hsize_t> dims = extent(space.get());
  if (dims.empty() || dims.size() > 2) fail(std::string("dataset ") + name + " must have one or two dimensions");
  Table t;
  t.rows = dims[0];
  t.cols = dims.size() == 2 ? dims[1] : 1;
  t.values.resize(t.rows * t.cols);
  if (!t.values.empty())
    check_status(H5Dread(d.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, t.values.data()),
                 std::string("reading ") + name);
  return t;
}

std::vector<std::int64_t> read_ints(hid_t group, const char* name) {
  Handle d{check(H5Dopen2(group, name, H5P_DEFAULT), std::string("dataset ") + name), H5Dclose};
  Handle space{H5Dget_space(d.get()), H5Sclose};
  const std::vector<hsize_t> dims = extent(space.get());
  if (dims.size() != 1) fail(std::string("dataset ") + name + " must have one dimension");
  std::vector<std::int64_t> v(dims[0]);
  if (!v.empty())
    check_status(H5Dread(d.get(), H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()),
                 std::string("reading ") + name);
  return v;
}

}  // namespace sph::h5
