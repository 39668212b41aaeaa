// VTK XML (.vtu, .pvd) writers; see vtu.hpp for the format written.
#include "io/vtu.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <set>
#include <stdexcept>
#include <system_error>

#ifdef DRAWBEND_HAVE_ZLIB
#include <zlib.h>
#endif

#include "core/csv.hpp"

namespace drawbend::io {
namespace {

constexpr int kVtkHexahedron = 12;

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw std::invalid_argument(path + ": " + what);
}

/// Escape the five XML special characters for use in attribute values.
std::string xml_escape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

/// Shortest text that reads back as the same double.
void append_double(std::string& out, double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

void append_int(std::string& out, long long v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

std::string double_text(double v) {
  std::string s;
  append_double(s, v);
  return s;
}

void check_finite(const std::string& path, const std::string& what, const double* v, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(v[i]))
      fail(path, what + " value " + std::to_string(i) + " is not finite (" + double_text(v[i]) + ")");
}

void check_mesh(const std::string& path, const VtuMesh& m) {
  if (m.num_points > 0 && (m.x == nullptr || m.y == nullptr || m.z == nullptr))
    fail(path, "mesh has " + std::to_string(m.num_points) + " points but a null coordinate pointer (x, y or z)");
  if (m.num_cells > 0 && m.hex == nullptr)
    fail(path, "mesh has " + std::to_string(m.num_cells) + " cells but a null connectivity pointer (hex)");
  check_finite(path, "coordinate x", m.x, m.num_points);
  check_finite(path, "coordinate y", m.y, m.num_points);
  check_finite(path, "coordinate z", m.z, m.num_points);
  for (std::size_t c = 0; c < m.num_cells; ++c)
    for (int k = 0; k < m.nodes_per_cell; ++k) {
      const int n = m.hex[static_cast<std::size_t>(m.nodes_per_cell) * c + k];
      if (n < 0 || static_cast<std::size_t>(n) >= m.num_points)
        fail(path, "cell " + std::to_string(c) + " node " + std::to_string(k) + " has index " + std::to_string(n) +
                       ", outside [0, " + std::to_string(m.num_points) + ")");
    }
}

void check_fields(const std::string& path, const char* section, const std::vector<VtuField>& fields,
                  std::size_t count) {
  std::set<std::string> seen;
  for (const VtuField& f : fields) {
    const std::string where = std::string(section) + " field '" + f.name + "'";
    if (f.name.empty()) fail(path, std::string(section) + " field with an empty name");
    if (!seen.insert(f.name).second) fail(path, "duplicate " + where);
    if (f.components != 1 && f.components != 3 && f.components != 6)
      fail(path, where + " has " + std::to_string(f.components) +
                     " components; expected 1 (scalar), 3 (vector) or 6 (symmetric tensor)");
    if (count > 0 && f.data == nullptr)
      fail(path, where + " has null data for " + std::to_string(count) + " entries");
    check_finite(path, where, f.data, count * static_cast<std::size_t>(f.components));
  }
}

/// One array to write: its VTK type, name, components and values as bytes
/// (binary) or as the source to print (ascii).
struct Array {
  const char* type;  ///< "Float64", "Int64" or "UInt8"
  std::string name;
  int components;
  std::string bytes;  ///< the values in the machine's byte order
  int per_line = 0;   ///< ascii: values per line (0: components)
};

template <class T>
void put(std::string& bytes, T v) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  bytes.append(b, sizeof(T));
}

Array doubles(const std::string& name, int components, const double* v, std::size_t n) {
  Array a{"Float64", name, components, {}};
  a.bytes.resize(n * sizeof(double));
  if (n > 0) std::memcpy(a.bytes.data(), v, n * sizeof(double));
  return a;
}

/// The values of an array back as text, one tuple per line.
void append_text(std::string& out, const Array& a) {
  const std::size_t size = a.type[0] == 'F' ? 8 : (a.type[0] == 'I' ? 8 : 1);
  const std::size_t n = a.bytes.size() / size, line = a.per_line > 0 ? a.per_line : a.components;
  for (std::size_t i = 0; i < n; ++i) {
    if (i % line == 0) out += "          ";
    const char* p = a.bytes.data() + i * size;
    if (a.type[0] == 'F') {
      double v;
      std::memcpy(&v, p, 8);
      append_double(out, v);
    } else if (a.type[0] == 'I') {
      std::int64_t v;
      std::memcpy(&v, p, 8);
      append_int(out, v);
    } else {
      append_int(out, static_cast<unsigned char>(*p));
    }
    out += (i + 1) % line == 0 ? '\n' : ' ';
  }
}

constexpr std::size_t kBlock = 1 << 16;  // zlib: uncompressed bytes per block

/// The appended record of one array: VTK's header and the (compressed) data.
std::string appended_record(const std::string& data, VtkFormat format) {
  std::string rec;
#ifdef DRAWBEND_HAVE_ZLIB
  if (format == VtkFormat::zlib) {
    const std::size_t nb = (data.size() + kBlock - 1) / kBlock;
    std::vector<std::uint64_t> header{nb, kBlock, data.size() % kBlock};
    std::string blocks;
    for (std::size_t b = 0; b < nb; ++b) {
      const std::size_t len = std::min(kBlock, data.size() - b * kBlock);
      uLongf clen = compressBound(len);
      std::string c(clen, '\0');
      if (compress2(reinterpret_cast<Bytef*>(c.data()), &clen, reinterpret_cast<const Bytef*>(data.data() + b * kBlock),
                    len, 6) != Z_OK)
        throw std::runtime_error("zlib compress2 failed");
      header.push_back(clen);
      blocks.append(c.data(), clen);
    }
    for (std::uint64_t h : header) put(rec, h);
    return rec + blocks;
  }
#else
  (void)format;
#endif
  put(rec, static_cast<std::uint64_t>(data.size()));
  return rec + data;
}

bool little_endian() {
  const std::uint16_t one = 1;
  unsigned char b;
  std::memcpy(&b, &one, 1);
  return b == 1;
}

#ifdef DRAWBEND_HAVE_ZLIB
constexpr bool kHaveZlib = true;
#else
constexpr bool kHaveZlib = false;
#endif

/// Writes the arrays' DataArray elements, as text or as offsets into `appended`.
class Emitter {
 public:
  Emitter(std::string& out, VtkFormat f) : out_(out), format_(f) {}
  void array(const Array& a, const std::string& indent = "        ") {
    out_ += indent + "<DataArray type=\"";
    out_ += a.type;
    out_ += "\" Name=\"" + xml_escape(a.name) + "\" NumberOfComponents=\"" + std::to_string(a.components) + "\"";
    if (a.components == 6) {  // label the symmetric-tensor components for ParaView
      static const char* const names[6] = {"XX", "YY", "ZZ", "XY", "YZ", "XZ"};
      for (int c = 0; c < 6; ++c) out_ += " ComponentName" + std::to_string(c) + "=\"" + names[c] + "\"";
    }
    if (format_ == VtkFormat::ascii) {
      out_ += " format=\"ascii\">\n";
      append_text(out_, a);
      out_ += indent + "</DataArray>\n";
    } else {
      out_ += " format=\"appended\" offset=\"" + std::to_string(appended_.size()) + "\"/>\n";
      appended_ += appended_record(a.bytes, format_);
    }
  }
  const std::string& appended() const { return appended_; }

