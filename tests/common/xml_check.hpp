#pragma once
// A small XML checker for tests (no external tools): parse_xml() checks that
// tags balance (prolog, comments, self-closing tags and quoted attributes are
// handled) and returns the elements; numbers() reads a DataArray's values.
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>
#include <cctype>
#include <map>
#include <vector>

namespace xmlcheck {


struct Element {
  std::string name, path;  // path: "VTKFile/UnstructuredGrid/Piece/..."
  std::map<std::string, std::string> attrs;
  std::string text;  // character data directly inside the element
};

/// Minimal well-formedness checker: balanced, correctly nested tags, one root,
/// quoted unique attributes; skips <?...?> and comments.  Throws on error.
inline std::vector<Element> parse_xml(const std::string& s) {
  std::vector<Element> out;
  std::vector<std::size_t> open;
  int roots = 0;
  std::size_t i = 0;
  auto error = [&](const std::string& m) { throw std::runtime_error("XML at " + std::to_string(i) + ": " + m); };
  auto name_at = [&](std::size_t& p) {
    const std::size_t b = p;
    while (p < s.size() && (std::isalnum(static_cast<unsigned char>(s[p])) || s[p] == '_' || s[p] == ':' || s[p] == '-'))
      ++p;
    if (p == b) error("expected a name");
    return s.substr(b, p - b);
  };
  auto skip_ws = [&](std::size_t& p) { while (p < s.size() && std::isspace(static_cast<unsigned char>(s[p]))) ++p; };
  while (i < s.size()) {
    if (s[i] != '<') {
      const std::size_t e = s.find('<', i);
      const std::string t = s.substr(i, e == std::string::npos ? std::string::npos : e - i);
      if (open.empty() && t.find_first_not_of(" \t\r\n") != std::string::npos) error("text outside the root");
      if (!open.empty()) out[open.back()].text += t;
      i = e == std::string::npos ? s.size() : e;
    } else if (s.compare(i, 2, "<?") == 0) {
      const std::size_t e = s.find("?>", i);
      if (e == std::string::npos) error("unterminated <?");
      i = e + 2;
    } else if (s.compare(i, 4, "<!--") == 0) {
      const std::size_t e = s.find("-->", i);
      if (e == std::string::npos) error("unterminated comment");
      i = e + 3;
    } else if (s.compare(i, 2, "</") == 0) {
      std::size_t p = i + 2;
      const std::string n = name_at(p);
      skip_ws(p);
      if (p >= s.size() || s[p] != '>') error("bad end tag");
      if (open.empty() || out[open.back()].name != n) error("end tag </" + n + "> does not match");
      open.pop_back();
      i = p + 1;
    } else {
      std::size_t p = i + 1;
      Element el;
      el.name = name_at(p);
      el.path = open.empty() ? el.name : out[open.back()].path + "/" + el.name;
      for (;;) {
        const std::size_t before = p;
        skip_ws(p);
        if (p >= s.size()) error("unterminated tag");
        if (s[p] == '>' || s.compare(p, 2, "/>") == 0) break;
        if (p == before) error("missing space before attribute");
        const std::string a = name_at(p);
        skip_ws(p);
        if (p >= s.size() || s[p] != '=') error("attribute without '='");
        skip_ws(++p);
        if (p >= s.size() || (s[p] != '"' && s[p] != '\'')) error("unquoted attribute " + a);
        const std::size_t e = s.find(s[p], p + 1);
        if (e == std::string::npos) error("unterminated attribute " + a);
        const std::string v = s.substr(p + 1, e - p - 1);
        if (v.find('<') != std::string::npos) error("'<' in attribute " + a);
        if (!el.attrs.emplace(a, v).second) error("duplicate attribute " + a);
        p = e + 1;
      }
      if (open.empty() && ++roots > 1) error("second root element");
      const bool self_closing = s[p] == '/';
      out.push_back(el);
      if (!self_closing) open.push_back(out.size() - 1);
      i = p + (self_closing ? 2 : 1);
    }
  }
  if (!open.empty()) throw std::runtime_error("unclosed <" + out[open.back()].name + ">");
  if (roots != 1) throw std::runtime_error("no root element");
  return out;
}

inline std::vector<std::string> tokens(const std::string& t) {
  std::istringstream is(t);
  std::vector<std::string> v;
  for (std::string w; is >> w;) v.push_back(w);
  return v;
}

inline std::vector<double> numbers(const Element& e) {
  std::vector<double> v;
  for (const auto& t : tokens(e.text)) v.push_back(std::strtod(t.c_str(), nullptr));
  return v;
}

const Element& find(const std::vector<Element>& els, const std::string& path, const std::string& name = "") {
  for (const auto& e : els)
    if (e.path == path && (name.empty() || (e.attrs.count("Name") && e.attrs.at("Name") == name))) return e;
  throw std::runtime_error("no element " + path + " " + name);
}

}  // namespace xmlcheck
