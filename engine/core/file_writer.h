// core/file_writer.h — the one way arcfire writes a file: every write checked, atomic, one line.
//
// Frames, snapshots, goldens, hash logs, summaries, recordings' headers, bindings, settings,
// contact sheets and WAVs all go through FileWriter: the bytes go to a temporary file in the
// target's folder (so the rename stays on one file system), every write() and the close() are
// checked, and only a complete file is renamed over the target (through a symbolic link: over the
// link's target, beside which the temporary file is made). On any failure the temporary
// file is removed, the old target is left as it was, and WriteError says in one line which file
// and the system's reason ("out/frame_000030.png: cannot write: No space left on device").
// WriteError::exit_code is 2 when the path itself cannot be used (missing folder, no
// permission, a folder in the way) and 1 when a write failed on the way (disk full, I/O error).
//
// check_output_file() and check_output_dir() test a path before a run starts, so a bad --out,
// --summary or --record is refused before any tick is simulated.
//
// A full disk can be simulated anywhere: ARCFIRE_WRITE_LIMIT=N in the environment (or
// set_write_limit(N) in a test) makes every checked write beyond N bytes in all fail with
// ENOSPC, as a full disk would (tests/cli/full_disk.sh).
//
// Example, compiled as CoreExamples.WriteAFile in tests/unit/core/test_core_examples.cpp:
//   FileWriter out("out/summary.json");
//   out.write(text);
//   out.commit();  // renamed into place; without commit() the destructor removes the temporary
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

#include "core/error.h"

namespace arc {

struct WriteError : InputError {
  WriteError(const std::string& message, int code) : InputError(message), exit_code(code) {}
  int exit_code;  // kExitBadInput (the path cannot be used) or kExitCheckFailed (a write failed)
};

class FileWriter {
 public:
  // Creates the temporary file; WriteError when it cannot.
  explicit FileWriter(const std::string& path);
  FileWriter(const FileWriter&) = delete;
  FileWriter& operator=(const FileWriter&) = delete;
  ~FileWriter();  // not committed: the temporary file is closed and removed

  void write(const void* data, size_t size);
  void write(const std::string& bytes) { write(bytes.data(), bytes.size()); }
  // Closes the temporary file, checked; it is renamed (or removed) later. Writers staged this
  // way can be committed together once all of them are complete (--update-golden).
  void close();
  // Closes (checked) unless closed, and renames the temporary file over the target.
  void commit();
  const std::string& path() const { return path_; }

 private:
  void abandon() noexcept;

  std::string path_;    // as named, for messages
  std::string target_;  // what is replaced: a symbolic link's target, so the link stays a link
  std::string tmp_;
  int fd_ = -1;
};

// The whole of `bytes` to `path` through a FileWriter.
void write_file_checked(const std::string& path, const std::string& bytes);
// The same, with `before_rename` run between the write and the rename (tests throw from it to
// stand for a crash there: the old file stays whole); WriteError on failure.
void write_file_atomic(const std::string& path, const std::string& text,
                       const std::function<void()>& before_rename = {});

// Writes all of `size` bytes to an open descriptor (append-mode files such as recordings), under
// the same write limit; returns 0 or the errno of the failure.
int write_all(int fd, const void* data, size_t size);

// The system's reason for errno `err`, as the messages print it.
std::string system_reason(int err);

// WriteError (exit 2) unless a file can be created at `path`: its folder exists and is writable
// and `path` is not a folder. `option` names it in the message ("--summary").
void check_output_file(const std::string& path, const std::string& option);
// Creates `dir` when missing; WriteError (exit 2) unless files can be created in it.
void check_output_dir(const std::string& dir, const std::string& option);

// Every checked write beyond `bytes` in all (from now) fails with ENOSPC; UINT64_MAX = no limit.
void set_write_limit(uint64_t bytes);

}  // namespace arc
