// VTK XML UnstructuredGrid with raw appended data (VTK file format documentation, "XML File Formats":
// each appended block is a UInt64 byte count followed by the bytes; offsets count from the "_").
#include "sph/vtu_writer.h"

#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstring>

namespace sph {
namespace {

constexpr const char* byte_order() { return std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian"; }

std::string exact(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

/// XML text of the header, and the appended blocks with their offsets.
class AppendedData {
 public:
  /// Adds a block of n values of type T; returns the XML attribute text for its DataArray.
  template <class T>
  std::string add(const std::vector<T>& values) {
    const std::uint64_t bytes = values.size() * sizeof(T);
    const std::size_t offset = blob_.size();
    blob_.append(reinterpret_cast<const char*>(&bytes), sizeof bytes);
    blob_.append(reinterpret_cast<const char*>(values.data()), bytes);
    return "format=\"appended\" offset=\"" + std::to_string(offset) + "\"";
  }
  const std::string& blob() const { return blob_; }

 private:
  std::string blob_;
};

std::string data_array(const char* type, const std::string& name, int components, const std::string& where) {
  std::string s = std::string("        <DataArray type=\"") + type + "\"";
  if (!name.empty()) s += " Name=\"" + name + "\"";
  if (components > 1) s += " NumberOfComponents=\"" + std::to_string(components) + "\"";
  return s + " " + where + "/>\n";
}

}  // namespace

std::string vtu_file(const World& world) {
  const Particles& p = world.particles();
  const std::vector<std::uint32_t>& order = world.by_id();
  const std::size_t n = order.size();
  AppendedData data;
  std::string point_data;

  std::vector<double> vec(3 * n);
  for (std::size_t r = 0; r < n; ++r)
    for (int k = 0; k < 3; ++k) vec[3 * r + k] = p.v[k][order[r]];
  point_data += data_array("Float64", "velocity", 3, data.add(vec));
  std::vector<std::int64_t> ids(n);
  std::vector<std::uint8_t> kinds(n);
  for (std::size_t r = 0; r < n; ++r) {
    ids[r] = p.id[order[r]];
    kinds[r] = p.kind[order[r]];
  }
  point_data += data_array("Int64", "id", 1, data.add(ids));
  point_data += data_array("UInt8", "kind", 1, data.add(kinds));
  std::vector<double> scalar(n);
  p.fields().for_each([&](Field f) {
    const std::vector<double>& src = p[f];
    for (std::size_t r = 0; r < n; ++r) scalar[r] = src[order[r]];
    point_data += data_array("Float64", std::string(info(f).key), 1, data.add(scalar));
  });

  for (std::size_t r = 0; r < n; ++r)
    for (int k = 0; k < 3; ++k) vec[3 * r + k] = p.x[k][order[r]];
  const std::string points = data_array("Float64", "Points", 3, data.add(vec));
  std::vector<std::int64_t> connectivity(n), offsets(n);
  for (std::size_t r = 0; r < n; ++r) {
    connectivity[r] = static_cast<std::int64_t>(r);
    offsets[r] = static_cast<std::int64_t>(r + 1);
  }
  const std::vector<std::uint8_t> types(n, 1);  // VTK_VERTEX
  std::string cells = data_array("Int64", "connectivity", 1, data.add(connectivity));
  cells += data_array("Int64", "offsets", 1, data.add(offsets));
  cells += data_array("UInt8", "types", 1, data.add(types));

  const std::string count = std::to_string(n);
  std::string out = std::string("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"") +
                    byte_order() + "\" header_type=\"UInt64\">\n  <UnstructuredGrid>\n    <FieldData>\n" +
                    "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\">" +
                    exact(world.time()) + "</DataArray>\n    </FieldData>\n" + "    <Piece NumberOfPoints=\"" + count +
                    "\" NumberOfCells=\"" + count + "\">\n      <PointData Vectors=\"velocity\"" +
                    (p.has(Field::Density) ? " Scalars=\"rho\"" : "") + ">\n" + point_data + "      </PointData>\n" +
                    "      <Points>\n" + points + "      </Points>\n      <Cells>\n" + cells +
                    "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n  <AppendedData encoding=\"raw\">\n   _";
  out += data.blob();
  out += "\n  </AppendedData>\n</VTKFile>\n";
  return out;
}

std::string pvd_file(const std::vector<PvdEntry>& entries) {
  std::string out = std::string("<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"") +
                    byte_order() + "\">\n  <Collection>\n";
  for (const PvdEntry& e : entries)
    out += "    <DataSet timestep=\"" + exact(e.t) + "\" group=\"\" part=\"0\" file=\"" + e.file + "\"/>\n";
  return out + "  </Collection>\n</VTKFile>\n";
}

}  // namespace sph
