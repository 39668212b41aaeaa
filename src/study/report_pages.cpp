#include "study/report_pages.hpp"

#include <map>
#include <set>

namespace drawbend::study {

namespace {

const std::string kNavOpen = "<nav id=\"TOC\"";

/// [begin, end) of the page's nav#TOC element, or {npos, npos}.
std::pair<std::size_t, std::size_t> toc_span(const std::string& html) {
  const std::size_t b = html.find(kNavOpen);
  if (b == std::string::npos) return {std::string::npos, std::string::npos};
  const std::size_t e = html.find("</nav>", b);
  if (e == std::string::npos) return {std::string::npos, std::string::npos};
  return {b, e + 6};
}

/// Every href="#x" of `text` rewritten by `to(x)` (returns the new href value).
template <class F>
std::string rewrite_local_links(const std::string& text, F&& to) {
  const std::string key = "href=\"#";
  std::string out;
  std::size_t pos = 0;
  for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, pos)) {
    const std::size_t b = at + key.size(), e = text.find('"', b);
    if (e == std::string::npos) break;
    out += text.substr(pos, at - pos) + "href=\"" + to(text.substr(b, e - b)) + "\"";
    pos = e + 1;
  }
  return out + text.substr(pos);
}

std::string page_bar(const std::vector<HtmlPage>& pages, std::size_t i) {
  std::string bar = "<nav class=\"pagenav\">";
  if (i > 1) bar += "<a class=\"prev\" href=\"" + pages[i - 1].file + "\">&larr; " + pages[i - 1].label + "</a> ";
  bar += "<a class=\"index\" href=\"" + pages[0].file + "\">" + pages[0].label + "</a>";
  if (i + 1 < pages.size())
    bar += " <a class=\"next\" href=\"" + pages[i + 1].file + "\">" + pages[i + 1].label + " &rarr;</a>";
  return bar + "</nav>\n";
}

}  // namespace

std::vector<std::string> html_ids(const std::string& html) {
  std::vector<std::string> ids;
  const std::string key = " id=\"";
  for (std::size_t at = html.find(key); at != std::string::npos; at = html.find(key, at + 1)) {
    const std::size_t b = at + key.size(), e = html.find('"', b);
    if (e == std::string::npos) break;
    ids.push_back(html.substr(b, e - b));
  }
  return ids;
}

std::string toc_items(const std::string& html) {
  const auto [b, e] = toc_span(html);
  if (b == std::string::npos) return "";
  const std::string nav = html.substr(b, e - b);
  const std::size_t ul = nav.find("<ul>"), end = nav.rfind("</ul>");
  if (ul == std::string::npos || end == std::string::npos || end < ul) return "";
  return nav.substr(ul + 4, end - ul - 4);
}

void link_pages(std::vector<HtmlPage>& pages) {
  // Which page holds each id (the first, when several do: "checks" is on every chapter page).
  std::vector<std::set<std::string>> ids(pages.size());
  std::map<std::string, std::size_t> home;
  for (std::size_t i = 0; i < pages.size(); ++i)
    for (const auto& id : html_ids(pages[i].html)) {
      ids[i].insert(id);
      home.emplace(id, i);
    }
  std::vector<std::string> items(pages.size());
  for (std::size_t i = 0; i < pages.size(); ++i) items[i] = toc_items(pages[i].html);
  for (std::size_t i = 0; i < pages.size(); ++i) {
    // The shared contents: each page's entries, linked into that page; this page's marked.
    // On a chapter page (class "pages") the style sheet folds the other chapters to their titles.
    std::string nav = kNavOpen + (i == 0 ? "" : " class=\"pages\"") + " role=\"doc-toc\">\n<ul>\n";
    for (std::size_t k = 0; k < pages.size(); ++k) {
      std::string part = rewrite_local_links(items[k], [&](const std::string& id) {
        return (k == i ? "" : pages[k].file) + "#" + id;
      });
      if (k == i) {
        const std::size_t li = part.find("<li>");
        if (li != std::string::npos) part.replace(li, 4, "<li class=\"current\">");
        const std::size_t a = part.find("<a href=");
        if (a != std::string::npos) part.replace(a, 8, "<a aria-current=\"page\" href=");
      }
      if (part.find("<li") == std::string::npos)  // a page without sections: its name alone
        part = "<li" + std::string(k == i ? " class=\"current\"" : "") + "><a href=\"" + pages[k].file + "\">" +
               pages[k].label + "</a></li>\n";
      nav += part;
    }
    nav += "</ul>\n</nav>";
    std::string& h = pages[i].html;
    // Links to another page's ids, outside the contents (which are replaced whole).
    h = rewrite_local_links(h, [&](const std::string& id) {
      if (ids[i].count(id)) return "#" + id;
      const auto it = home.find(id);
      return it == home.end() ? "#" + id : pages[it->second].file + "#" + id;
    });
    const auto [b, e] = toc_span(h);
    const std::string bar = i == 0 ? "" : page_bar(pages, i);
    if (b != std::string::npos) h.replace(b, e - b, nav + "\n" + bar);
    else {
      const std::size_t body = h.find("<body>");
      if (body != std::string::npos) h.insert(body + 6, "\n" + nav + "\n" + bar);
    }
    const std::size_t end = h.rfind("</body>");
    if (i > 0 && end != std::string::npos) h.insert(end, bar);
  }
}

}  // namespace drawbend::study
