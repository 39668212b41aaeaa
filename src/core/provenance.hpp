#pragma once
// Provenance of a result: which input files a program read (with an FNV-1a
// hash of their contents) and which binary produced it.  read_csv and
// read_file note every file they read; a chapter writes the list to
// provenance.csv next to its results, and the report assembler compares the
// recorded hashes with the files as they are now, to mark a stale result.
//
// provenance.csv columns: kind,path,fnv1a64,bytes
//   kind = input (a file read), binary (the executable), version (git
//   describe at configure time; fnv1a64 and bytes empty).
#include <cstdint>
#include <string>
#include <vector>

namespace drawbend {

/// Record that `path` was read (thread-safe; duplicates kept once).
void note_input(const std::string& path);
/// Every file noted so far, in the order first read.
std::vector<std::string> inputs_read();

struct FileHash {
  bool exists = false;
  std::uint64_t hash = 0;
  std::uint64_t bytes = 0;
};
/// FNV-1a 64 of a file's contents (exists = false if it cannot be read).
FileHash hash_file(const std::string& path);

/// Write provenance.csv for the inputs read so far and this executable.
void write_provenance(const std::string& path, const std::string& version);

/// Compare a provenance.csv with the files as they are now: one line per
/// input or binary whose hash differs or that is gone (empty: up to date).
std::vector<std::string> stale_inputs(const std::string& provenance_csv);

}  // namespace drawbend
