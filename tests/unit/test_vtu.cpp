// VTK XML writers (io/vtu.hpp), checked without external tools.
// Mesh: a 2 x 1 x 1 block of two unit hexahedra, 12 points, node n = i + 3j + 6k
// at (x, y, z) = (0.1 + 1.5 i, 0.2 + j, 0.3 + k), for i = 0..2 and j, k = 0..1.
// Expected answers:
//  - the .vtu is well-formed XML (checked by a small parser with tag balance below);
//  - Piece NumberOfPoints="12" NumberOfCells="2";
//  - DataArray value counts: T 12*1 = 12, u 12*3 = 36, Points 12*3 = 36, stress 2*6 = 12;
//  - connectivity 0 1 4 3 6 7 10 9 / 1 2 5 4 7 8 11 10, offsets 8 16, types 12 12;
//  - every double reads back bit-identical (e.g. x = 0.1 + 1.5 i);
//  - FieldData TimeValue = 0.25; the .pvd lists (0, "s0.vtu"), (0.25, "out/s1 &amp; 2.vtu"),
//    in order, with the '&' of the file name XML-escaped;
//  - bad input throws std::invalid_argument and writes no file;
//  - binary (appended raw, appended zlib): read_vtu_array gives back every
//    value bit-identical (Points, T, u, stress, connectivity, offsets 8 16,
//    types 12 12, TimeValue 0.25), the zlib file names vtkZLibDataCompressor,
//    and a 20,000-value field (2.4 blocks of 64 KiB) crosses block bounds intact;
//  - a .vtp of 2 quadrilaterals lists NumberOfPolys 2, offsets 4 8;
//  - a .vtm lists its blocks in order with their names and files.
#define BOOST_TEST_MODULE vtu
#include <boost/test/unit_test.hpp>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "core/csv.hpp"
#include "io/vtu.hpp"

using namespace drawbend::io;
namespace fs = std::filesystem;
namespace tt = boost::test_tools;

#include "xml_check.hpp"

namespace {
using namespace xmlcheck;

std::string tmpdir() {
  auto d = fs::temp_directory_path() / "drawbend_vtu_test";
  fs::remove_all(d);
  fs::create_directories(d);
  return d.string();
}

// The 2-hex block of the header comment, with its fields.
struct Block {
  std::vector<double> x, y, z, T, u, stress;
  std::vector<int> hex{0, 1, 4, 3, 6, 7, 10, 9, 1, 2, 5, 4, 7, 8, 11, 10};
  Block() {
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 3; ++i) {
          const int n = i + 3 * j + 6 * k;
          x.push_back(0.1 + 1.5 * i), y.push_back(0.2 + j), z.push_back(0.3 + k);
          T.push_back(20.0 + n / 3.0);
          u.insert(u.end(), {1e-3 * n, -2e-3 * n, 1.0 / 3.0});
        }
    for (int c = 0; c < 2; ++c)
      for (int v = 0; v < 6; ++v) stress.push_back(100.0 * c + v + 0.5);  // XX YY ZZ XY YZ XZ
  }
  VtuMesh mesh() const { return {12, x.data(), y.data(), z.data(), 2, hex.data()}; }
};

}  // namespace

BOOST_AUTO_TEST_CASE(xml_checker_rejects_malformed_text) {
  BOOST_CHECK_NO_THROW(parse_xml("<?xml version=\"1.0\"?>\n<!-- c <x> --><a b='1' c=\"x y\"><b/> t </a>\n"));
  for (const char* bad : {"<a><b></a></b>", "<a><b>", "<a x=1/>", "<a x=\"1/>", "<a/><b/>", "<a x='1' x='2'/>",
                          "<a><!-- open </a>", "<a>t</a> t", ""})
    BOOST_CHECK_THROW(parse_xml(bad), std::runtime_error);
}

