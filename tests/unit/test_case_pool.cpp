// The case pool (src/sim/case_pool.hpp).
// Closed-form answers:
//  - n = 7 cases on 1, 2 and 3 workers: every index runs exactly once, and
//    each case's result lands in its own slot (out[i] = i*i), whatever the order.
//  - With costs, one worker takes the cases largest cost first: cost
//    {1, 5, 3} runs 1, 2, 0.
//  - Cases 2 and 5 throw: the other cases still run (6 of 8 done), and the
//    exception rethrown is case 2's (the first by case order).
//  - Each case sees max(1, hardware threads / workers) OpenMP threads.
//  - set_case_threads(n) caps the threads in all (`model-loop --threads`):
//    with n = 1 and 2 jobs asked for, 6 cases run one at a time (never two
//    at once) with 1 OpenMP thread each; with n = 3 and 3 jobs, 3 threads
//    each for 1 case and 1 each for 3 cases; set_case_threads(0) restores
//    the hardware threads.
//  - A case run before under another name (sim::find_same_run): in a folder
//    holding runs "a" and "b" with the deck of spec s under the names
//    "ch5_base" and "other", and a summary each (s: the quick draw-bend deck,
//    sim::quick_deck_spec), s under the name "fb" is
//    found in "a" (the first by name); with the back tension 1 N higher,
//    nowhere (""); with "a"'s summary gone, in "b"; with a byte then added to
//    "b"'s deck, nowhere; a folder that does not exist is skipped.  The
//    folders hold their tables as a run writes them (the flow curve copied
//    beside the deck); with "b"'s deck restored but one byte added to its
//    copy of the flow curve, nowhere (the table it ran with is not the one
//    the deck reads now).
//  - io::portable_fingerprint: one deck text naming a table by absolute path
//    in folder "x" and the same text with the same table (same name, same
//    bytes) in folder "y" give the same fingerprint; one byte added to the
//    table in "y" gives another; a deck text one byte longer gives another.
#define BOOST_TEST_MODULE case_pool
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "io/portable_paths.hpp"
#include "sim/case_pool.hpp"
#include "sim/fe_options.hpp"

#include <filesystem>
#include <fstream>
#include <unistd.h>

using drawbend::sim::run_cases;

BOOST_AUTO_TEST_CASE(every_case_once_in_its_slot) {
  for (int jobs : {1, 2, 3}) {
    std::vector<int> out(7, -1);
    std::vector<std::atomic<int>> runs(7);
    run_cases(7, [&](std::size_t i) {
      ++runs[i];
      out[i] = static_cast<int>(i * i);
    }, {}, jobs);
    for (int i = 0; i < 7; ++i) {
      BOOST_TEST(runs[i].load() == 1);
      BOOST_TEST(out[i] == i * i);
    }
  }
}

BOOST_AUTO_TEST_CASE(largest_cost_first_on_one_worker) {
  std::vector<std::size_t> order;
  run_cases(3, [&](std::size_t i) { order.push_back(i); }, {1.0, 5.0, 3.0}, 1);
  BOOST_TEST(order == (std::vector<std::size_t>{1, 2, 0}), boost::test_tools::per_element());
}

BOOST_AUTO_TEST_CASE(first_exception_by_case_order) {
  std::atomic<int> done{0};
  try {
    run_cases(8, [&](std::size_t i) {
      if (i == 5 || i == 2) throw std::runtime_error("case " + std::to_string(i));
      ++done;
    }, {}, 2);
    BOOST_FAIL("no exception");
  } catch (const std::runtime_error& e) {
    BOOST_TEST(std::string(e.what()) == "case 2");
  }
  BOOST_TEST(done.load() == 6);
}

#ifdef _OPENMP
BOOST_AUTO_TEST_CASE(threads_per_case) {
  const int hw = omp_get_num_procs();
  std::mutex m;
  std::vector<int> seen;
  run_cases(4, [&](std::size_t) {
    std::lock_guard<std::mutex> lock(m);
    seen.push_back(omp_get_max_threads());
  }, {}, 2);
  for (int t : seen) BOOST_TEST(t == std::max(1, hw / 2));
}
#endif

BOOST_AUTO_TEST_CASE(thread_budget_caps_cases_and_threads) {
  using drawbend::sim::set_case_threads;
  auto run = [](std::size_t n, int jobs, int& most_at_once, std::vector<int>& threads) {
    std::mutex m;
    int now = 0;
    most_at_once = 0;
    threads.clear();
    run_cases(n, [&](std::size_t) {
      {
        std::lock_guard<std::mutex> lock(m);
        most_at_once = std::max(most_at_once, ++now);
#ifdef _OPENMP
        threads.push_back(omp_get_max_threads());
#else
        threads.push_back(1);
#endif
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));  // long enough to overlap if allowed
      std::lock_guard<std::mutex> lock(m);
      --now;
    }, {}, jobs);
  };
  int most = 0;
  std::vector<int> threads;
  set_case_threads(1);
  run(6, 2, most, threads);
  BOOST_TEST(most == 1);
  BOOST_TEST(threads.size() == 6u);
  for (int t : threads) BOOST_TEST(t == 1);
  set_case_threads(3);