 private:
  std::string& out_;
  VtkFormat format_;
  std::string appended_;
};

void append_fields(Emitter& em, std::string& out, const char* section, const std::vector<VtuField>& fields,
                   std::size_t count) {
  if (fields.empty()) return;
  out += "      <";
  out += section;
  out += ">\n";
  for (const VtuField& f : fields) em.array(doubles(f.name, f.components, f.data, count * f.components));
  out += "      </";
  out += section;
  out += ">\n";
}

}  // namespace

namespace {

/// A .vtu (UnstructuredGrid) or, with `poly`, a .vtp (PolyData of polygons).
void write_grid(const std::string& path, const VtuMesh& mesh, const std::vector<VtuField>& point_fields,
                const std::vector<VtuField>& cell_fields, double time, VtkFormat format, bool poly) {
  // Validate everything first so that a bad call writes nothing.
  if (!std::isfinite(time)) fail(path, "time is not finite (" + double_text(time) + ")");
  if (!((mesh.nodes_per_cell == 8 && mesh.cell_type == kVtkHexahedron) || (mesh.nodes_per_cell == 4 && mesh.cell_type == 9)))
    fail(path, "cell type " + std::to_string(mesh.cell_type) + " with " + std::to_string(mesh.nodes_per_cell) +
                   " nodes; expected hexahedra (12, 8 nodes) or quadrilaterals (9, 4 nodes)");
  check_mesh(path, mesh);
  check_fields(path, "PointData", point_fields, mesh.num_points);
  check_fields(path, "CellData", cell_fields, mesh.num_cells);
  if (format == VtkFormat::zlib && !kHaveZlib) format = VtkFormat::raw;

  const int npc = mesh.nodes_per_cell;
  std::string out;
  out += "<?xml version=\"1.0\"?>\n";
  const std::string grid = poly ? "PolyData" : "UnstructuredGrid";
  out += "<VTKFile type=\"" + grid + "\" version=\"1.0\" byte_order=\"";
  out += format == VtkFormat::ascii || little_endian() ? "LittleEndian" : "BigEndian";
  out += "\" header_type=\"UInt64\"";
  if (format == VtkFormat::zlib) out += " compressor=\"vtkZLibDataCompressor\"";
  out += ">\n";
  out += "  <" + grid + ">\n";
  out += "    <FieldData>\n";
  out += "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\">";
  append_double(out, time);
  out += "</DataArray>\n";
  out += "    </FieldData>\n";
  out += "    <Piece NumberOfPoints=\"" + std::to_string(mesh.num_points) + "\" " +
         (poly ? "NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\""
               : "NumberOfCells=\"") +
         std::to_string(mesh.num_cells) + "\">\n";
  Emitter em(out, format);
  append_fields(em, out, "PointData", point_fields, mesh.num_points);
  append_fields(em, out, "CellData", cell_fields, mesh.num_cells);

  out += "      <Points>\n";
  {
    Array p{"Float64", "Points", 3, {}};
    p.bytes.reserve(24 * mesh.num_points);
    for (std::size_t i = 0; i < mesh.num_points; ++i) put(p.bytes, mesh.x[i]), put(p.bytes, mesh.y[i]), put(p.bytes, mesh.z[i]);
    em.array(p);
  }
  out += "      </Points>\n";

  out += poly ? "      <Polys>\n" : "      <Cells>\n";
  Array conn{"Int64", "connectivity", 1, {}, npc}, offs{"Int64", "offsets", 1, {}}, types{"UInt8", "types", 1, {}};
  for (std::size_t c = 0; c < mesh.num_cells; ++c) {
    for (int k = 0; k < npc; ++k) put(conn.bytes, static_cast<std::int64_t>(mesh.hex[npc * c + k]));
    put(offs.bytes, static_cast<std::int64_t>(npc * (c + 1)));
    put(types.bytes, static_cast<unsigned char>(mesh.cell_type));
  }
  em.array(conn);
  em.array(offs);
  if (!poly) em.array(types);
  out += poly ? "      </Polys>\n" : "      </Cells>\n";

  out += "    </Piece>\n";
  out += "  </" + grid + ">\n";
  if (format != VtkFormat::ascii) {
    out += "  <AppendedData encoding=\"raw\">\n   _";
    out += em.appended();
    out += "\n  </AppendedData>\n";
  }
  out += "</VTKFile>\n";
  write_file_atomic(path, out);
}

}  // namespace

