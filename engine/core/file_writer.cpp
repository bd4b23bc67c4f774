// The checked, atomic file writer (core/file_writer.h).
#include "core/file_writer.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>

namespace arc {
namespace {

namespace fs = std::filesystem;

constexpr uint64_t kNoLimit = std::numeric_limits<uint64_t>::max();

uint64_t limit_from_environment() {
  const char* text = std::getenv("ARCFIRE_WRITE_LIMIT");
  if (!text || !*text) return kNoLimit;
  char* end = nullptr;
  const unsigned long long v = std::strtoull(text, &end, 10);
  return end && *end == '\0' ? uint64_t(v) : kNoLimit;
}

// Bytes the checked writes may still write before they fail as a full disk would.
std::atomic<uint64_t>& bytes_left() {
  static std::atomic<uint64_t> left{limit_from_environment()};
  return left;
}

// How many of `want` bytes the limit allows now (taken from it).
size_t take_allowance(size_t want) {
  std::atomic<uint64_t>& left = bytes_left();
  uint64_t have = left.load();
  for (;;) {
    if (have == kNoLimit) return want;
    const uint64_t grant = std::min<uint64_t>(have, want);
    if (left.compare_exchange_weak(have, have - grant)) return size_t(grant);
  }
}

// Errors that say the path cannot be used at all (bad input, exit 2) rather than that a write
// failed on the way (exit 1).
bool path_unusable(int err) {
  return err == EACCES || err == EPERM || err == EROFS || err == ENOENT || err == ENOTDIR || err == EISDIR ||
         err == ENAMETOOLONG || err == ELOOP;
}

int exit_code_for(int err) { return path_unusable(err) ? kExitBadInput : kExitCheckFailed; }

std::string temporary_name(const std::string& path) { return path + ".tmp." + std::to_string(::getpid()); }

std::string folder_of(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

// Creates and removes a file at `probe`; 0 or the errno of the failure.
int probe_create(const std::string& probe) {
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) return errno;
  ::close(fd);
  ::unlink(probe.c_str());
  return 0;
}

}  // namespace

std::string system_reason(int err) { return std::strerror(err); }

void set_write_limit(uint64_t bytes) { bytes_left().store(bytes); }

int write_all(int fd, const void* data, size_t size) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const size_t allowed = take_allowance(size);
    if (allowed == 0) return ENOSPC;
    const ssize_t n = ::write(fd, p, allowed);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    if (n == 0) return EIO;
    p += n;
    size -= size_t(n);
  }
  return 0;
}

// The file a write to `path` replaces: a symbolic link's target (the link stays a link), else
// `path` itself. A link loop or a name too long is the path's error, as opening it would be.
static std::string write_target(const std::string& path) {
  fs::path p(path);
  for (int hops = 0; hops < 40; ++hops) {
    struct stat st {};
    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p.string();
    std::error_code ec;
    const fs::path next = fs::read_symlink(p, ec);
    if (ec) throw WriteError(path + ": cannot write: " + ec.message(), kExitBadInput);
    p = next.is_absolute() ? next : p.parent_path() / next;
  }
  throw WriteError(path + ": cannot write: " + system_reason(ELOOP), kExitBadInput);
}

FileWriter::FileWriter(const std::string& path)
    : path_(path), target_(write_target(path)), tmp_(temporary_name(target_)) {
  std::error_code ec;
  if (fs::is_directory(target_, ec)) throw WriteError(path + ": cannot write: it is a folder", kExitBadInput);
  fd_ = ::open(tmp_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd_ < 0) {
    const int err = errno;
    throw WriteError(path + ": cannot write: " + system_reason(err) + " (folder " + folder_of(target_) + ")",
                     exit_code_for(err));
  }
}

FileWriter::~FileWriter() { abandon(); }

void FileWriter::abandon() noexcept {
  if (tmp_.empty()) return;
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  ::unlink(tmp_.c_str());
  tmp_.clear();
}

void FileWriter::write(const void* data, size_t size) {
  if (fd_ < 0) throw WriteError(path_ + ": cannot write: the file is already closed", kExitCheckFailed);
  if (const int err = write_all(fd_, data, size)) {
    abandon();
    throw WriteError(path_ + ": cannot write: " + system_reason(err), kExitCheckFailed);
  }
}

void FileWriter::close() {
  if (fd_ < 0) return;
  const int closed = ::close(fd_);
  const int close_err = errno;
  fd_ = -1;
  if (closed != 0) {
    abandon();
    throw WriteError(path_ + ": cannot write: " + system_reason(close_err), kExitCheckFailed);
  }
}

void FileWriter::commit() {
  if (tmp_.empty()) throw WriteError(path_ + ": cannot write: the file was abandoned", kExitCheckFailed);
  close();
  if (std::rename(tmp_.c_str(), target_.c_str()) != 0) {
    const int err = errno;
    abandon();
    throw WriteError(path_ + ": cannot replace the file: " + system_reason(err), exit_code_for(err));
  }
  tmp_.clear();
}

void write_file_checked(const std::string& path, const std::string& bytes) { write_file_atomic(path, bytes); }

void write_file_atomic(const std::string& path, const std::string& text, const std::function<void()>& before_rename) {
  FileWriter out(path);
  out.write(text);
  if (before_rename) before_rename();  // a throw here leaves the old file: ~FileWriter removes the temporary
  out.commit();
}

void check_output_file(const std::string& path, const std::string& option) {
  const std::string what = option.empty() ? path : option + " " + path;
  if (path.empty()) throw WriteError(option + ": needs a file name", kExitBadInput);
  const std::string target = write_target(path);
  std::error_code ec;
  if (fs::is_directory(target, ec)) throw WriteError(what + ": is a folder, not a file", kExitBadInput);
  const std::string folder = folder_of(target);
  if (!fs::is_directory(folder, ec)) throw WriteError(what + ": folder " + folder + " does not exist", kExitBadInput);
  if (const int err = probe_create(temporary_name(target)))
    throw WriteError(what + ": cannot write: " + system_reason(err), kExitBadInput);
}

void check_output_dir(const std::string& dir, const std::string& option) {
  const std::string what = option.empty() ? dir : option + " " + dir;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir, ec))
    throw WriteError(what + ": cannot create folder (" + (ec ? ec.message() : std::string("a file is in the way")) +
                         ")",
                     kExitBadInput);
  const std::string probe = (fs::path(dir) / (".arcfire-probe." + std::to_string(::getpid()))).string();
  if (const int err = probe_create(probe))
    throw WriteError(what + ": cannot write in this folder: " + system_reason(err), kExitBadInput);
}

}  // namespace arc
