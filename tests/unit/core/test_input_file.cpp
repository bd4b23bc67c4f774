// Opening input files (core/input_file.h): each kind of thing a path can name is one line saying
// what it is, at once; sizes are checked before reading; folders are listed without aborting.
#include <gtest/gtest.h>

#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "core/error.h"
#include "core/input_file.h"

namespace {

namespace fs = std::filesystem;

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const arc::InputError& e) {
    return e.what();
  }
  return "(no error)";
}

class InputFile : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing::TempDir() + "arcfire_input_file_" + std::to_string(::getpid());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string at(const std::string& name) const { return dir_ + "/" + name; }
  void write(const std::string& name, const std::string& text) const { std::ofstream(at(name), std::ios::binary) << text; }
  std::string read(const std::string& path) const { return arc::read_input_file(path, 1000, "a test file"); }
  std::string refused(const std::string& path, const std::string& what) const {
    return path + ": " + what + "; allowed: a regular file of at most 1000 bytes for a test file";
  }
  std::string dir_;
};

TEST_F(InputFile, ReadsARegularFileWhole) {
  write("a.json", "{\"a\": 1}");
  EXPECT_EQ(read(at("a.json")), "{\"a\": 1}");
  write("empty", "");
  EXPECT_EQ(read(at("empty")), "");
  EXPECT_EQ(arc::input_path_problem(at("a.json")), "");
}

TEST_F(InputFile, EachKindOfPathIsNamedInOneLine) {
  fs::create_directory(at("folder"));
  ASSERT_EQ(::mkfifo(at("fifo").c_str(), 0600), 0);
  fs::create_symlink("loop", at("loop"));
  fs::create_symlink("fifo", at("to_fifo"));
  fs::create_symlink("/dev/zero", at("zero"));
  const std::string long_name = at(std::string(300, 'n'));
  EXPECT_EQ(error_of([&] { read(at("folder")); }), refused(at("folder"), "a folder"));
  EXPECT_EQ(error_of([&] { read(at("fifo")); }), refused(at("fifo"), "a FIFO (named pipe)"));
  EXPECT_EQ(error_of([&] { read(at("to_fifo")); }), refused(at("to_fifo"), "a FIFO (named pipe)"));
  EXPECT_EQ(error_of([&] { read(at("loop")); }), refused(at("loop"), "a symbolic link loop"));
  EXPECT_EQ(error_of([&] { read(at("zero")); }), refused(at("zero"), "a character device"));
  EXPECT_EQ(error_of([&] { read("/dev/urandom"); }), refused("/dev/urandom", "a character device"));
  EXPECT_EQ(error_of([&] { read(long_name); }), refused(long_name, "a name longer than the system allows"));
  EXPECT_EQ(error_of([&] { read(at("missing")); }), refused(at("missing"), "not found"));
  EXPECT_EQ(arc::input_path_problem(at("loop")), "a symbolic link loop");
  EXPECT_EQ(arc::input_path_problem(at("fifo")), "a FIFO (named pipe)");
}

TEST_F(InputFile, ASocketIsNamed) {
  const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
  ASSERT_GE(fd, 0);
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  const std::string path = at("sock");
  if (path.size() >= sizeof addr.sun_path) GTEST_SKIP() << "temporary folder too deep for a socket name";
  std::strcpy(addr.sun_path, path.c_str());
  ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
  EXPECT_EQ(error_of([&] { read(path); }), refused(path, "a socket"));
  ::close(fd);
}

TEST_F(InputFile, AFifoAnswersAtOnce) {
  // Nothing ever writes to it: a blocking open would wait for ever.
  ASSERT_EQ(::mkfifo(at("fifo").c_str(), 0600), 0);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_THROW(read(at("fifo")), arc::InputError);
  EXPECT_THROW(arc::check_input_path(at("fifo"), 1000, "a test file"), arc::InputError);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
}

TEST_F(InputFile, SizeIsCheckedBeforeReading) {
  write("big", std::string(2000, 'x'));
  EXPECT_EQ(error_of([&] { read(at("big")); }), at("big") + ": file is 2000 bytes; a test file may be at most 1000 bytes");
  write("edge", std::string(1000, 'x'));
  EXPECT_EQ(read(at("edge")).size(), 1000u);
}

TEST_F(InputFile, AnOptionalFileThatIsNotThereIsNothing) {
  EXPECT_FALSE(arc::read_optional_input_file(at("missing"), 1000, "a test file"));
  write("there", "x");
  EXPECT_EQ(*arc::read_optional_input_file(at("there"), 1000, "a test file"), "x");
  // There but wrong is reported, not skipped.
  fs::create_symlink("loop", at("loop"));
  EXPECT_EQ(error_of([&] { arc::read_optional_input_file(at("loop"), 1000, "a test file"); }),
            refused(at("loop"), "a symbolic link loop"));
  fs::create_symlink("nowhere", at("dangling"));
  EXPECT_TRUE(arc::input_path_exists(at("dangling")));
  EXPECT_FALSE(arc::input_path_exists(at("missing")));
  // A name too long is something to report, not a file that is simply absent.
  EXPECT_TRUE(arc::input_path_exists(at(std::string(300, 'n'))));
}

TEST_F(InputFile, ReadInPiecesStopsAtTheLimit) {
  write("f", std::string(600, 'y'));
  arc::InputFile in(at("f"), 1000, "a test file");
  EXPECT_EQ(in.size(), 600u);
  char buf[256];
  size_t total = 0;
  while (const size_t n = in.read_some(buf, sizeof buf)) total += n;
  EXPECT_EQ(total, 600u);
}

TEST_F(InputFile, FoldersAreListedSortedAndHostileEntriesKept) {
  write("b.json", "{}");
  write("a.json", "{}");
  write("notes.txt", "");
  ASSERT_EQ(::mkfifo(at("pipe.json").c_str(), 0600), 0);
  fs::create_symlink("loop.json", at("loop.json"));
  const auto files = arc::list_input_folder(dir_, ".json", "test files", false);
  const std::vector<std::string> want = {at("a.json"), at("b.json"), at("loop.json"), at("pipe.json")};
  EXPECT_EQ(files, want);
  // Each hostile entry is then refused by its reader, with its name.
  EXPECT_EQ(error_of([&] { read(at("pipe.json")); }), refused(at("pipe.json"), "a FIFO (named pipe)"));
}

TEST_F(InputFile, AFolderThatIsALoopOrAFileIsOneLine) {
  fs::create_symlink("effects", at("effects"));
  write("file", "x");
  EXPECT_EQ(error_of([&] { arc::list_input_folder(at("effects"), ".json", "the effects", false); }),
            at("effects") + ": a symbolic link loop; allowed: a folder for the effects");
  EXPECT_EQ(error_of([&] { arc::check_input_folder(at("file"), "the effects"); }),
            at("file") + ": a file; allowed: a folder for the effects");
  EXPECT_TRUE(arc::list_input_folder(at("missing"), ".json", "the effects", true).empty());
  EXPECT_EQ(error_of([&] { arc::list_input_folder(at("missing"), ".json", "the effects", false); }),
            at("missing") + ": not found; allowed: a folder for the effects");
}

TEST_F(InputFile, AFolderWithTooManyEntriesIsRefused) {
  for (int i = 0; i < 5; ++i) write("f" + std::to_string(i) + ".json", "{}");
  EXPECT_EQ(error_of([&] { arc::list_input_folder(dir_, ".json", "test files", false, 4); }),
            dir_ + ": a folder of more than 4 entries; allowed: a folder for test files");
}

}  // namespace
