#pragma once
// List-valued options (export's --parts and --rd-vector, loop's --export,
// model-loop's --candidates and their members): one reading for all of them.
// An empty item (a doubled, leading or trailing separator), white space in an
// item, an item given twice where the list is a set, and a number that is not
// a finite decimal are refused, naming the option and the item (before
// 2026-12-04 `--parts 1,2,` and `--parts ' 1, 2'` were taken, `--export
// lsdyna,lsdyna` wrote the file twice and `--candidates voce,voce` ran the
// candidate twice).  Errors are std::invalid_argument (exit 2).
#include <string>
#include <vector>

namespace drawbend {

/// The items of `text` separated by `sep`; `what` names the option in the
/// messages ("--parts", "--candidates 'split:0.3/0.6'").  `unique`: an item
/// given twice is refused.
std::vector<std::string> list_items(const std::string& text, const std::string& what, char sep = ',',
                                    bool unique = true);

/// The same, each item a finite decimal number (as the numeric options read
/// them: no hexadecimal, no NaN or infinity); `unique` compares the values.
std::vector<double> list_numbers(const std::string& text, const std::string& what, char sep = ',',
                                 bool unique = true);

}  // namespace drawbend
