// The file gate and the CSV dialects (core/file_gate.hpp, core/csv_dialect.hpp),
// one case per class of input, not per example.  Closed-form answers:
//  - read_input refuses a folder, a device (/dev/zero), a FIFO and a missing
//    file, each message naming the path and the option registered for it
//    ("--hardening '<path>': expected a regular file, found a FIFO"); it
//    returns at once on the FIFO (no writer: a blocking open would hang).
//  - a 10-byte file read with a 4-byte cap is refused; read with its size it
//    comes back unchanged.
//  - write_output refuses to replace a FIFO and a folder (both still there,
//    no temporary file left), and replaces a regular file.
//  - parse_csv: "a,b,,\n1,2,,\n" has header {a, b} and the row {1, 2}
//    (trailing empty columns); a quoted cell with a line break is one cell of
//    one row numbered by its first line; a UTF-8 byte-order mark is dropped;
//    UTF-16 (FF FE) and a tab-separated header are refused naming "UTF-16"
//    and "tab"; Windows-1252 "\xB5" becomes UTF-8 "\xC2\xB5" (µ).
//  - valid_utf8 turns every invalid byte into U+FFFD and keeps valid text;
//    clip_for_message cuts a 10,000-byte text to 80 bytes plus its length.
#define BOOST_TEST_MODULE file_gate
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>

#include <sys/stat.h>

#include "core/csv.hpp"
#include "core/csv_dialect.hpp"
#include "core/file_gate.hpp"
#include "loop/measured.hpp"

using namespace drawbend;
namespace fs = std::filesystem;

namespace {
std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}
fs::path scratch() {
  const fs::path d = fs::temp_directory_path() / ("drawbend_file_gate_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}
bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }
}  // namespace

BOOST_AUTO_TEST_CASE(reader_refuses_what_is_not_a_regular_file) {
  const fs::path d = scratch();
  const std::string fifo = (d / "fifo").string(), folder = (d / "folder").string();
  fs::remove(fifo);
  BOOST_REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  fs::create_directories(folder);
  name_input(fifo, "--hardening");
  const std::string m_fifo = message_of([&] { read_input(fifo); });
  BOOST_TEST(contains(m_fifo, "--hardening '" + fifo + "': expected a regular file, found a FIFO"), m_fifo);
  const std::string m_dir = message_of([&] { read_input(folder); });
  BOOST_TEST(contains(m_dir, folder + ": expected a regular file, found a folder"), m_dir);
  const std::string m_dev = message_of([&] { read_input("/dev/zero"); });
  BOOST_TEST(contains(m_dev, "/dev/zero: expected a regular file, found a device"), m_dev);
  const std::string m_none = message_of([&] { read_input((d / "none").string()); });
  BOOST_TEST(contains(m_none, "cannot open file for reading"), m_none);
  // The same through the CSV reader every table goes through.
  BOOST_TEST(contains(message_of([&] { read_csv(fifo); }), "found a FIFO"));
  fs::remove_all(d);
}

BOOST_AUTO_TEST_CASE(reader_caps_the_size) {
  const fs::path d = scratch();
  const std::string f = (d / "ten.txt").string();
  std::ofstream(f) << "0123456789";
  BOOST_TEST(contains(message_of([&] { read_input(f, 4); }), "above the limit"));
  BOOST_TEST(read_input(f, 10) == "0123456789");
  fs::remove_all(d);
}

BOOST_AUTO_TEST_CASE(writer_replaces_only_regular_files) {
  const fs::path d = scratch();
  const std::string fifo = (d / "fifo").string(), folder = (d / "folder").string(), file = (d / "f.txt").string();
  BOOST_REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  fs::create_directories(folder);
  BOOST_TEST(contains(message_of([&] { write_output(fifo, "x"); }), "it is a FIFO"));
  BOOST_TEST(contains(message_of([&] { write_output(folder, "x"); }), "it is a folder"));
  BOOST_TEST(fs::is_fifo(fifo));
  BOOST_TEST(fs::is_directory(folder));
  std::ofstream(file) << "old";
  write_output(file, "new");
  BOOST_TEST(read_input(file) == "new");
  int left = 0;
  for (const auto& e : fs::directory_iterator(d)) left += contains(e.path().filename().string(), ".tmp");
  BOOST_TEST(left == 0);
  fs::remove_all(d);
}

