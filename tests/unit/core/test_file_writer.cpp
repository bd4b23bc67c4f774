// The checked writer (core/file_writer.h): a write that fails on the way (the disk full, here
// through set_write_limit) leaves the old file and no temporary one, and says which file and why;
// a path that cannot be used is exit 2, a failed write exit 1.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <string>

#include "core/file_writer.h"
#include "core/json.h"

namespace fs = std::filesystem;
using arc::WriteError;

namespace {

fs::path fresh_dir(const std::string& name) {
  fs::path d = fs::path(testing::TempDir()) / ("arcfire-writer-" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

int files_in(const fs::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

// The WriteError `f` throws, or a failure.
WriteError error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const WriteError& e) {
    return e;
  }
  ADD_FAILURE() << "no WriteError";
  return WriteError("", 0);
}

struct NoWriteLimit {
  ~NoWriteLimit() { arc::set_write_limit(std::numeric_limits<uint64_t>::max()); }
};

}  // namespace

TEST(FileWriter, FullDiskKeepsTheOldFileAndLeavesNoTemporary) {
  const fs::path dir = fresh_dir("full");
  const fs::path file = dir / "summary.json";
  arc::write_file_checked(file.string(), "old contents\n");
  NoWriteLimit restore;
  arc::set_write_limit(10);
  const WriteError e = error_of([&] { arc::write_file_checked(file.string(), std::string(4096, 'x')); });
  EXPECT_EQ(e.exit_code, arc::kExitCheckFailed);
  EXPECT_EQ(std::string(e.what()), file.string() + ": cannot write: No space left on device");
  EXPECT_EQ(read(file), "old contents\n");
  EXPECT_EQ(files_in(dir), 1) << "the temporary file must be gone";
}

TEST(FileWriter, AtomicWriteReplacesWholeFile) {
  std::string p = testing::TempDir() + "/atomic.json";
  arc::write_file_atomic(p, "{\"a\": 1}");
  arc::write_file_atomic(p, "{\"a\": 2}");
  EXPECT_EQ(arc::read_text_file(p), "{\"a\": 2}");
}

// A write through a symbolic link (a chain of them, or one to a file not there yet) replaces the
// target, beside which the temporary file is made: the link stays a link.
TEST(FileWriter, WritesThroughASymbolicLink) {
  const fs::path dir = fresh_dir("link");
  fs::create_directories(dir / "real");
  arc::write_file_atomic((dir / "real" / "f.txt").string(), "old\n");
  fs::create_symlink("real/f.txt", dir / "link.txt");
  fs::create_symlink("link.txt", dir / "link2.txt");
  arc::write_file_atomic((dir / "link2.txt").string(), "new\n");
  EXPECT_TRUE(fs::is_symlink(dir / "link.txt"));
  EXPECT_TRUE(fs::is_symlink(dir / "link2.txt"));
  EXPECT_EQ(read(dir / "real" / "f.txt"), "new\n");
  EXPECT_EQ(files_in(dir / "real"), 1) << "the temporary file must be gone";
  fs::create_symlink("real/g.txt", dir / "dangling.txt");
  arc::write_file_atomic((dir / "dangling.txt").string(), "g\n");
  EXPECT_TRUE(fs::is_symlink(dir / "dangling.txt"));
  EXPECT_EQ(read(dir / "real" / "g.txt"), "g\n");
  fs::create_symlink("loop.txt", dir / "loop.txt");
  EXPECT_EQ(error_of([&] { arc::write_file_atomic((dir / "loop.txt").string(), "x"); }).exit_code, arc::kExitBadInput);
}

TEST(FileWriter, AtomicWriteIsCheckedToo) {
  const fs::path dir = fresh_dir("atomic");
  const fs::path file = dir / "bindings.json";
  arc::write_file_atomic(file.string(), "{}");
  NoWriteLimit restore;
  arc::set_write_limit(1);
  EXPECT_EQ(error_of([&] { arc::write_file_atomic(file.string(), "{\"a\": 1}"); }).exit_code, arc::kExitCheckFailed);
  EXPECT_EQ(read(file), "{}");
  EXPECT_EQ(files_in(dir), 1);
}

TEST(FileWriter, UncommittedWriterRemovesItsTemporary) {
  const fs::path dir = fresh_dir("abandon");
  {
    arc::FileWriter w((dir / "frame.png").string());
    w.write("half a frame");
  }
  EXPECT_EQ(files_in(dir), 0);
}

TEST(FileWriter, UnusablePathsAreExitTwo) {
  const fs::path dir = fresh_dir("paths");
  const WriteError missing = error_of([&] { arc::write_file_checked((dir / "no" / "x.json").string(), "x"); });
  EXPECT_EQ(missing.exit_code, arc::kExitBadInput);
  EXPECT_NE(std::string(missing.what()).find("No such file or directory"), std::string::npos) << missing.what();
  EXPECT_EQ(error_of([&] { arc::write_file_checked(dir.string(), "x"); }).exit_code, arc::kExitBadInput);
  const WriteError summary = error_of([&] { arc::check_output_file((dir / "no" / "s.json").string(), "--summary"); });
  EXPECT_EQ(summary.exit_code, arc::kExitBadInput);
  EXPECT_EQ(std::string(summary.what()),
            "--summary " + (dir / "no" / "s.json").string() + ": folder " + (dir / "no").string() + " does not exist");
  EXPECT_EQ(error_of([&] { arc::check_output_file(dir.string(), "--summary"); }).exit_code, arc::kExitBadInput);
  arc::write_file_checked((dir / "plain").string(), "x");
  EXPECT_EQ(error_of([&] { arc::check_output_dir((dir / "plain").string(), "--out"); }).exit_code, arc::kExitBadInput);
  arc::check_output_dir((dir / "made" / "here").string(), "--out");
  EXPECT_TRUE(fs::is_directory(dir / "made" / "here"));
  EXPECT_EQ(files_in(dir / "made" / "here"), 0) << "the probe file must be gone";
}

TEST(FileWriter, AppendsCountAgainstTheLimit) {
  const fs::path file = fresh_dir("append") / "rec.replay";
  std::ofstream(file) << "";
  FILE* f = std::fopen(file.c_str(), "ab");
  ASSERT_NE(f, nullptr);
  NoWriteLimit restore;
  arc::set_write_limit(5);
  EXPECT_EQ(arc::write_all(fileno(f), "0123456789", 10), ENOSPC);
  std::fclose(f);
  EXPECT_EQ(read(file), "01234");
}
