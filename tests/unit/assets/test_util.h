// Helpers shared by the asset tests: a per-test scratch directory and byte-level file writes.
#pragma once
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>
#include <unistd.h>
#include <gtest/gtest.h>

namespace arc::test {

// Removes every scratch directory this process made once all tests have run.
class ScratchCleanup : public ::testing::Environment {
 public:
  static std::vector<std::filesystem::path>& made() {
    static std::vector<std::filesystem::path> dirs;
    return dirs;
  }
  void TearDown() override {
    std::error_code ec;
    for (const auto& d : made()) std::filesystem::remove_all(d, ec);
  }
};
inline ::testing::Environment* const kScratchCleanup = ::testing::AddGlobalTestEnvironment(new ScratchCleanup);

inline std::filesystem::path scratch_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  auto dir = std::filesystem::temp_directory_path() /
             ("arcfire_assets_" + std::to_string(::getpid()) + "_" + info->test_suite_name() + "_" + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  ScratchCleanup::made().push_back(dir);
  return dir;
}

inline void write_bytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), std::streamsize(bytes.size()));
}

inline std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace arc::test