void write_vtu(const std::string& path, const VtuMesh& mesh, const std::vector<VtuField>& point_fields,
               const std::vector<VtuField>& cell_fields, double time, VtkFormat format) {
  write_grid(path, mesh, point_fields, cell_fields, time, format, false);
}

void write_vtp(const std::string& path, const VtuMesh& mesh, const std::vector<VtuField>& point_fields,
               const std::vector<VtuField>& cell_fields, double time, VtkFormat format) {
  if (mesh.nodes_per_cell != 4 || mesh.cell_type != 9)
    fail(path, "a .vtp takes quadrilaterals (nodes_per_cell 4, cell_type 9)");
  write_grid(path, mesh, point_fields, cell_fields, time, format, true);
}

void write_pvd(const std::string& path, const std::vector<std::pair<double, std::string>>& steps) {
  std::vector<PvdEntry> entries;
  for (const auto& [t, file] : steps) entries.push_back({t, 0, "", file});
  write_pvd(path, entries);
}

void write_pvd(const std::string& path, const std::vector<PvdEntry>& steps) {
  for (std::size_t i = 0; i < steps.size(); ++i) {
    if (!std::isfinite(steps[i].time))
      fail(path, "step " + std::to_string(i) + " has a time that is not finite (" + double_text(steps[i].time) + ")");
    if (steps[i].file.empty()) fail(path, "step " + std::to_string(i) + " has an empty file name");
  }
  std::string out;
  out += "<?xml version=\"1.0\"?>\n";
  out += "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n";
  out += "  <Collection>\n";
  for (const PvdEntry& e : steps) {
    out += "    <DataSet timestep=\"";
    append_double(out, e.time);
    out += "\" group=\"\" part=\"" + std::to_string(e.part) + "\"";
    if (!e.name.empty()) out += " name=\"" + xml_escape(e.name) + "\"";
    out += " file=\"" + xml_escape(e.file) + "\"/>\n";
  }
  out += "  </Collection>\n";
  out += "</VTKFile>\n";
  write_file_atomic(path, out);
}

}  // namespace drawbend::io