BOOST_AUTO_TEST_CASE(csv_dialects) {
  const CsvTable t = parse_csv("a,b,,\n1,2,,\n3,4\n", "t.csv");
  BOOST_TEST(t.header.size() == 2u);
  BOOST_TEST(t.rows.size() == 2u);
  const CsvTable q = parse_csv("name,value\n\"two\nlines\",1\nnext,2\n", "q.csv");
  BOOST_REQUIRE(q.rows.size() == 2u);
  BOOST_TEST(q.rows[0].cells[0] == "two\nlines");
  BOOST_TEST(q.rows[0].line == 2);
  BOOST_TEST(q.rows[1].line == 4);
  BOOST_TEST(parse_csv("\xEF\xBB\xBFx,y\n1,2\n", "bom.csv").header[0] == "x");
  const std::string utf16("\xFF\xFE" "a\0,\0b\0\n\0", 10);
  BOOST_TEST(contains(message_of([&] { parse_csv(utf16, "u.csv"); }), "UTF-16"));
  const std::string utf16_nobom("a\0,\0b\0\n\0" "1\0,\0" "2\0\n\0", 16);
  BOOST_TEST(contains(message_of([&] { parse_csv(utf16_nobom, "u.csv"); }), "UTF-16"));
  BOOST_TEST(contains(message_of([&] { parse_csv("a\tb\n1\t2\n", "tab.csv"); }), "found a tab"));
  const CsvTable w = parse_csv("F_\xB5,b\n1,2\n", "w.csv");
  BOOST_TEST(w.header[0] == "F_\xC2\xB5");
}

BOOST_AUTO_TEST_CASE(loop_reader_dialects) {
  const std::string head = "test_id,pin,pin_diameter_mm,direction_deg,speed_mm_s,lubricant,back_tension_N,outlet_force_N";
  const std::string row = "t1,fixed,12.7,0,10,dry,1000,1500";
  // Trailing empty columns, a tab-separated copy and a quoted line break in an extra column.
  const loop::Dataset a = loop::parse_measured(head + ",,\n" + row + ",,\n", "a.csv");
  BOOST_TEST(a.rows.size() == 1u);
  BOOST_TEST(a.problems.empty());
  std::string tabbed = head + "\n" + row + "\n";
  for (char& c : tabbed) c = c == ',' ? '\t' : c;
  const loop::Dataset b = loop::parse_measured(tabbed, "b.csv");
  BOOST_TEST(b.rows.size() == 1u);
  BOOST_TEST(contains(b.format_note, "tab"));
  const loop::Dataset c = loop::parse_measured(head + ",note\n" + row + ",\"two\nlines\"\n" + row + ",x\n", "c.csv");
  BOOST_TEST(c.rows_read == 2);
  BOOST_TEST(c.rows_dropped == 0);
  const loop::Dataset w = loop::parse_measured(head + ",F_\xB5\n" + row + ",1\n", "w.csv");
  BOOST_REQUIRE(w.extra_columns.size() == 1u);
  BOOST_TEST(w.extra_columns[0] == "F_\xC2\xB5");
  BOOST_TEST(contains(w.format_note, "Windows-1252"));
}

BOOST_AUTO_TEST_CASE(utf8_and_clipping) {
  BOOST_TEST(valid_utf8("ok \xC2\xB5") == "ok \xC2\xB5");
  BOOST_TEST(valid_utf8("a\xB5z") == "a\xEF\xBF\xBDz");
  BOOST_TEST(valid_utf8("\xED\xA0\x80") == "\xEF\xBF\xBD\xEF\xBF\xBD\xEF\xBF\xBD");  // a surrogate, byte by byte
  const std::string c = clip_for_message(std::string(10000, 'k'));
  BOOST_TEST(c.size() < 120u);
  BOOST_TEST(contains(c, "(10000 bytes)"));
}
