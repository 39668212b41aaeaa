// Portable inputs.  See portable_paths.hpp.
#include "io/portable_paths.hpp"

#include <filesystem>
#include <map>
#include <regex>

#include <toml++/toml.h>

#include "core/csv.hpp"
#include "core/hash.hpp"
#include "core/input_problems.hpp"
#include "core/toml_read.hpp"
#include "io/deck_context.hpp"
#include "io/deck_friction.hpp"

namespace drawbend::io {

namespace fs = std::filesystem;

namespace {

constexpr const char* kFileKeys[] = {"nodes", "lines", "table"};  // friction tables (hardening: [material])

/// Make the friction table's relative file keys absolute against `base`.
void absolutise(toml::table& t, const fs::path& base) {
  for (const char* k : kFileKeys)
    if (auto* v = t.get_as<std::string>(k)) {
      const fs::path p(v->get());
      if (p.is_relative()) *v = fs::absolute(base / p).lexically_normal().string();
    }
}

}  // namespace

namespace {
/// The law checked on its own, as the deck reader checks [contact.friction]
/// (io/deck_friction.hpp), so that a problem names where the user wrote it
/// ("--friction:1: friction.mu", or friction_model.toml:7: friction.p_max; a
/// nodes file's own file:line) and not a line of the deck built from it.
void check_friction(const toml::table& t, const std::string& where, const std::string& dir) {
  InputProblems problems(where);
  const DeckContext c(where, problems);
  problems.attempt([&] { (void)make_friction(c, t, dir, "friction"); });
  problems.throw_if_any();
}
}  // namespace

std::optional<FrictionSpec> friction_argument(const std::string& text, const std::string& base_dir) {
  if (text.empty()) return std::nullopt;
  const std::size_t first = text.find_first_not_of(" \t");
  if (first != std::string::npos && text[first] == '{') {
    toml::table root = parse_toml("friction = " + text, "--friction");
    auto* t = root["friction"].as_table();
    if (!t) throw InputError("--friction: expected a TOML inline table such as { law = \"coulomb\", mu = 0.1 }");
    check_friction(*t, "--friction", base_dir);
    absolutise(*t, fs::path(base_dir));
    return read_friction(*t);
  }
  const fs::path file = fs::path(base_dir) / text;
  if (!fs::is_regular_file(file))
    throw InputError("--friction: '" + text + "' is neither a TOML inline table ({ law = ... }) nor a readable file "
                     "with a [friction] table (such as the loop's friction_model.toml)");
  toml::table root = parse_toml_file(file.string());
  auto* t = root["friction"].as_table();
  if (!t) throw InputError(file.string() + ": expected a [friction] table (the loop's friction_model.toml has one)");
  check_friction(*t, file.string(), file.parent_path().string());
  absolutise(*t, file.parent_path());
  return read_friction(*t);
}

namespace {
/// `text` with every input file that can be named by its bare name so named
/// (see portable_deck); `fn(absolute path, bare name)` is called for each, in
/// the deck's order.
template <class Fn>
std::string rewrite_inputs(const std::string& text, Fn fn) {
  static const std::regex key(R"re(\b(hardening|nodes|lines|table)(\s*=\s*)(["'])([^"'\n]*)\3)re");
  std::map<std::string, std::string> by_name;  // file name -> the absolute path it stands for
  std::string out;
  std::size_t last = 0;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), key); it != std::sregex_iterator(); ++it) {
    const auto& m = *it;
    const fs::path p(m[4].str());
    std::string value = m[4].str();
    std::error_code ec;
    if (p.is_absolute() && fs::is_regular_file(p, ec)) {
      const std::string name = p.filename().string();
      const auto [slot, fresh] = by_name.emplace(name, p.string());
      if (fresh || slot->second == p.string()) {
        value = name;
        fn(p, name);
      }
    }
    out.append(text, last, static_cast<std::size_t>(m.position(0)) - last);
    out += m[1].str() + m[2].str() + m[3].str() + value + m[3].str();
    last = static_cast<std::size_t>(m.position(0) + m.length(0));
  }
  out.append(text, last, std::string::npos);
  return out;
}
}  // namespace

std::string portable_deck(const std::string& text, const std::string& copy_to) {
  return rewrite_inputs(text, [&](const fs::path& p, const std::string& name) {
    if (copy_to.empty()) return;
    std::error_code ec;
    const fs::path dest = fs::path(copy_to) / name;
    if (!fs::exists(dest, ec) || read_file(dest.string()) != read_file(p.string()))
      write_file_atomic(dest.string(), read_file(p.string()));
  });
}

std::uint64_t portable_fingerprint(const std::string& text) {
  std::uint64_t tables = fnv1a64({});
  const std::string portable = rewrite_inputs(text, [&](const fs::path& p, const std::string& name) {
    tables = fnv1a64(read_file(p.string()), fnv1a64(name, tables));
  });
  return fnv1a64(portable, tables);
}

bool portable_inputs_current(const std::string& text, const std::string& dir) {
  bool same = true;
  rewrite_inputs(text, [&](const fs::path& p, const std::string& name) {
    std::error_code ec;
    const fs::path copy = fs::path(dir) / name;
    same = same && fs::is_regular_file(copy, ec) && read_file(copy.string()) == read_file(p.string());
  });
  return same;
}

}  // namespace drawbend::io
