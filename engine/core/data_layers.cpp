#include "core/data_layers.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <system_error>

#include "core/error.h"
#include "core/fast_hash.h"
#include "core/input_file.h"
#include "core/input_limits.h"

namespace arc {
namespace fs = std::filesystem;
namespace {

// "/data/", "/data/." and "/data" are one folder.
std::string normal(const std::string& p) {
  std::string s = fs::path(p).lexically_normal().generic_string();
  while (s.size() > 1 && s.back() == '/') s.pop_back();
  return s;
}

bool is_folder(const fs::path& p) {
  std::error_code ec;
  return fs::is_directory(p, ec);
}

bool is_file(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

// Every regular file under `dir` by its relative path ('/'-separated), in path order. Links are
// not followed into folders, so a link loop cannot trap the walk.
std::vector<std::string> relative_files(const fs::path& dir) {
  std::vector<std::string> out;
  std::error_code ec;
  fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec), end;
  for (; !ec && it != end; it.increment(ec)) {
    if (!is_file(it->path())) continue;
    out.push_back(it->path().lexically_relative(dir).generic_string());
    if (out.size() > kMaxModFiles)
      throw InputError(dir.string() + ": a mod holds at most " + std::to_string(kMaxModFiles) + " files");
  }
  if (ec) throw InputError(dir.string() + ": cannot list the mod's files: " + ec.message());
  std::sort(out.begin(), out.end());
  return out;
}

// Relative paths and contents, so a renamed file or a changed byte changes the hash.
uint64_t content_hash(const fs::path& dir) {
  FastHasher h;
  std::vector<char> buf(1 << 16);
  for (const std::string& rel : relative_files(dir)) {
    h.add_str(rel);
    // Read in pieces: no mod file is larger than a model, the largest input the game reads.
    InputFile in((dir / rel).string(), kMaxModelFileBytes, "a file of a mod");
    uint64_t size = 0;
    while (const size_t n = in.read_some(buf.data(), buf.size())) {
      for (size_t i = 0; i < n; ++i) h.add_u64(uint8_t(buf[i]));
      size += n;
    }
    h.add_u64(size);
  }
  return h.value();
}

DataLayers& layers_in_use() {
  static DataLayers layers;
  return layers;
}

}  // namespace

void DataLayers::add_mod(const std::string& dir) {
  const fs::path p(dir);
  if (!is_folder(p)) {
    const std::string what = input_path_exists(dir) ? input_path_problem(dir) : "not found";
    throw InputError("--mod " + dir + ": " + (what.empty() ? "a file" : what) +
                     "; allowed: a folder (a mod is a folder shaped like the data root)");
  }
  bool data = false;
  for (const char* sub : {"assets", "levels", "shaders"}) data = data || is_folder(p / sub);
  if (!data) throw InputError("--mod " + dir + ": holds none of assets/, levels/, shaders/ (a mod mirrors the data root)");
  ModLayer m;
  m.dir = normal(dir);
  m.name = fs::path(m.dir).filename().string();
  const bool plain = !m.name.empty() && m.name.size() <= 64 &&
                     m.name.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_-") == std::string::npos;
  if (!plain) throw InputError("--mod " + dir + ": a mod's folder name must be 1 to 64 of A-Z a-z 0-9 _ - (replays record it)");
  for (const ModLayer& other : mods_)
    if (other.name == m.name) throw InputError("--mod " + dir + ": a mod named '" + m.name + "' is already laid (" + other.dir + ")");
  m.hash = content_hash(p);
  mods_.push_back(std::move(m));
}

std::string DataLayers::file(const std::string& rel) const {
  for (auto it = mods_.rbegin(); it != mods_.rend(); ++it) {
    const fs::path candidate = fs::path(it->dir) / rel;
    if (input_path_exists(candidate.string())) return candidate.string();  // its reader checks what it is
  }
  return (fs::path(base_) / rel).string();
}

std::vector<std::string> DataLayers::files(const std::string& rel_dir, const std::string& ext) const {
  std::map<std::string, std::string> by_name;  // later layers overwrite: the topmost wins
  // Every entry named like the files wanted is listed, so a FIFO or a loop named like one is
  // refused by its reader rather than skipped without a word.
  for (const std::string& dir : dirs(rel_dir))
    for (const std::string& path : list_input_folder(dir, ext, "data files", false, kMaxModFiles))
      by_name[fs::path(path).filename().string()] = path;
  std::vector<std::string> out;
  for (auto& [name, path] : by_name) out.push_back(path);
  return out;
}

std::vector<std::string> DataLayers::dirs(const std::string& rel_dir) const {
  std::vector<std::string> out;
  // A layer may lack the folder; one that has something else there (a loop, a file) is refused.
  auto add = [&](const fs::path& dir) {
    if (!input_path_exists(dir.string())) return;
    check_input_folder(dir.string(), "data files");
    out.push_back(dir.string());
  };
  add(fs::path(base_) / rel_dir);
  for (const ModLayer& m : mods_) add(fs::path(m.dir) / rel_dir);
  return out;
}

std::string DataLayers::mod_of(const std::string& path) const {
  const std::string p = normal(path);
  for (const ModLayer& m : mods_)
    if (p.size() > m.dir.size() && p.compare(0, m.dir.size(), m.dir) == 0 && p[m.dir.size()] == '/') return m.name;
  return "";
}

void use_data_layers(DataLayers layers) { layers_in_use() = std::move(layers); }
const DataLayers& data_layers() { return layers_in_use(); }

namespace {
// Where `folder` lies within the base in use: "" for the base itself, "shaders" for its
// shaders/; false when it lies outside (or no layers are in use).
bool within_base(const std::string& folder, std::string& rel) {
  const std::string& base = layers_in_use().base();
  if (base.empty()) return false;
  const std::string f = normal(folder), b = normal(base);
  if (f == b) return rel = "", true;
  if (f.size() <= b.size() || f.compare(0, b.size(), b) != 0 || f[b.size()] != '/') return false;
  rel = f.substr(b.size() + 1);
  return true;
}
std::string join(const std::string& a, const std::string& b) { return a.empty() ? b : b.empty() ? a : a + "/" + b; }
}  // namespace

std::string data_file(const std::string& root, const std::string& rel) {
  std::string in;
  return within_base(root, in) ? layers_in_use().file(join(in, rel)) : (fs::path(root) / rel).string();
}

std::vector<std::string> data_files(const std::string& root, const std::string& rel_dir, const std::string& ext) {
  std::string in;
  if (within_base(root, in)) return layers_in_use().files(join(in, rel_dir), ext);
  return DataLayers(root).files(rel_dir, ext);
}

std::vector<std::string> data_dirs(const std::string& root, const std::string& rel_dir) {
  std::string in;
  if (within_base(root, in)) return layers_in_use().dirs(join(in, rel_dir));
  return DataLayers(root).dirs(rel_dir);
}

}  // namespace arc
