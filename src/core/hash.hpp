#pragma once
// FNV-1a, 64 bit: a fast, dependency-free fingerprint of file contents for
// provenance records and checkpoint/deck matching (not a cryptographic hash).
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace drawbend {

inline std::uint64_t fnv1a64(std::string_view data, std::uint64_t h = 0xcbf29ce484222325ULL) {
  for (const unsigned char c : data) {
    h ^= c;
    h *= 0x100000001b3ULL;
  }
  return h;
}

/// 16 lower-case hex digits.
inline std::string hex64(std::uint64_t h) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

}  // namespace drawbend
