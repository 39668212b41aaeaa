#pragma once
// The report as one page per chapter (issue 55, item 4): the front page is
// the index, each chapter a page of its own, all sharing one contents sidebar
// that lists every chapter and its sections (nav#TOC, kept in view by
// report/style.css) and a bar to the previous chapter, the front page and the
// next chapter at the top and bottom of each chapter page.
//
// Works on the HTML Pandoc wrote for each page on its own (with --toc):
//  - every page's contents are replaced by the union of all pages' contents,
//    the page's own entry marked (<li class="current">, <a aria-current="page">);
//    on a chapter page the nav has class "pages" (the style sheet shows the
//    other chapters by their titles only; the front page lists every section);
//  - a link href="#id" to an id that is not on its page but on another
//    becomes href="other.html#id" (the front page's links to the checks
//    tables and figures of each chapter); a link to an id on no page is left
//    as it is (report/check_html.py --links reports it).
// Pure text in, text out: no file is read or written here.
#include <string>
#include <vector>

namespace drawbend::study {

struct HtmlPage {
  std::string file;   ///< its file name in the pages folder, e.g. "ch5-measured.html"
  std::string label;  ///< how the page bar names it, e.g. "Chapter 5"
  std::string html;   ///< Pandoc's standalone HTML; rewritten in place by link_pages
};

/// Every id="..." of the page, in order.
std::vector<std::string> html_ids(const std::string& html);

/// The list items of the page's contents (the inside of nav#TOC's outer <ul>),
/// empty when the page has no contents.
std::string toc_items(const std::string& html);

/// Link the pages (pages[0] is the front page, the index): the shared
/// contents, the cross-page links and the page bars, as in the header above.
void link_pages(std::vector<HtmlPage>& pages);

}  // namespace drawbend::study
