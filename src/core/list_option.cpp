#include "core/list_option.hpp"

#include <cctype>
#include <cmath>
#include <stdexcept>

#include "core/csv.hpp"
#include "core/file_gate.hpp"

namespace drawbend {

std::vector<std::string> list_items(const std::string& text, const std::string& what, char sep, bool unique) {
  const std::string shown = "'" + clip_for_message(text) + "'";
  if (text.empty()) throw std::invalid_argument(what + ": expected a list separated by '" + std::string(1, sep) + "', found an empty value");
  std::vector<std::string> items;
  std::size_t pos = 0;
  for (;;) {
    const std::size_t end = text.find(sep, pos);
    const std::string item = text.substr(pos, end == std::string::npos ? std::string::npos : end - pos);
    const std::size_t n = items.size() + 1;
    if (item.empty())
      throw std::invalid_argument(what + ": item " + std::to_string(n) + " of " + shown + " is empty (" +
                                  (n == 1 ? "a leading" : end == std::string::npos ? "a trailing" : "a doubled") +
                                  " '" + std::string(1, sep) + "')");
    for (char ch : item)
      if (std::isspace(static_cast<unsigned char>(ch)))
        throw std::invalid_argument(what + ": item " + std::to_string(n) + " '" + clip_for_message(item) + "' of " +
                                    shown + " holds white space (write the list without spaces)");
    if (unique)
      for (std::size_t k = 0; k < items.size(); ++k)
        if (items[k] == item)
          throw std::invalid_argument(what + ": '" + clip_for_message(item) + "' is given twice in " + shown +
                                      " (items " + std::to_string(k + 1) + " and " + std::to_string(n) + ")");
    items.push_back(item);
    if (end == std::string::npos) break;
    pos = end + 1;
  }
  return items;
}

std::vector<double> list_numbers(const std::string& text, const std::string& what, char sep, bool unique) {
  const std::vector<std::string> items = list_items(text, what, sep, false);
  std::vector<double> v;
  for (std::size_t k = 0; k < items.size(); ++k) {
    const std::string& item = items[k];
    std::size_t used = 0;
    double x = NAN;
    try {
      x = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != item.size() || hex_number(item) || !std::isfinite(x))
      throw std::invalid_argument(what + ": item " + std::to_string(k + 1) + " '" + clip_for_message(item) + "' of '" +
                                  clip_for_message(text) + "' is not a finite number");
    if (unique)
      for (std::size_t j = 0; j < v.size(); ++j)
        if (v[j] == x)
          throw std::invalid_argument(what + ": the value " + fmt_shortest(x) + " is given twice in '" +
                                      clip_for_message(text) + "' (items " + std::to_string(j + 1) + " and " +
                                      std::to_string(k + 1) + ")");
    v.push_back(x);
  }
  return v;
}

}  // namespace drawbend
