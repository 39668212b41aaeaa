// VTK XML (.vtu, .pvd) writers; see vtu.hpp for the format written.
#include "io/vtu.hpp"

#include <charconv>
#include <cmath>
#include <set>
#include <stdexcept>
#include <system_error>

#include "core/csv.hpp"

namespace drawbend::io {
namespace {

constexpr int kHexNodes = 8;
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
    for (int k = 0; k < kHexNodes; ++k) {
      const int n = m.hex[kHexNodes * c + k];
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

void open_array(std::string& out, const char* type, const std::string& name, int components) {
  out += "        <DataArray type=\"";
  out += type;
  out += "\" Name=\"" + xml_escape(name) + "\" NumberOfComponents=\"" + std::to_string(components) + "\"";
  if (components == 6) {  // label the symmetric-tensor components for ParaView
    static const char* const names[6] = {"XX", "YY", "ZZ", "XY", "YZ", "XZ"};
    for (int c = 0; c < 6; ++c) out += " ComponentName" + std::to_string(c) + "=\"" + names[c] + "\"";
  }
  out += " format=\"ascii\">\n";
}

void close_array(std::string& out) { out += "        </DataArray>\n"; }

/// Values of a field, one tuple per line.
void append_tuples(std::string& out, const double* v, std::size_t count, int components) {
  for (std::size_t i = 0; i < count; ++i) {
    out += "          ";
    for (int c = 0; c < components; ++c) {
      if (c > 0) out += ' ';
      append_double(out, v[i * components + c]);
    }
    out += '\n';
  }
}

void append_fields(std::string& out, const char* section, const std::vector<VtuField>& fields,
                   std::size_t count) {
  if (fields.empty()) return;
  out += "      <";
  out += section;
  out += ">\n";
  for (const VtuField& f : fields) {
    open_array(out, "Float64", f.name, f.components);
    append_tuples(out, f.data, count, f.components);
    close_array(out);
  }
  out += "      </";
  out += section;
  out += ">\n";
}

}  // namespace

void write_vtu(const std::string& path, const VtuMesh& mesh, const std::vector<VtuField>& point_fields,
               const std::vector<VtuField>& cell_fields, double time) {
  // Validate everything first so that a bad call writes nothing.
  if (!std::isfinite(time)) fail(path, "time is not finite (" + double_text(time) + ")");
  check_mesh(path, mesh);
  check_fields(path, "PointData", point_fields, mesh.num_points);
  check_fields(path, "CellData", cell_fields, mesh.num_cells);

  std::size_t values = 3 * mesh.num_points + 10 * mesh.num_cells;
  for (const auto& f : point_fields) values += f.components * mesh.num_points;
  for (const auto& f : cell_fields) values += f.components * mesh.num_cells;
  std::string out;
  out.reserve(512 + 24 * values);

  out += "<?xml version=\"1.0\"?>\n";
  out += "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n";
  out += "  <UnstructuredGrid>\n";
  out += "    <FieldData>\n";
  out += "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\">";
  append_double(out, time);
  out += "</DataArray>\n";
  out += "    </FieldData>\n";
  out += "    <Piece NumberOfPoints=\"" + std::to_string(mesh.num_points) + "\" NumberOfCells=\"" +
         std::to_string(mesh.num_cells) + "\">\n";

  append_fields(out, "PointData", point_fields, mesh.num_points);
  append_fields(out, "CellData", cell_fields, mesh.num_cells);

  out += "      <Points>\n";
  open_array(out, "Float64", "Points", 3);
  for (std::size_t i = 0; i < mesh.num_points; ++i) {
    out += "          ";
    append_double(out, mesh.x[i]);
    out += ' ';
    append_double(out, mesh.y[i]);
    out += ' ';
    append_double(out, mesh.z[i]);
    out += '\n';
  }
  close_array(out);
  out += "      </Points>\n";

  out += "      <Cells>\n";
  open_array(out, "Int64", "connectivity", 1);
  for (std::size_t c = 0; c < mesh.num_cells; ++c) {
    out += "          ";
    for (int k = 0; k < kHexNodes; ++k) {
      if (k > 0) out += ' ';
      append_int(out, mesh.hex[kHexNodes * c + k]);
    }
    out += '\n';
  }
  close_array(out);
  open_array(out, "Int64", "offsets", 1);
  for (std::size_t c = 0; c < mesh.num_cells; ++c) {
    out += "          ";
    append_int(out, static_cast<long long>(kHexNodes * (c + 1)));
    out += '\n';
  }
  close_array(out);
  open_array(out, "UInt8", "types", 1);
  for (std::size_t c = 0; c < mesh.num_cells; ++c) {
    out += "          ";
    append_int(out, kVtkHexahedron);
    out += '\n';
  }
  close_array(out);
  out += "      </Cells>\n";

  out += "    </Piece>\n";
  out += "  </UnstructuredGrid>\n";
  out += "</VTKFile>\n";
  write_file_atomic(path, out);
}

void write_pvd(const std::string& path, const std::vector<std::pair<double, std::string>>& steps) {
  for (std::size_t i = 0; i < steps.size(); ++i) {
    if (!std::isfinite(steps[i].first))
      fail(path, "step " + std::to_string(i) + " has a time that is not finite (" + double_text(steps[i].first) + ")");
    if (steps[i].second.empty()) fail(path, "step " + std::to_string(i) + " has an empty file name");
  }
  std::string out;
  out += "<?xml version=\"1.0\"?>\n";
  out += "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n";
  out += "  <Collection>\n";
  for (const auto& [t, file] : steps) {
    out += "    <DataSet timestep=\"";
    append_double(out, t);
    out += "\" group=\"\" part=\"0\" file=\"" + xml_escape(file) + "\"/>\n";
  }
  out += "  </Collection>\n";
  out += "</VTKFile>\n";
  write_file_atomic(path, out);
}

}  // namespace drawbend::io
