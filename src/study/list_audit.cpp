#include "study/list_audit.hpp"

#include <filesystem>
#include <map>
#include <set>
#include <utility>

#include "core/csv.hpp"
#include "study/checks.hpp"

namespace drawbend::study {

std::string chapter_of(const std::string& check_id) { return check_id.substr(0, check_id.find('.')); }

std::string chapter_tier(const ChapterSource& ch) {
  const std::string p = ch.out_dir + "/values.csv";
  if (!std::filesystem::exists(p)) return "";
  const CsvTable t = read_csv(p);
  for (const auto& r : t.rows)
    if (t.text(r, "key") == "tier") return t.text(r, "value");
  return "";
}

std::vector<std::string> unused_list_entries(const std::vector<ChapterSource>& chapters, const std::string& list_csv) {
  // Check ids and the chapters that ran, per tier.
  std::map<std::string, std::vector<std::string>> ids_by_tier;
  std::map<std::string, std::set<std::string>> ran_by_tier;
  std::set<std::string> ran_any;
  for (const auto& ch : chapters) {
    std::string tier = chapter_tier(ch);
    if (tier.empty()) tier = "quick";
    const CsvTable t = read_csv(ch.out_dir + "/checks.csv");
    for (const auto& r : t.rows) {
      const std::string id = t.text(r, "id");
      ids_by_tier[tier].push_back(id);
      ran_by_tier[tier].insert(chapter_of(id));
      ran_any.insert(chapter_of(id));
    }
  }
  std::map<std::string, std::pair<int, int>> seen;  // entry -> (tiers that audit it, tiers where it is unused)
  for (const auto& [tier, ids] : ids_by_tier) {
    const std::set<std::string>& ran = ran_by_tier[tier];
    const auto e = Errata::load(list_csv, tier);
    for (const auto& x : e.unused({}))
      if (ran.count(chapter_of(x))) ++seen[x].first;
    for (const auto& x : e.unused(ids))
      if (ran.count(chapter_of(x))) ++seen[x].second;
  }
  std::vector<std::string> dead;
  for (const auto& x : Errata::load(list_csv, "").unused({}))
    if (!ran_any.count(chapter_of(x))) dead.push_back(x);
  for (const auto& [x, n] : seen)
    if (n.first > 0 && n.second == n.first) dead.push_back(x);
  return dead;
}

}  // namespace drawbend::study
