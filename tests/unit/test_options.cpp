// Command-line options (core/options.hpp), on known command lines:
//  - an on/off option (bool) takes true or false, and 1 or 0 for older
//    command lines; `--name=value` works as `--name value`;
//  - any other value ("yes", "2", "") is an error that names the option and
//    the accepted values, and leaves the variable unchanged;
//  - the help shows "--name true|false" and the default as true/false; echo()
//    gives "name = true";
//  - a numeric option rejects trailing text ("3x") naming the option.
//  - given() is true exactly for the options on the command line (also when
//    the value equals the default); only_when(false, {"n"}, "with X") throws
//    "--n: applies only with X (given here, it would be ignored)" when --n was
//    given, and nothing when it was not or when the condition holds.
#define BOOST_TEST_MODULE options
#include <boost/test/unit_test.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/options.hpp"

using drawbend::Options;

namespace {
// Parse `args` (without the program name) into a fresh option set.
struct Cli {
  bool on = true, off = false;
  int n = 0;
  Options o{"prog", "test"};
  Cli() {
    o.add(on, "on", "an option that defaults to true");
    o.add(off, "off", "an option that defaults to false");
    o.add(n, "n", "an integer");
  }
  void parse(std::vector<std::string> args) {
    args.insert(args.begin(), "prog");
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    o.parse(static_cast<int>(argv.size()), argv.data());
  }
};

// The message of the invalid_argument thrown by parsing `args`, or "" if none.
std::string error_of(const std::vector<std::string>& args) {
  Cli c;
  try {
    c.parse(args);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}
}  // namespace

BOOST_AUTO_TEST_CASE(bool_takes_true_false_and_one_zero) {
  Cli c;
  c.parse({"--on", "false", "--off", "true"});
  BOOST_TEST(!c.on);
  BOOST_TEST(c.off);
  Cli d;
  d.parse({"--on=0", "--off=1"});
  BOOST_TEST(!d.on);
  BOOST_TEST(d.off);
}

BOOST_AUTO_TEST_CASE(bool_bad_value_names_the_option) {
  for (const std::string bad : {"yes", "2", "", "TRUE"}) {
    const std::string msg = error_of({"--off", bad});
    BOOST_TEST(msg == "--off: expected true or false, found '" + bad + "'");
  }
  BOOST_TEST(error_of({"--on"}) == "option '--on' needs a value");
}

BOOST_AUTO_TEST_CASE(bool_help_and_echo) {
  Cli c;
  const std::string u = c.o.usage();
  BOOST_TEST(u.find("--on true|false\n") != std::string::npos);
  BOOST_TEST(u.find("(default: true)") != std::string::npos);
  BOOST_TEST(u.find("--n VALUE\n") != std::string::npos);
  const auto e = c.o.echo();
  BOOST_TEST(e.at(0) == "on = true");
  BOOST_TEST(e.at(1) == "off = false");
}

BOOST_AUTO_TEST_CASE(integer_rejects_trailing_text) {
  BOOST_TEST(error_of({"--n", "3x"}) == "--n: expected an integer, found '3x'");
}

BOOST_AUTO_TEST_CASE(given_and_only_when) {
  Cli c;
  c.parse({"--n", "0"});
  BOOST_TEST(c.o.given("n"));
  BOOST_TEST(!c.o.given("on"));
  BOOST_CHECK_NO_THROW(c.o.only_when(true, {"n"}, "with X"));
  BOOST_CHECK_NO_THROW(c.o.only_when(false, {"on", "off"}, "with X"));
  std::string msg;
  try {
    c.o.only_when(false, {"on", "n"}, "with X");
  } catch (const std::invalid_argument& e) {
    msg = e.what();
  }
  BOOST_TEST(msg == "--n: applies only with X (given here, it would be ignored)");
}
