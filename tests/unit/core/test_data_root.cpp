// The data root (core/data_root.h): --data, then ARCFIRE_DATA, then ../share/arcfire beside the
// executable, then the folder a development build names in arcfire-data-root; a folder without
// levels/, assets/ and shaders/, or no source at all, is one line naming the folder and its source.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/data_root.h"
#include "core/error.h"

namespace fs = std::filesystem;
using arc::resolve_data_root;

namespace {

fs::path fresh_dir(const std::string& name) {
  fs::path d = fs::path(testing::TempDir()) / ("arcfire-data-root-" + std::to_string(::getpid()) + "-" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return fs::canonical(d);
}

fs::path data_folder(const fs::path& dir) {
  for (const char* sub : {"levels", "assets", "shaders"}) fs::create_directories(dir / sub);
  return dir;
}

// An installed layout: P/bin/arcfire (its path only; nothing runs it) and P/share/arcfire.
std::string installed(const fs::path& prefix) {
  data_folder(prefix / "share" / "arcfire");
  fs::create_directories(prefix / "bin");
  return (prefix / "bin" / "arcfire").string();
}

// A development build: B/arcfire and B/arcfire-data-root naming `source`.
std::string dev_build(const fs::path& build, const fs::path& source) {
  fs::create_directories(build);
  std::ofstream(build / arc::kDataRootFile) << source.string() << "\n";
  return (build / "arcfire").string();
}

std::string error_of(const std::string& cli, const char* env, const std::string& exe) {
  try {
    resolve_data_root(cli, env, exe);
  } catch (const arc::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(DataRoot, OrderIsDataThenEnvironmentThenInstallThenBuild) {
  const fs::path d = fresh_dir("order");
  const fs::path cli = data_folder(d / "cli"), env = data_folder(d / "env"), source = data_folder(d / "src");
  const std::string exe = installed(d / "prefix");
  dev_build(d / "prefix" / "bin", source);  // a build file beside an installed program loses to share/

  auto r = resolve_data_root(cli.string(), env.c_str(), exe);
  EXPECT_EQ(r.dir, cli.string());
  EXPECT_EQ(r.source, "--data");
  r = resolve_data_root("", env.c_str(), exe);
  EXPECT_EQ(r.dir, env.string());
  EXPECT_EQ(r.source, "ARCFIRE_DATA");
  r = resolve_data_root("", "", exe);  // an empty variable counts as unset
  EXPECT_EQ(r.dir, (d / "prefix" / "share" / "arcfire").string());
  EXPECT_EQ(r.source, "beside the executable");
  r = resolve_data_root("", nullptr, dev_build(d / "build", source));
  EXPECT_EQ(r.dir, source.string());
  EXPECT_NE(r.source.find("development build"), std::string::npos);
  EXPECT_NE(r.source.find((d / "build" / arc::kDataRootFile).string()), std::string::npos);
}

TEST(DataRoot, RelativeFoldersBecomeAbsolute) {
  const fs::path d = fresh_dir("relative");
  data_folder(d / "game");
  const fs::path cwd = fs::current_path();
  fs::current_path(d);
  const auto r = resolve_data_root("./game/../game", nullptr, "");
  fs::current_path(cwd);
  EXPECT_EQ(r.dir, (d / "game").string());
}

TEST(DataRoot, BadFoldersAreOneLineNamingTheSource) {
  const fs::path d = fresh_dir("bad");
  fs::create_directories(d / "half" / "levels");
  const std::string exe = installed(d / "prefix");
  EXPECT_EQ(error_of((d / "nope").string(), nullptr, exe), "--data " + (d / "nope").string() + ": no such folder");
  EXPECT_EQ(error_of((d / "half").string(), nullptr, exe),
            "--data " + (d / "half").string() +
                ": not a data folder (it needs levels/, assets/ and shaders/; missing assets/, shaders/)");
  EXPECT_EQ(error_of("", (d / "nope").c_str(), exe), "ARCFIRE_DATA=" + (d / "nope").string() + ": no such folder");
  // A broken install is named, not skipped for the build's folder.
  fs::remove_all(d / "prefix" / "share" / "arcfire" / "shaders");
  const std::string broken = error_of("", nullptr, exe);
  EXPECT_NE(broken.find((d / "prefix" / "share" / "arcfire").string() + " (beside the executable): not a data folder"),
            std::string::npos)
      << broken;
  // A build whose source tree moved away names its arcfire-data-root file.
  const std::string moved = error_of("", nullptr, dev_build(d / "build", d / "gone"));
  EXPECT_EQ(moved, (d / "gone").string() + " (named by " + (d / "build" / arc::kDataRootFile).string() + "): no such folder");
}

TEST(DataRoot, NoSourceAtAllSaysHowToNameOne) {
  const fs::path d = fresh_dir("none");
  fs::create_directories(d / "bin");
  const std::string msg = error_of("", nullptr, (d / "bin" / "arcfire").string());
  EXPECT_EQ(msg.rfind("no data folder: none at " + (d / "share" / "arcfire").string(), 0), 0u) << msg;
  EXPECT_NE(msg.find("--data DIR or ARCFIRE_DATA"), std::string::npos) << msg;
  EXPECT_EQ(msg.find('\n'), std::string::npos);
}

// The tests themselves find the data the way the game does: this program lies in the build
// folder, beside its arcfire-data-root.
TEST(DataRoot, TestsFindTheSourceTreeThroughTheBuild) {
  const std::string exe = arc::executable_path();
  ASSERT_FALSE(exe.empty());
  const std::string source = arc::build_source_tree(exe);
  ASSERT_FALSE(source.empty()) << "no " << arc::kDataRootFile << " beside " << exe;
  EXPECT_TRUE(fs::is_regular_file(fs::path(source) / "engine" / "core" / "data_root.h"));
  EXPECT_TRUE(fs::is_directory(fs::path(arc::data_root()) / "levels"));
  EXPECT_EQ(arc::build_source_tree("/no/such/folder/arcfire"), "");
}

// The banner's example: the data root resolved as a test program finds it, then set.
TEST(DataRootExample, ResolveAndSet) {
  using namespace arc;
  const std::string cli_value;  // no --data
  const DataRoot root = resolve_data_root(cli_value, std::getenv("ARCFIRE_DATA"), executable_path());
  set_data_root(root.dir);  // what data_root() answers from now on
  EXPECT_EQ(data_root(), root.dir);
}

}  // namespace
