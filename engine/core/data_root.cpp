// core/data_root.cpp — resolving and checking the data root (see data_root.h).
#include "core/data_root.h"

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <optional>
#include <system_error>

#include "core/error.h"
#include "core/input_file.h"

namespace arc {
namespace {

namespace fs = std::filesystem;

fs::path normalised(const fs::path& p) {
  std::error_code ec;
  fs::path abs = fs::absolute(p, ec);
  if (ec) abs = p;
  fs::path canon = fs::weakly_canonical(abs, ec);
  return ec ? abs.lexically_normal() : canon;
}

// `label` names the folder and its source in the message, e.g. "--data /x".
DataRoot checked(const fs::path& dir, const std::string& source, const std::string& label) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    if (!input_path_exists(dir.string())) throw InputError(label + ": no such folder");
    const std::string what = input_path_problem(dir.string());
    throw InputError(label + ": " + (what.empty() ? "a file" : what) + "; allowed: a folder");
  }
  std::string missing;
  for (const char* sub : {"levels", "assets", "shaders"}) {
    if (fs::is_directory(dir / sub, ec)) continue;
    const std::string what = input_path_exists((dir / sub).string()) ? input_path_problem((dir / sub).string()) : "";
    missing += std::string(missing.empty() ? "" : ", ") + sub + "/" + (what.empty() ? "" : " (" + what + ")");
  }
  if (!missing.empty())
    throw InputError(label + ": not a data folder (it needs levels/, assets/ and shaders/; missing " + missing + ")");
  return {normalised(dir).string(), source};
}

std::optional<std::string> first_line(const fs::path& file) {
  const std::optional<std::string> text = read_optional_input_file(file.string(), 64 << 10, "the data root marker");
  if (!text) return std::nullopt;
  std::string line = text->substr(0, text->find('\n'));
  while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
  return line;
}

}  // namespace

std::string executable_path() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string() : exe.string();
}

std::string build_source_tree(const std::string& exe_path) {
  if (exe_path.empty()) return "";
  return first_line(fs::path(exe_path).parent_path() / kDataRootFile).value_or("");
}

DataRoot resolve_data_root(const std::string& cli_value, const char* env_value, const std::string& exe_path) {
  if (!cli_value.empty()) return checked(cli_value, "--data", "--data " + cli_value);
  if (env_value && *env_value) return checked(env_value, "ARCFIRE_DATA", std::string("ARCFIRE_DATA=") + env_value);
  if (exe_path.empty())
    throw InputError("no data folder: the executable's own path is unknown; name one with --data DIR or ARCFIRE_DATA");
  const fs::path exe_dir = fs::path(exe_path).parent_path();
  const fs::path installed = normalised(exe_dir / ".." / "share" / "arcfire");
  std::error_code ec;
  if (fs::exists(installed, ec))
    return checked(installed, "beside the executable", installed.string() + " (beside the executable)");
  const fs::path marker = exe_dir / kDataRootFile;
  if (const auto named = first_line(marker)) {
    if (named->empty()) throw InputError(marker.string() + ": empty; it should name the source folder");
    return checked(*named, "development build (" + marker.string() + ")", *named + " (named by " + marker.string() + ")");
  }
  throw InputError("no data folder: none at " + installed.string() + " and no " + marker.string() +
                   "; name one with --data DIR or ARCFIRE_DATA");
}

namespace {
std::mutex root_mutex;
std::optional<std::string> root_value;
}  // namespace

std::string data_root() {
  std::lock_guard<std::mutex> lock(root_mutex);
  if (!root_value) root_value = resolve_data_root("", std::getenv("ARCFIRE_DATA"), executable_path()).dir;
  return *root_value;
}

void set_data_root(const std::string& dir) {
  std::lock_guard<std::mutex> lock(root_mutex);
  root_value = dir;
}

}  // namespace arc
