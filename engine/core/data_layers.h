// core/data_layers.h — the game's data as layers: mod folders laid over the data root.
//
// A mod is a folder shaped like the data root (assets/, levels/, shaders/ ...). A file of a mod
// replaces the base file at the same relative path; a file the base lacks is added. Mods named
// later lie over earlier ones. Loaders ask for a relative path and get the topmost file; folder
// listings (effects, levels, ships) are the union by file name, the topmost file winning.
//
// One set of layers is in use per run (set at start, read-only after). Code that is given a
// folder asks data_file(folder, rel): for the data root in use, or a folder within it
// (root/shaders), the mods apply; for any other folder (a test's own data) the plain path is
// returned.
//
// Example, compiled as DataLayersExample.LayAMod in tests/unit/core/test_data_layers.cpp:
//   DataLayers layers(data_root());
//   layers.add_mod(mod_dir);  // InputError: not a folder, not a mod
//   use_data_layers(layers);
//   const std::string ship = data_file(data_root(), "assets/ships/viper_mk2.json");  // the mod's
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace arc {

struct ModLayer {
  std::string name;  // the folder's name, as replays record it
  std::string dir;   // the folder
  uint64_t hash = 0; // content hash: every file's relative path and bytes, in path order
};

class DataLayers {
 public:
  DataLayers() = default;
  explicit DataLayers(std::string base_dir) : base_(std::move(base_dir)) {}

  // Lays a mod over the layers so far. InputError when `dir` is not a folder, holds none of the
  // data folders (assets/, levels/, shaders/), repeats a mod's name, or holds more than
  // kMaxModFiles files.
  void add_mod(const std::string& dir);

  const std::string& base() const { return base_; }
  const std::vector<ModLayer>& mods() const { return mods_; }
  // The topmost layer's file at `rel` ("assets/ships/viper.json"), or the base's path when no
  // layer has it (so a missing file is named where the game expects it).
  std::string file(const std::string& rel) const;
  // Regular files in `rel_dir` with extension `ext` (".json") over all layers, one per file
  // name, the topmost winning; sorted by file name.
  std::vector<std::string> files(const std::string& rel_dir, const std::string& ext) const;
  // The existing folders at `rel_dir`, base first: what a watcher of that folder watches.
  std::vector<std::string> dirs(const std::string& rel_dir) const;
  // The mod a path lies in ("" for the base or outside every mod).
  std::string mod_of(const std::string& path) const;

 private:
  std::string base_;
  std::vector<ModLayer> mods_;
};

constexpr size_t kMaxModFiles = 100000;

// The layers in use (empty: none set, so data_file() returns plain paths).
void use_data_layers(DataLayers layers);
const DataLayers& data_layers();
// root/rel through the layers in use when `root` is their base or lies within it; root/rel otherwise.
std::string data_file(const std::string& root, const std::string& rel);
std::vector<std::string> data_files(const std::string& root, const std::string& rel_dir, const std::string& ext);
std::vector<std::string> data_dirs(const std::string& root, const std::string& rel_dir);

}  // namespace arc