#ifdef _OPENMP
  run(1, 3, most, threads);
  BOOST_TEST(threads == std::vector<int>{3}, boost::test_tools::per_element());
#endif
  run(3, 3, most, threads);
  for (int t : threads) BOOST_TEST(t == 1);
  set_case_threads(0);
#ifdef _OPENMP
  run(1, 1, most, threads);
  BOOST_TEST(threads == std::vector<int>{omp_get_num_procs()}, boost::test_tools::per_element());
#endif
}

BOOST_AUTO_TEST_CASE(same_run_found_under_another_name) {
  namespace fs = std::filesystem;
  using drawbend::sim::DrawBendSpec;
  using drawbend::sim::find_same_run;
  const fs::path root = fs::temp_directory_path() / ("drawbend_same_run_" + std::to_string(::getpid()));
  fs::remove_all(root);
  auto write = [](const fs::path& f, const std::string& text) {
    fs::create_directories(f.parent_path());
    std::ofstream(f) << text;
  };
  DrawBendSpec s = drawbend::sim::quick_deck_spec();  // the quick draw-bend deck (sim/fe_options.hpp)
  DrawBendSpec a = s, b = s;
  a.name = "ch5_base";
  b.name = "other";
  // As run_drawbend writes a run folder's deck: tables by file name (io/portable_paths.hpp).
  auto deck_text = [](const DrawBendSpec& d) { return drawbend::io::portable_deck(drawbend::sim::deck_text(d)); };
  fs::create_directories(root / "a");
  fs::create_directories(root / "b");
  drawbend::io::portable_deck(drawbend::sim::deck_text(a), (root / "a").string());  // copies the tables
  drawbend::io::portable_deck(drawbend::sim::deck_text(b), (root / "b").string());
  write(root / "a" / "deck.toml", deck_text(a));
  write(root / "a" / "summary.csv", "quantity,value,unit\n");
  write(root / "b" / "deck.toml", deck_text(b));
  write(root / "b" / "summary.csv", "quantity,value,unit\n");
  s.name = "fb";
  const std::vector<std::string> roots = {(root / "missing").string(), root.string()};
  BOOST_TEST(find_same_run(s, roots) == (root / "a").string());
  DrawBendSpec t = s;
  t.back_tension += 1.0;
  BOOST_TEST(find_same_run(t, roots) == "");
  fs::remove(root / "a" / "summary.csv");
  BOOST_TEST(find_same_run(s, roots) == (root / "b").string());
  write(root / "b" / "deck.toml", deck_text(b) + "#");
  BOOST_TEST(find_same_run(s, roots) == "");
  write(root / "b" / "deck.toml", deck_text(b));
  BOOST_TEST(find_same_run(s, roots) == (root / "b").string());
  std::size_t tables = 0;
  for (const auto& f : fs::directory_iterator(root / "b"))
    if (f.path().extension() == ".csv" && f.path().filename() != "summary.csv") {
      std::ofstream(f.path(), std::ios::app) << " ";
      ++tables;
    }
  BOOST_TEST(tables == 1u);  // the flow curve
  BOOST_TEST(find_same_run(s, roots) == "");
  BOOST_TEST(find_same_run(s, {}) == "");
  fs::remove_all(root);
}

BOOST_AUTO_TEST_CASE(fingerprint_follows_the_tables_not_their_folder) {
  namespace fs = std::filesystem;
  const fs::path root = fs::temp_directory_path() / ("drawbend_fingerprint_" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root / "x");
  fs::create_directories(root / "y");
  for (const char* d : {"x", "y"}) std::ofstream(root / d / "curve.csv") << "strain,stress\n0,100\n0.1,200\n";
  auto deck = [&](const char* d) { return "[material]\nhardening = \"" + (root / d / "curve.csv").string() + "\"\n"; };
  using drawbend::io::portable_fingerprint;
  BOOST_TEST(deck("x") != deck("y"));
  BOOST_TEST(portable_fingerprint(deck("x")) == portable_fingerprint(deck("y")));
  BOOST_TEST(portable_fingerprint(deck("x") + "#") != portable_fingerprint(deck("x")));
  std::ofstream(root / "y" / "curve.csv", std::ios::app) << " ";
  BOOST_TEST(portable_fingerprint(deck("x")) != portable_fingerprint(deck("y")));
  fs::remove_all(root);
}
