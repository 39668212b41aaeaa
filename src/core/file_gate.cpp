#include "core/file_gate.hpp"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <map>
#include <mutex>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/csv.hpp"
#include "core/provenance.hpp"

namespace drawbend {

namespace gate_detail {
std::mutex g_names_mutex;
std::map<std::string, std::string>& names() {
  static std::map<std::string, std::string> m;
  return m;
}

/// What a stat mode is, for messages ("a folder", "a FIFO (named pipe)").
const char* kind_of(mode_t m) {
  if (S_ISDIR(m)) return "a folder";
  if (S_ISFIFO(m)) return "a FIFO (named pipe)";
  if (S_ISCHR(m) || S_ISBLK(m)) return "a device";
  if (S_ISSOCK(m)) return "a socket";
  return "not a regular file";
}

std::string mib(std::uintmax_t bytes) { return fmt(static_cast<double>(bytes) / (1 << 20), 4) + " MiB"; }

/// Closes a file descriptor at the end of a scope.
struct Fd {
  int fd = -1;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};
}  // namespace gate_detail
using namespace gate_detail;

void name_input(const std::string& path, const std::string& origin) {
  if (path.empty()) return;
  std::lock_guard<std::mutex> lock(g_names_mutex);
  names()[path] = origin;
}

std::string describe_path(const std::string& path) {
  std::lock_guard<std::mutex> lock(g_names_mutex);
  const auto it = names().find(path);
  return it == names().end() ? path : it->second + " '" + path + "'";
}

std::string read_input(const std::string& path, std::uintmax_t max_bytes) {
  const std::string who = describe_path(path);
  if (path.empty()) throw InputError(who + ": expected a file name, found an empty one");
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    throw InputError(who + ": cannot open file for reading (" + std::strerror(errno) + ")");
  if (!S_ISREG(st.st_mode)) throw InputError(who + ": expected a regular file, found " + kind_of(st.st_mode));
  if (static_cast<std::uintmax_t>(st.st_size) > max_bytes)
    throw InputError(who + ": the file is " + mib(static_cast<std::uintmax_t>(st.st_size)) +
                     ", above the limit of " + mib(max_bytes) + " for an input file");
  // Non-blocking: were the path swapped for a FIFO after stat(), open() still returns at once.
  Fd f{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (f.fd < 0) throw InputError(who + ": cannot open file for reading (" + std::strerror(errno) + ")");
  if (::fstat(f.fd, &st) != 0 || !S_ISREG(st.st_mode))
    throw InputError(who + ": expected a regular file, found " + kind_of(st.st_mode));
  std::string text;
  text.reserve(static_cast<std::size_t>(st.st_size));
  char buf[1 << 16];
  for (;;) {
    const ssize_t n = ::read(f.fd, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw InputError(who + ": read failed (" + std::strerror(errno) + ")");
    if (n == 0) break;
    text.append(buf, static_cast<std::size_t>(n));
    if (text.size() > max_bytes)  // the file grew while being read
      throw InputError(who + ": the file is above the limit of " + mib(max_bytes) + " for an input file");
  }
  note_input(path);
  return text;
}

namespace gate_detail {
/// Whether a file is text by its name: text outputs are made valid UTF-8.
bool text_output(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  for (const char* e : {".md", ".csv", ".json", ".toml", ".txt", ".dat", ".svg", ".gp", ".k", ".rad", ".inp", ".log",
                        ".html"})
    if (ext == e) return true;
  return false;
}
}  // namespace gate_detail

void write_output(const std::string& path, const std::string& text_in) {
  namespace fs = std::filesystem;
  // Every text output is valid UTF-8, whatever bytes the inputs' names held.
  const std::string text = text_output(path) ? valid_utf8(text_in) : text_in;
  const std::string who = describe_path(path);
  if (path.empty()) throw InputError("expected an output file name, found an empty one");
  // "dir/": a folder's name, not a file's (the folder was made, then "cannot replace the file (Not a
  // directory)", before 2026-12-05).
  if (path.back() == '/') throw InputError(who + ": expected a file name, found a folder's (it ends in '/')");
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
    throw InputError(who + ": cannot write the output there: it is " + kind_of(st.st_mode) +
                     ", which is never replaced by a file");
  const fs::path target(path);
  if (target.has_parent_path()) {
    std::error_code ec;
    fs::create_directories(target.parent_path(), ec);
    if (ec) throw InputError(who + ": cannot create the folder '" + target.parent_path().string() + "': " + ec.message());
  }
  // The temporary name carries the process id and a counter: two programs (or
  // two threads) writing the same output cannot clobber each other's half-file.
  static std::atomic<unsigned> counter{0};
  const std::string tmp = path + ".tmp" + std::to_string(::getpid()) + "." + std::to_string(counter++);
  Fd f{::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666)};
  if (f.fd < 0) throw InputError(who + ": cannot open file for writing (" + std::strerror(errno) + ")");
  auto fail = [&](const std::string& what) {
    const std::string reason = std::strerror(errno);
    ::close(f.fd);
    f.fd = -1;
    ::unlink(tmp.c_str());
    throw InputError(who + ": " + what + " (" + reason + ")");
  };
  for (std::size_t done = 0; done < text.size();) {
    const ssize_t n = ::write(f.fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail("write failed (disk full?)");
    done += static_cast<std::size_t>(n);
  }
  if (::close(f.fd) != 0) {
    f.fd = -1;
    const std::string reason = std::strerror(errno);
    ::unlink(tmp.c_str());
    throw InputError(who + ": write failed (" + reason + ")");
  }
  f.fd = -1;
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    ::unlink(tmp.c_str());
    throw InputError(who + ": cannot replace the file (" + reason + ")");
  }
}

void refuse_input_as_output(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path target = fs::weakly_canonical(fs::absolute(path, ec), ec);
  if (ec) return;  // write_output names what is wrong with the path
  for (const std::string& in : inputs_read()) {
    std::error_code ec2;
    if (fs::path(in) == target || (fs::exists(target, ec2) && fs::equivalent(fs::path(in), target, ec2)))
      throw InputError(describe_path(path) + ": is also an input of this command (read as '" + in +
                       "'); writing there would replace it: choose another file");
  }
}

std::string valid_utf8(const std::string& s) {
  bool ascii = true;  // the common case, one fast pass and no copy
  for (const char c : s) ascii = ascii && static_cast<unsigned char>(c) < 0x80;
  if (ascii) return s;
  std::string out;
  out.reserve(s.size());
  const auto* p = reinterpret_cast<const unsigned char*>(s.data());
  const std::size_t n = s.size();
  for (std::size_t i = 0; i < n;) {
    const unsigned c = p[i];
    std::size_t len = 0;
    unsigned cp = 0;
    if (c < 0x80) len = 1, cp = c;
    else if (c >= 0xC2 && c <= 0xDF) len = 2, cp = c & 0x1F;
    else if (c >= 0xE0 && c <= 0xEF) len = 3, cp = c & 0x0F;
    else if (c >= 0xF0 && c <= 0xF4) len = 4, cp = c & 0x07;
    bool ok = len > 0 && i + len <= n;
    for (std::size_t k = 1; ok && k < len; ++k) {
      if ((p[i + k] & 0xC0) != 0x80) ok = false;
      cp = (cp << 6) | (p[i + k] & 0x3F);
    }
    // Overlong forms, surrogates and code points above U+10FFFF are not UTF-8.
    if (ok && ((len == 3 && (cp < 0x800 || (cp >= 0xD800 && cp <= 0xDFFF))) || (len == 4 && (cp < 0x10000 || cp > 0x10FFFF))))
      ok = false;
    if (ok) {
      out.append(s, i, len);
      i += len;
    } else {
      out += "\xEF\xBF\xBD";  // U+FFFD
      ++i;
    }
  }
  return out;
}

std::string clip_for_message(const std::string& text, std::size_t max_chars) {
  if (text.size() <= max_chars) return text;
  std::size_t cut = max_chars;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
  return text.substr(0, cut) + "... (" + std::to_string(text.size()) + " bytes)";
}

}  // namespace drawbend
