#pragma once
// What spreadsheet programs write, read the same way by every CSV reader
// (core/csv.cpp's parse_csv and loop/measured.cpp's parse_measured), issue 53:
//
//  * encoding: UTF-8, with or without a byte-order mark.  UTF-16 and UTF-32
//    (a byte-order mark, or NUL bytes between the characters) are refused with
//    a message naming the encoding and how to save the file as UTF-8.  Text
//    that is not valid UTF-8 is read as Windows-1252 (what Excel writes on
//    Windows: 'µ' is the byte 0xB5) and converted, so every output stays UTF-8;
//    the readers say so in a note.
//  * records: RFC 4180 — a quoted cell may hold line breaks; the record then
//    spans several lines and is numbered by its first line.
//  * trailing empty columns (Excel keeps a formatted but empty column): empty
//    cells after the last header name are dropped, from the header and from
//    every row.
//  * separators: ',' is read everywhere; the loop's reader also reads ';' (with
//    decimal commas) and tab; parse_csv names them and refuses (see
//    separator_message).
#include <istream>
#include <string>
#include <vector>

namespace drawbend {

/// `text` as UTF-8 without a byte-order mark; throws InputError naming `path`
/// and the encoding for UTF-16/UTF-32; Windows-1252 text is converted, and
/// `note` (if given) then says so.
std::string csv_text_utf8(const std::string& text, const std::string& path, std::string* note = nullptr);

/// The next record of a CSV stream (physical lines joined while a quote is
/// open, line ends '\r' removed); `lineno` counts physical lines, `first` is
/// the record's first line.  False at the end of the stream.
bool next_csv_record(std::istream& in, std::string& record, int& lineno, int& first);

/// Whether a header split at ',' is one cell holding a tab (a tab-separated file).
bool tab_header(const std::vector<std::string>& cells);

/// Drop the empty cells after the first `keep` cells (trailing empty columns);
/// cells beyond `keep` that are not empty are kept (a ragged row).
void drop_trailing_empty(std::vector<std::string>& cells, std::size_t keep);

/// Header cells without the empty ones at its end.
void trim_trailing_empty_header(std::vector<std::string>& header);

}  // namespace drawbend
