#pragma once
// The one gate for files (issue 53), as parse_toml is the one gate for TOML:
// every file drawbend reads goes through read_input and every file it writes
// through write_output (core/csv.hpp's read_file and write_file_atomic call
// them), so the same rules hold at every entry point:
//
//  * Reading: only a regular file is read.  A folder, a device (/dev/zero), a
//    FIFO or a socket is refused from stat() before it is opened, and the file
//    is opened non-blocking and checked again with fstat(), so nothing can make
//    a read hang or fill the memory.  A file larger than its cap
//    (kMaxInputBytes unless the caller states another) is refused before it is
//    read.  Every message names the path and, when known, where the path came
//    from: the option or deck key registered with name_input (e.g.
//    "--hardening '/dev/zero': expected a regular file, found a device").
//  * Writing: the target must be missing or a regular file; a folder, FIFO or
//    device is never replaced.  The text goes to a temporary file in the same
//    folder (NAME.tmp<pid>.<n>, created exclusively), which is then renamed over
//    the target, so a reader sees the old file or the new one, never half of
//    one; on any failure the temporary file is removed.
//
// Every refusal is an InputError (exit 2 in the commands).
#include <cstdint>
#include <string>

namespace drawbend {

/// The cap of any input file: 512 MiB, some 30 times the largest input a user
/// sends (a 50,000-row loop file is under 10 MB; decks and tables are kB).
inline constexpr std::uintmax_t kMaxInputBytes = 512ull << 20;
/// The cap of a checkpoint (`run --restart`): 16 GiB, above the state of a run
/// at [limits] max_memory_mb's largest accepted value.
inline constexpr std::uintmax_t kMaxCheckpointBytes = 16ull << 30;

/// Remember that `path` was given as `origin` (an option such as "--hardening"
/// or a deck key such as "deck.toml:12: material.hardening"); read_input and
/// write_output then name the origin in their messages.
void name_input(const std::string& path, const std::string& origin);

/// "ORIGIN 'path'" when the path's origin is known, else "path".
std::string describe_path(const std::string& path);

/// The whole content of the regular file `path`; throws InputError naming the
/// path (and its origin) when it is missing, not a regular file, or larger than
/// `max_bytes`.
std::string read_input(const std::string& path, std::uintmax_t max_bytes = kMaxInputBytes);

/// Write `text` to `path` atomically; throws InputError naming the path when
/// the target is not a regular file or the write fails (nothing left behind).
void write_output(const std::string& path, const std::string& text);

/// Refuse an output file that this command has read as an input (core/provenance.hpp's
/// inputs_read: the same file by its canonical path): InputError "ORIGIN 'path': is also
/// an input of this command (...)" before anything is written (before 2026-12-04
/// `export m.toml --out m.toml` and `block-deck --hardening h.csv --out h.csv` replaced
/// the input with the output, exit 0).
void refuse_input_as_output(const std::string& path);

/// Text with every byte sequence that is not valid UTF-8 replaced by U+FFFD
/// (a Windows-1252 'µ' in a column name becomes '\uFFFD'): outputs are UTF-8.
std::string valid_utf8(const std::string& text);

/// At most `max_chars` bytes of `text` (cut at a UTF-8 boundary), with
/// "... (N bytes)" when it was cut: for echoing user text in messages.
std::string clip_for_message(const std::string& text, std::size_t max_chars = 80);

}  // namespace drawbend