BOOST_AUTO_TEST_CASE(two_hex_mesh_with_fields) {
  const std::string dir = tmpdir();
  const Block b;
  write_vtu(dir + "/s1.vtu", b.mesh(), {{"T", 1, b.T.data()}, {"u", 3, b.u.data()}}, {{"stress", 6, b.stress.data()}},
            0.25);
  for (const auto& e : fs::directory_iterator(dir))  // no temporary file left behind
    BOOST_TEST(e.path().filename().string().rfind("s1.vtu.tmp", 0) == std::string::npos);
  const auto els = parse_xml(drawbend::read_file(dir + "/s1.vtu"));  // (a) well-formed

  const std::string grid = "VTKFile/UnstructuredGrid", piece = grid + "/Piece";
  BOOST_TEST(find(els, "VTKFile").attrs.at("type") == "UnstructuredGrid");
  const Element& p = find(els, piece);  // (b)
  BOOST_TEST(p.attrs.at("NumberOfPoints") == "12");
  BOOST_TEST(p.attrs.at("NumberOfCells") == "2");
  BOOST_TEST(find(els, grid + "/FieldData/DataArray", "TimeValue").text == "0.25");

  // (c) values per DataArray = count * components, with components and type as written.
  const std::vector<std::tuple<std::string, std::string, std::size_t, std::string>> arrays{
      {"T", "PointData", 12, "1"}, {"u", "PointData", 36, "3"}, {"stress", "CellData", 12, "6"},
      {"Points", "Points", 36, "3"}};
  for (const auto& [name, section, count, comps] : arrays) {
    const Element& a = find(els, piece + "/" + section + "/DataArray", name);
    BOOST_TEST_CONTEXT(name) {
      BOOST_TEST(tokens(a.text).size() == count);
      BOOST_TEST(a.attrs.at("NumberOfComponents") == comps);
      BOOST_TEST(a.attrs.at("type") == "Float64");
    }
  }

  const Element& st = find(els, piece + "/CellData/DataArray", "stress");
  BOOST_TEST(st.attrs.at("ComponentName0") == "XX");
  BOOST_TEST(st.attrs.at("ComponentName5") == "XZ");

  // Full precision: every value reads back bit-identical (exact ==, no tolerance).
  std::vector<double> xyz;
  for (std::size_t n = 0; n < 12; ++n) xyz.insert(xyz.end(), {b.x[n], b.y[n], b.z[n]});
  BOOST_TEST(numbers(find(els, piece + "/Points/DataArray")) == xyz, tt::per_element());
  BOOST_TEST(numbers(find(els, piece + "/PointData/DataArray", "T")) == b.T, tt::per_element());
  BOOST_TEST(numbers(find(els, piece + "/PointData/DataArray", "u")) == b.u, tt::per_element());
  BOOST_TEST(numbers(st) == b.stress, tt::per_element());

  // (d) cells.
  const std::vector<double> conn(b.hex.begin(), b.hex.end()), offsets{8, 16}, types{12, 12};
  BOOST_TEST(numbers(find(els, piece + "/Cells/DataArray", "connectivity")) == conn, tt::per_element());
  BOOST_TEST(numbers(find(els, piece + "/Cells/DataArray", "offsets")) == offsets, tt::per_element());
  BOOST_TEST(numbers(find(els, piece + "/Cells/DataArray", "types")) == types, tt::per_element());
}

BOOST_AUTO_TEST_CASE(pvd_lists_steps) {
  const std::string dir = tmpdir();
  write_pvd(dir + "/run.pvd", {{0.0, "s0.vtu"}, {0.25, "out/s1 & 2.vtu"}});
  const auto els = parse_xml(drawbend::read_file(dir + "/run.pvd"));  // well-formed
  BOOST_TEST(find(els, "VTKFile").attrs.at("type") == "Collection");
  std::vector<std::string> steps;  // "timestep|file" as written (attribute text, still escaped)
  for (const auto& e : els)
    if (e.path == "VTKFile/Collection/DataSet") steps.push_back(e.attrs.at("timestep") + "|" + e.attrs.at("file"));
  const std::vector<std::string> expected{"0|s0.vtu", "0.25|out/s1 &amp; 2.vtu"};
  BOOST_TEST(steps == expected, tt::per_element());
}

BOOST_AUTO_TEST_CASE(empty_mesh_is_valid) {
  const std::string dir = tmpdir();
  write_vtu(dir + "/e.vtu", VtuMesh{}, {{"T", 1, nullptr}}, {});
  const auto els = parse_xml(drawbend::read_file(dir + "/e.vtu"));
  BOOST_TEST(find(els, "VTKFile/UnstructuredGrid/Piece").attrs.at("NumberOfPoints") == "0");
}

BOOST_AUTO_TEST_CASE(bad_input_throws_and_writes_nothing) {
  const std::string dir = tmpdir(), path = dir + "/bad.vtu";
  const Block b;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto expect = [&](VtuMesh m, std::vector<VtuField> pf, std::vector<VtuField> cf, const std::string& says,
                    double t = 0.0) {
    BOOST_TEST_CONTEXT(says) {
      try {
        write_vtu(path, m, pf, cf, t);
        BOOST_ERROR("no exception");
      } catch (const std::invalid_argument& e) {
        BOOST_TEST(std::string(e.what()).find(says) != std::string::npos, e.what());
      }
      BOOST_TEST(!fs::exists(path));
    }
  };
  auto mesh = [&](const double* y, const int* hex) { return VtuMesh{12, b.x.data(), y, b.z.data(), 2, hex}; };
  expect(mesh(nullptr, b.hex.data()), {}, {}, "null coordinate pointer");
  expect(mesh(b.y.data(), nullptr), {}, {}, "null connectivity pointer");
  std::vector<int> hex = b.hex;
  hex[13] = 12;
  expect(mesh(b.y.data(), hex.data()), {}, {}, "cell 1 node 5 has index 12, outside [0, 12)");
  hex[13] = -1;
  expect(mesh(b.y.data(), hex.data()), {}, {}, "cell 1 node 5 has index -1");
  expect(b.mesh(), {{"u", 2, b.u.data()}}, {}, "PointData field 'u' has 2 components");
  expect(b.mesh(), {}, {{"s", 9, b.stress.data()}}, "CellData field 's' has 9 components");
  expect(b.mesh(), {{"T", 1, nullptr}}, {}, "PointData field 'T' has null data");
  expect(b.mesh(), {{"", 1, b.T.data()}}, {}, "empty name");
  expect(b.mesh(), {{"T", 1, b.T.data()}, {"T", 1, b.T.data()}}, {}, "duplicate PointData field 'T'");
  std::vector<double> T = b.T;
  T[4] = nan;
  expect(b.mesh(), {{"T", 1, T.data()}}, {}, "field 'T' value 4 is not finite");
  expect(b.mesh(), {}, {}, "time is not finite", nan);

  BOOST_CHECK_THROW(write_pvd(dir + "/r.pvd", {{0.0, ""}}), std::invalid_argument);
  BOOST_CHECK_THROW(write_pvd(dir + "/r.pvd", {{nan, "a.vtu"}}), std::invalid_argument);
  BOOST_TEST(!fs::exists(dir + "/r.pvd"));
}