namespace drawbend::io {
namespace {

std::string attribute(const std::string& tag, const std::string& key) {
  const std::size_t at = tag.find(" " + key + "=\"");
  if (at == std::string::npos) return "";
  const std::size_t from = at + key.size() + 3, to = tag.find('"', from);
  return tag.substr(from, to - from);
}

template <class T>
T get(const std::string& text, std::size_t at, const std::string& path, const std::string& name) {
  if (at + sizeof(T) > text.size()) throw InputError(path + ": DataArray '" + name + "': appended data cut short");
  T v;
  std::memcpy(&v, text.data() + at, sizeof(T));
  return v;
}

/// The bytes of an appended array at `at` (after the '_'), decompressed.
std::string appended_bytes(const std::string& text, std::size_t at, bool zlib, const std::string& path,
                           const std::string& name) {
  if (!zlib) {
    const auto n = get<std::uint64_t>(text, at, path, name);
    if (at + 8 + n > text.size()) throw InputError(path + ": DataArray '" + name + "': appended data cut short");
    return text.substr(at + 8, n);
  }
#ifdef DRAWBEND_HAVE_ZLIB
  const auto nb = get<std::uint64_t>(text, at, path, name), bs = get<std::uint64_t>(text, at + 8, path, name),
             last = get<std::uint64_t>(text, at + 16, path, name);
  std::size_t p = at + 24 + 8 * nb;
  std::string out;
  for (std::uint64_t b = 0; b < nb; ++b) {
    const auto clen = get<std::uint64_t>(text, at + 24 + 8 * b, path, name);
    uLongf len = b + 1 == nb && last > 0 ? last : bs;
    std::string block(len, '\0');
    if (p + clen > text.size() ||
        uncompress(reinterpret_cast<Bytef*>(block.data()), &len, reinterpret_cast<const Bytef*>(text.data() + p), clen) != Z_OK)
      throw InputError(path + ": DataArray '" + name + "': zlib block " + std::to_string(b) + " does not decompress");
    out.append(block.data(), len);
    p += clen;
  }
  return out;
#else
  throw InputError(path + ": DataArray '" + name + "' is zlib-compressed, and this drawbend was built without zlib");
#endif
}

}  // namespace

std::vector<double> read_vtu_array(const std::string& path, const std::string& text, const std::string& name) {
  const std::size_t data_start = text.find("<AppendedData");
  const std::string head = text.substr(0, data_start);
  const std::size_t at = head.find("Name=\"" + xml_escape(name) + "\"");
  if (at == std::string::npos) throw InputError(path + ": no DataArray '" + name + "'");
  const std::size_t open = head.rfind("<DataArray", at), close = head.find('>', at);
  if (open == std::string::npos || close == std::string::npos) throw InputError(path + ": DataArray '" + name + "' is not closed");
  const std::string tag = head.substr(open, close - open);
  const std::string type = attribute(tag, "type");
  std::vector<double> v;
  if (attribute(tag, "format") != "appended") {
    const std::size_t to = head.find("</DataArray>", close);
    if (to == std::string::npos) throw InputError(path + ": DataArray '" + name + "' is not closed");
    const char* p = text.data() + close + 1;
    const char* end = text.data() + to;
    while (p < end) {
      while (p < end && std::isspace(static_cast<unsigned char>(*p))) ++p;
      if (p == end) break;
      double d = 0;
      const auto r = std::from_chars(p, end, d);
      if (r.ec != std::errc()) throw InputError(path + ": DataArray '" + name + "': not a number");
      v.push_back(d);
      p = r.ptr;
    }
    return v;
  }
  const std::size_t underscore = data_start == std::string::npos ? std::string::npos : text.find('_', data_start);
  if (underscore == std::string::npos) throw InputError(path + ": DataArray '" + name + "' is appended, but no AppendedData");
  const bool zlib = head.find("compressor=\"vtkZLibDataCompressor\"") != std::string::npos;
  const std::string bytes =
      appended_bytes(text, underscore + 1 + std::stoull(attribute(tag, "offset")), zlib, path, name);
  const std::size_t size = type == "UInt8" ? 1 : 8;
  for (std::size_t i = 0; i + size <= bytes.size(); i += size) {
    if (type == "Float64") v.push_back(get<double>(bytes, i, path, name));
    else if (type == "Int64") v.push_back(static_cast<double>(get<std::int64_t>(bytes, i, path, name)));
    else if (type == "UInt8") v.push_back(static_cast<unsigned char>(bytes[i]));
    else throw InputError(path + ": DataArray '" + name + "' of type " + type + " (this reader knows Float64, Int64, UInt8)");
  }
  return v;
}

void write_vtm(const std::string& path, const std::vector<std::pair<std::string, std::string>>& blocks) {
  for (const auto& [name, file] : blocks)
    if (name.empty() || file.empty()) fail(path, "a block with an empty name or file");
  std::string out;
  out += "<?xml version=\"1.0\"?>\n";
  out += "<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n";
  out += "  <vtkMultiBlockDataSet>\n";
  for (std::size_t i = 0; i < blocks.size(); ++i)
    out += "    <DataSet index=\"" + std::to_string(i) + "\" name=\"" + xml_escape(blocks[i].first) + "\" file=\"" +
           xml_escape(blocks[i].second) + "\"/>\n";
  out += "  </vtkMultiBlockDataSet>\n";
  out += "</VTKFile>\n";
  write_file_atomic(path, out);
}

}  // namespace drawbend::io
