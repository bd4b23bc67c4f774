#include "core/input_limits.h"

#include <sys/stat.h>
#include <vector>

#include "core/error.h"

namespace arc {
namespace {

std::string where(const char* text, size_t size, size_t offset, const std::string& path) {
  int line = 1, col = 1;
  for (size_t i = 0; i < offset && i < size; ++i) {
    if (text[i] == '\n') { ++line; col = 1; }
    else ++col;
  }
  return path + ":" + std::to_string(line) + ":" + std::to_string(col);
}

size_t digits(size_t n) {
  size_t d = 1;
  while (n >= 10) { n /= 10; ++d; }
  return d;
}

// One open array or object on the way from the root to the scanner's position.
struct Frame {
  bool is_array;
  size_t pointer_bytes;  // of the container itself
  size_t index = 0;      // arrays: the element being read
  bool expect_key = true;  // objects: the next string is a key
  size_t key_bytes = 0;    // objects: the last key read
};

class JsonScanner {
 public:
  JsonScanner(const char* text, size_t size, const std::string& path, const JsonLimits& limits)
      : t_(text), n_(size), path_(path), lim_(limits) {}

  void run() {
    while (i_ < n_) {
      const char c = t_[i_];
      if (c == '"') string();
      else if (c == '/' && i_ + 1 < n_ && (t_[i_ + 1] == '/' || t_[i_ + 1] == '*')) comment();
      else {
        structural(c);
        ++i_;
      }
    }
  }

 private:
  [[noreturn]] void fail(size_t at, const std::string& what) const {
    throw InputError(where(t_, n_, at, path_) + ": " + what);
  }

  // The pointer length of the value starting here: its container's, a slash and its name.
  size_t child_pointer_bytes() const {
    if (stack_.empty()) return 0;
    const Frame& f = stack_.back();
    return f.pointer_bytes + 1 + (f.is_array ? digits(f.index) : f.key_bytes);
  }

  void check_pointer(size_t bytes, size_t at) {
    if (bytes > lim_.max_pointer_bytes)
      fail(at, "the path to this value (keys and indices from the top, like /ships/3/position) is longer than " +
                   std::to_string(lim_.max_pointer_bytes) + " characters, the limit for " + lim_.kind);
    // The position recorder keeps every value's path: their sum bounds its memory.
    pointer_total_ += bytes;
    if (pointer_total_ > lim_.max_pointer_total_bytes)
      fail(at, "the paths to all values (keys and indices from the top) add up to more than " +
                   std::to_string(lim_.max_pointer_total_bytes >> 20) + " MiB, the limit for " + lim_.kind);
  }

  void structural(char c) {
    if (c == '{' || c == '[') {
      if (int(stack_.size()) >= lim_.max_depth)
        fail(i_, "arrays and objects nested deeper than " + std::to_string(lim_.max_depth) + " levels; " +
                     lim_.kind + " may nest at most " + std::to_string(lim_.max_depth));
      const size_t bytes = child_pointer_bytes();
      check_pointer(bytes, i_);
      count_value();
      if (c == '{' && ++objects_ > lim_.max_objects)
        fail(i_, "more than " + std::to_string(lim_.max_objects) + " objects; " + lim_.kind + " may hold at most " +
                     std::to_string(lim_.max_objects));
      stack_.push_back(Frame{c == '[', bytes});
    } else if ((c == '}' || c == ']') && !stack_.empty()) {
      stack_.pop_back();
    } else if (c == ',' && !stack_.empty()) {
      count_value();
      Frame& f = stack_.back();
      if (f.is_array) check_pointer(f.pointer_bytes + 1 + digits(++f.index), i_);
      else f.expect_key = true;
    }
  }

  void count_value() {
    if (++values_ > lim_.max_values)
      fail(i_, "more than " + std::to_string(lim_.max_values) + " values; " + lim_.kind + " may hold at most " +
                   std::to_string(lim_.max_values) + " (arrays, objects and their elements)");
  }

  void string() {
    const size_t start = i_++;
    while (i_ < n_ && t_[i_] != '"') i_ += t_[i_] == '\\' ? 2 : 1;
    const size_t end = i_ < n_ ? i_ : n_;
    const size_t bytes = end - start - 1;
    ++i_;
    if (bytes > lim_.max_string_bytes)
      fail(start, "a string of " + std::to_string(bytes) + " bytes; strings in " + lim_.kind + " may be at most " +
                      std::to_string(lim_.max_string_bytes) + " bytes long");
    if (stack_.empty() || stack_.back().is_array || !stack_.back().expect_key) return;
    Frame& f = stack_.back();
    f.expect_key = false;
    f.key_bytes = bytes;
    check_pointer(f.pointer_bytes + 1 + bytes, start);
  }

  void comment() {
    if (t_[i_ + 1] == '/') {
      while (i_ < n_ && t_[i_] != '\n') ++i_;
      return;
    }
    i_ += 2;
    while (i_ + 1 < n_ && !(t_[i_] == '*' && t_[i_ + 1] == '/')) ++i_;
    i_ += 2;
  }

  const char* t_;
  size_t n_;
  const std::string& path_;
  const JsonLimits& lim_;
  size_t i_ = 0;
  size_t objects_ = 0;
  size_t values_ = 0;
  size_t pointer_total_ = 0;
  std::vector<Frame> stack_;
};

}  // namespace

std::string byte_size_text(size_t bytes) {
  if (bytes >= (size_t(1) << 20) && bytes % (size_t(1) << 20) == 0) return std::to_string(bytes >> 20) + " MiB";
  if (bytes >= (size_t(1) << 10) && bytes % (size_t(1) << 10) == 0) return std::to_string(bytes >> 10) + " KiB";
  return std::to_string(bytes) + " bytes";
}

void check_file_size(const std::string& path, size_t max_bytes, const std::string& what) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return;
  if (uint64_t(st.st_size) > max_bytes)
    throw InputError(path + ": file is " + std::to_string(uint64_t(st.st_size)) + " bytes; " + what + " may be at most " +
                     byte_size_text(max_bytes));
}

void check_text_size(size_t size, const std::string& path, size_t max_bytes, const std::string& what) {
  if (size > max_bytes)
    throw InputError(path + ": " + std::to_string(size) + " bytes; " + what + " may be at most " + byte_size_text(max_bytes));
}

void check_json_text(const char* text, size_t size, const std::string& path, const JsonLimits& limits) {
  check_text_size(size, path, limits.max_bytes, limits.kind);
  JsonScanner(text, size, path, limits).run();
}

}  // namespace arc