BOOST_AUTO_TEST_CASE(binary_frames_read_back_bit_identical) {
  const std::string dir = tmpdir();
  const Block b;
  std::vector<double> big(20000);  // 160,000 bytes: 3 zlib blocks of 64 KiB (the last partial)
  for (std::size_t i = 0; i < big.size(); ++i) big[i] = std::sin(0.001 * static_cast<double>(i)) / 3.0;
  VtuMesh line{20000, big.data(), big.data(), big.data(), 0, nullptr};
  for (VtkFormat f : {VtkFormat::raw, VtkFormat::zlib}) {
    const std::string path = dir + (f == VtkFormat::raw ? "/raw.vtu" : "/zlib.vtu");
    write_vtu(path, b.mesh(), {{"T", 1, b.T.data()}, {"u", 3, b.u.data()}}, {{"stress", 6, b.stress.data()}}, 0.25, f);
    const std::string text = drawbend::read_file(path);
    BOOST_TEST((text.find("vtkZLibDataCompressor") != std::string::npos) == (f == VtkFormat::zlib));
    std::vector<double> xyz;
    for (std::size_t n = 0; n < 12; ++n) xyz.insert(xyz.end(), {b.x[n], b.y[n], b.z[n]});
    BOOST_TEST(read_vtu_array(path, text, "Points") == xyz, tt::per_element());
    BOOST_TEST(read_vtu_array(path, text, "T") == b.T, tt::per_element());
    BOOST_TEST(read_vtu_array(path, text, "u") == b.u, tt::per_element());
    BOOST_TEST(read_vtu_array(path, text, "stress") == b.stress, tt::per_element());
    const std::vector<double> conn(b.hex.begin(), b.hex.end()), offsets{8, 16}, types{12, 12}, time{0.25};
    BOOST_TEST(read_vtu_array(path, text, "connectivity") == conn, tt::per_element());
    BOOST_TEST(read_vtu_array(path, text, "offsets") == offsets, tt::per_element());
    BOOST_TEST(read_vtu_array(path, text, "types") == types, tt::per_element());
    BOOST_TEST(read_vtu_array(path, text, "TimeValue") == time, tt::per_element());
    BOOST_CHECK_THROW(read_vtu_array(path, text, "missing"), drawbend::InputError);
    const std::string bigpath = dir + "/big.vtu";
    write_vtu(bigpath, line, {{"v", 1, big.data()}}, {}, 0.0, f);
    BOOST_TEST(read_vtu_array(bigpath, drawbend::read_file(bigpath), "v") == big, tt::per_element());
  }
}

BOOST_AUTO_TEST_CASE(polydata_and_multiblock) {
  const std::string dir = tmpdir();
  const std::vector<double> x{0, 1, 2, 0, 1, 2}, y{0, 0, 0, 1, 1, 1}, z(6, 0.0), s{0, 1};
  const std::vector<int> quads{0, 1, 4, 3, 1, 2, 5, 4};
  write_vtp(dir + "/t.vtp", {6, x.data(), y.data(), z.data(), 2, quads.data(), 4, 9}, {}, {{"surface", 1, s.data()}});
  const auto els = parse_xml(drawbend::read_file(dir + "/t.vtp"));
  BOOST_TEST(find(els, "VTKFile/PolyData/Piece").attrs.at("NumberOfPolys") == "2");
  BOOST_TEST(numbers(find(els, "VTKFile/PolyData/Piece/Polys/DataArray", "offsets")) == (std::vector<double>{4, 8}),
             tt::per_element());
  BOOST_CHECK_THROW(write_vtp(dir + "/h.vtp", Block().mesh(), {}, {}), std::invalid_argument);  // hexahedra
  write_vtm(dir + "/f.vtm", {{"sheet", "a.vtu"}, {"pin", "b.vtp"}});
  std::vector<std::string> blocks;
  for (const auto& e : parse_xml(drawbend::read_file(dir + "/f.vtm")))
    if (e.path == "VTKFile/vtkMultiBlockDataSet/DataSet") blocks.push_back(e.attrs.at("name") + "|" + e.attrs.at("file"));
  BOOST_TEST(blocks == (std::vector<std::string>{"sheet|a.vtu", "pin|b.vtp"}), tt::per_element());
}
