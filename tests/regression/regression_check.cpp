// Regression tier: compare a chapter's checks.csv against gold values from our
// own code (tests/regression/gold/<chapter>.csv: id,ours,status).
//   - every gold id must be present, with the same status;
//   - |ours - gold| <= rel_err * |gold| + abs_zero, with rel_err = 1e-7 because
//     checks.csv prints 8 significant digits, and abs_zero = 1e-12;
//   - ids without gold are reported (new checks need gold: run `make gold`).
// This pins documented errata too: an erratum that moves is caught here.
// Usage: regression_check CHECKS.csv GOLD.csv [--update]
#include <cmath>
#include <iostream>
#include <map>

#include "core/csv.hpp"

int main(int argc, char** argv) {
  using namespace drawbend;
  if (argc < 3) {
    std::cerr << "usage: regression_check CHECKS.csv GOLD.csv [--update]\n";
    return 2;
  }
  const std::string checks_path = argv[1], gold_path = argv[2];
  const bool update = argc > 3 && std::string(argv[3]) == "--update";
  constexpr double rel_err = 1e-7, abs_zero = 1e-12;
  try {
    const CsvTable now = read_csv(checks_path);
    if (update) {
      CsvWriter w({"id", "ours", "status"});
      w.comment("regression gold: our own values (not the thesis's); regenerate with `make gold` and review the diff");
      for (const auto& r : now.rows) w.row({now.text(r, "id"), now.text(r, "ours"), now.text(r, "status")});
      w.save(gold_path);
      std::cout << "gold written: " << gold_path << " (" << now.rows.size() << " values)\n";
      return 0;
    }
    std::map<std::string, const CsvRow*> current;
    for (const auto& r : now.rows) current[now.text(r, "id")] = &r;
    const CsvTable gold = read_csv(gold_path);
    int bad = 0;
    for (const auto& g : gold.rows) {
      const std::string id = gold.text(g, "id");
      const auto it = current.find(id);
      if (it == current.end()) {
        std::cout << "missing: " << id << "\n";
        ++bad;
        continue;
      }
      const double want = gold.number(g, "ours"), got = now.number(*it->second, "ours");
      if (!(std::abs(got - want) <= rel_err * std::abs(want) + abs_zero)) {
        std::cout << "changed: " << id << ": gold " << fmt(want, 10) << ", now " << fmt(got, 10) << "\n";
        ++bad;
      }
      if (gold.text(g, "status") != now.text(*it->second, "status")) {
        std::cout << "status: " << id << ": gold " << gold.text(g, "status") << ", now "
                  << now.text(*it->second, "status") << "\n";
        ++bad;
      }
      current.erase(it);
    }
    for (const auto& [id, r] : current) {
      std::cout << "no gold: " << id << " (run `make gold` and review)\n";
      ++bad;
    }
    std::cout << (bad ? "REGRESSION: " : "regression ok: ") << gold.rows.size() << " gold values, " << bad
              << " problem(s)\n";
    return bad ? 1 : 0;
  } catch (const std::exception& e) {
    std::cerr << "regression_check: " << e.what() << "\n";
    return 2;
  }
}
