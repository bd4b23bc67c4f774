// core/input_file.h — the one way every loader opens an input file: checked, then read with a bound.
//
// A path may name anything: a folder, a FIFO that never delivers a byte, /dev/zero that never
// ends, a symbolic link to itself, a name longer than the system allows. Every input goes
// through here, so each of those is one line (an InputError) at once, never a hang, an abort or
// a read without end:
//   LOOP: a symbolic link loop; allowed: a regular file (a level)
//   pipe: a FIFO (named pipe); allowed: a regular file (a replay script)
// The file is opened non-blocking (a FIFO's open returns at once), its type and size are taken
// from the open descriptor (no gap between the check and the read), and the read stops one byte
// past the limit, so a file that grows while read is refused rather than filling memory.
// Paths are examined with system calls and std::error_code only; nothing here throws anything
// but InputError.
//
// Example, compiled as CoreExamples.ReadAnInputFile in tests/unit/core/test_core_examples.cpp:
//   std::string text = read_input_file("levels/duel.json", kMaxDataFileBytes, "a level");
//   check_input_path("assets/textures/hull_dart.png", kMaxImageFileBytes, "an image");
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace arc {

// What `path` names when it is not a regular file that can be opened for reading: "not found",
// "a folder", "a FIFO (named pipe)", "a character device", "a block device", "a socket",
// "a symbolic link loop", "a name longer than the system allows", "permission denied", ...
// Empty for a readable regular file. Never throws.
std::string input_path_problem(const std::string& path);

// Whether `path` names anything at all, even something a reader will refuse (a dangling link or
// a loop counts): so an optional file that is there but wrong is reported, not skipped.
bool input_path_exists(const std::string& path);

// The whole content of `path`, a regular file of at most `max_bytes`. `kind` names what the file
// should be for the message ("a level", "a replay script"). Throws InputError
// "path: WHAT; allowed: a regular file (KIND)" or "path: file is N bytes; KIND may be at most M".
std::string read_input_file(const std::string& path, size_t max_bytes, const std::string& kind);

// The same for an optional file: nothing at `path` gives nullopt; anything else wrong throws.
std::optional<std::string> read_optional_input_file(const std::string& path, size_t max_bytes,
                                                    const std::string& kind);

// The same checks without keeping the bytes, for a library that opens the path itself.
void check_input_path(const std::string& path, size_t max_bytes, const std::string& kind);

// A file read in pieces (hashing a mod's files): the same checks at open; read_some() returns
// 0 at the end and throws once more than `max_bytes` have come.
class InputFile {
 public:
  InputFile(const std::string& path, size_t max_bytes, const std::string& kind);
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  uint64_t size() const { return size_; }  // at open
  size_t read_some(void* buf, size_t n);
  std::string read_all();

 private:
  int fd_ = -1;
  std::string path_;
  std::string kind_;
  size_t max_bytes_;
  uint64_t size_ = 0;
  uint64_t read_ = 0;
};

// The regular files directly in folder `dir` (full paths, sorted), those ending in `ext` when it
// is not empty. A folder that is not there gives an empty list when `optional`; one that is a
// loop, a file, unreadable or holds more than `max_entries` entries throws one line.
std::vector<std::string> list_input_folder(const std::string& dir, const std::string& ext, const std::string& kind,
                                           bool optional, size_t max_entries = 100000);

// Throws when `dir` is not a folder that can be listed ("path: a symbolic link loop; allowed: a
// folder (KIND)"); quiet for a folder.
void check_input_folder(const std::string& dir, const std::string& kind);

}  // namespace arc
