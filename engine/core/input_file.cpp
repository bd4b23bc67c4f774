// core/input_file.cpp — opening, checking and reading input files (see input_file.h).
#include "core/input_file.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/error.h"
#include "core/input_limits.h"

namespace arc {
namespace {

// What a file of this type is, in the words of a message; empty for a regular file.
std::string type_name(mode_t mode) {
  if (S_ISREG(mode)) return "";
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

// What a failed stat or open of `path` says about it.
std::string errno_name(int err, const std::string& path) {
  switch (err) {
    case ENOENT: return "not found";
    case ENOTDIR: return "not found (a part of the path is not a folder)";
    case ELOOP: return "a symbolic link loop";
    case ENAMETOOLONG: return "a name longer than the system allows";
    case EACCES:
    case EPERM: return "permission denied";
    case EISDIR: return "a folder";
    case ENXIO: {  // open() of a socket, or of a device with nothing behind it
      struct stat st {};
      if (::stat(path.c_str(), &st) == 0 && S_ISSOCK(st.st_mode)) return "a socket";
      return "a device with nothing behind it";
    }
    default: return std::strerror(err);
  }
}

[[noreturn]] void refuse(const std::string& path, const std::string& what, const std::string& allowed) {
  throw InputError((path.empty() ? std::string("''") : path) + ": " + what + "; allowed: " + allowed);
}

std::string file_allowed(size_t max_bytes, const std::string& kind) {
  return "a regular file of at most " + byte_size_text(max_bytes) + " for " + kind;
}

// The path's own type before anything is opened, so a device is never opened at all; "" when
// it is a regular file.
std::string problem_before_open(const std::string& path) {
  if (path.empty()) return "an empty file name";
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return errno_name(errno, path);
  return type_name(st.st_mode);
}

void check_size(const std::string& path, uint64_t size, size_t max_bytes, const std::string& kind) {
  if (size > max_bytes)
    throw InputError(path + ": file is " + std::to_string(size) + " bytes; " + kind + " may be at most " +
                     byte_size_text(max_bytes));
}

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

std::string input_path_problem(const std::string& path) {
  if (std::string p = problem_before_open(path); !p.empty()) return p;
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) return errno_name(errno, path);
  struct stat st {};
  std::string p = ::fstat(fd, &st) != 0 ? errno_name(errno, path) : type_name(st.st_mode);
  ::close(fd);
  return p;
}

bool input_path_exists(const std::string& path) {
  if (path.empty()) return false;
  struct stat st {};
  if (::lstat(path.c_str(), &st) == 0) return true;
  return errno != ENOENT && errno != ENOTDIR;
}

InputFile::InputFile(const std::string& path, size_t max_bytes, const std::string& kind)
    : path_(path), kind_(kind), max_bytes_(max_bytes) {
  if (std::string p = problem_before_open(path); !p.empty()) refuse(path, p, file_allowed(max_bytes, kind));
  // Non-blocking: a FIFO swapped in after the stat opens at once and is refused below.
  fd_ = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd_ < 0) refuse(path, errno_name(errno, path), file_allowed(max_bytes, kind));
  struct stat st {};
  std::string p = ::fstat(fd_, &st) != 0 ? errno_name(errno, path) : type_name(st.st_mode);
  if (!p.empty()) {
    ::close(fd_);
    fd_ = -1;
    refuse(path, p, file_allowed(max_bytes, kind));
  }
  size_ = uint64_t(st.st_size);
  try {
    check_size(path, size_, max_bytes, kind);
  } catch (...) {
    ::close(fd_);
    fd_ = -1;
    throw;
  }
}

InputFile::~InputFile() {
  if (fd_ >= 0) ::close(fd_);
}

size_t InputFile::read_some(void* buf, size_t n) {
  for (;;) {
    const ssize_t got = ::read(fd_, buf, n);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw InputError(path_ + ": cannot read: " + std::strerror(errno));
    read_ += uint64_t(got);
    // A file that grows while it is read is bounded by the limit all the same.
    if (read_ > max_bytes_)
      throw InputError(path_ + ": grew past " + byte_size_text(max_bytes_) + " while it was read; " + kind_ +
                       " may be at most " + byte_size_text(max_bytes_));
    return size_t(got);
  }
}

std::string InputFile::read_all() {
  std::string out;
  // One byte more than the size at open, so the end is seen without a second allocation.
  out.resize(size_t(std::min<uint64_t>(size_, max_bytes_)) + 1);
  size_t used = 0;
  for (;;) {
    if (used == out.size()) out.resize(std::min(out.size() * 2, max_bytes_ + 1));
    const size_t got = read_some(out.data() + used, out.size() - used);
    if (got == 0) break;
    used += got;
  }
  out.resize(used);
  return out;
}

std::string read_input_file(const std::string& path, size_t max_bytes, const std::string& kind) {
  return InputFile(path, max_bytes, kind).read_all();
}

std::optional<std::string> read_optional_input_file(const std::string& path, size_t max_bytes,
                                                    const std::string& kind) {
  if (!input_path_exists(path)) return std::nullopt;
  return read_input_file(path, max_bytes, kind);
}

void check_input_path(const std::string& path, size_t max_bytes, const std::string& kind) {
  InputFile(path, max_bytes, kind);
}

void check_input_folder(const std::string& dir, const std::string& kind) {
  const std::string allowed = "a folder for " + kind;
  if (dir.empty()) refuse(dir, "an empty folder name", allowed);
  struct stat st {};
  if (::stat(dir.c_str(), &st) != 0) refuse(dir, errno_name(errno, dir), allowed);
  if (!S_ISDIR(st.st_mode)) refuse(dir, S_ISREG(st.st_mode) ? "a file" : type_name(st.st_mode), allowed);
}

std::vector<std::string> list_input_folder(const std::string& dir, const std::string& ext, const std::string& kind,
                                           bool optional, size_t max_entries) {
  if (optional && !input_path_exists(dir)) return {};
  check_input_folder(dir, kind);
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) refuse(dir, errno_name(errno, dir), "a folder for " + kind);
  DIR* d = ::fdopendir(fd);
  if (!d) {
    ::close(fd);
    refuse(dir, errno_name(errno, dir), "a folder for " + kind);
  }
  const std::string prefix = dir.back() == '/' ? dir : dir + "/";
  std::vector<std::string> out;
  size_t entries = 0;
  while (const dirent* e = ::readdir(d)) {
    const std::string name = e->d_name;
    if (name == "." || name == "..") continue;
    if (++entries > max_entries) {
      ::closedir(d);
      refuse(dir, "a folder of more than " + std::to_string(max_entries) + " entries", "a folder for " + kind);
    }
    if (!ext.empty() && !ends_with(name, ext)) continue;
    // Anything named like an input is listed, whatever it is, so its reader says what is wrong
    // with it; without an extension to go by, only what is not a folder.
    struct stat st {};
    if (ext.empty() && ::fstatat(::dirfd(d), e->d_name, &st, 0) == 0 && S_ISDIR(st.st_mode)) continue;
    out.push_back(prefix + name);
  }
  ::closedir(d);
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace arc
