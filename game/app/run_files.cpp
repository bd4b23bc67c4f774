// The files of a run, outputs checked against inputs (app/run_files.h).
#include "game/app/run_files.h"

#include <sys/stat.h>

#include <filesystem>
#include <system_error>

#include "core/data_layers.h"
#include "core/error.h"
#include "game/sim/world.h"

namespace arc {
namespace {

namespace fs = std::filesystem;

// Where a path leads: the file itself when it exists, its path with every link resolved, and
// the path of its own entry (a link not followed), so a link and its target both count.
struct Place {
  bool exists = false;
  dev_t dev = 0;
  ino_t ino = 0;
  std::string target;
  std::string entry;
};

// Absolute, every link resolved as far as the path exists; lexical where resolving fails (a
// link loop, a name too long): never throws.
std::string resolved(const fs::path& p) {
  std::error_code ec;
  const fs::path abs = fs::absolute(p, ec);
  if (ec) return p.lexically_normal().string();
  const fs::path r = fs::weakly_canonical(abs, ec);
  return (ec ? abs.lexically_normal() : r).string();
}

Place place_of(const std::string& path) {
  Place pl;
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {
    pl.exists = true;
    pl.dev = st.st_dev;
    pl.ino = st.st_ino;
  }
  pl.target = resolved(path);
  const fs::path p(path);
  const fs::path name = p.filename();
  if (name.empty() || name == "." || name == "..") pl.entry = pl.target;
  else pl.entry = (fs::path(resolved(p.parent_path().empty() ? fs::path(".") : p.parent_path())) / name).string();
  return pl;
}

bool same_file(const Place& a, const Place& b) {
  if (a.exists && b.exists && a.dev == b.dev && a.ino == b.ino) return true;
  return a.target == b.target || a.entry == b.entry || a.entry == b.target || a.target == b.entry;
}

[[noreturn]] void clash(const std::string& output, const std::string& input) {
  throw InputError(output + " is the same file as " + input + "; an output may not replace an input");
}

}  // namespace

void RunFiles::input(const std::string& what, const std::string& path) {
  if (!path.empty()) inputs_.push_back({what, path});
}

void RunFiles::output(const std::string& what, const std::string& path) {
  if (!path.empty()) outputs_.push_back({what, path});
}

void RunFiles::output_folder(const std::string& what, const std::string& dir,
                             std::function<bool(const std::string&)> writes) {
  if (!dir.empty()) folders_.push_back({what, dir, std::move(writes)});
}

void RunFiles::add(const RunFiles& other) {
  inputs_.insert(inputs_.end(), other.inputs_.begin(), other.inputs_.end());
  outputs_.insert(outputs_.end(), other.outputs_.begin(), other.outputs_.end());
  folders_.insert(folders_.end(), other.folders_.begin(), other.folders_.end());
}

void RunFiles::check() const {
  std::vector<Place> in;
  in.reserve(inputs_.size());
  for (const Named& i : inputs_) in.push_back(place_of(i.path));
  for (const Named& o : outputs_) {
    const Place out = place_of(o.path);
    for (size_t k = 0; k < in.size(); ++k)
      if (same_file(out, in[k])) clash(o.what + " " + o.path, inputs_[k].what + " " + inputs_[k].path);
  }
  for (const Folder& f : folders_) {
    const std::string dir = resolved(f.dir);
    for (size_t k = 0; k < in.size(); ++k)
      for (const std::string* name : {&in[k].entry, &in[k].target}) {
        const fs::path p(*name);
        if (p.parent_path().string() == dir && f.writes(p.filename().string()))
          clash(f.what + " " + f.dir + " (its " + p.filename().string() + ")",
                inputs_[k].what + " " + inputs_[k].path);
      }
  }
}

void add_level_inputs(RunFiles& files, const World& world, const std::string& root_dir) {
  files.input("level", world.level.path);
  for (const auto& [name, cls] : world.level.classes) files.input("ship class", cls->path);
  for (const std::string& model : world.model_paths)
    files.input("model", fs::path(model).is_absolute() ? model : data_file(root_dir, model));
  for (const std::string& effect : data_files(root_dir, "assets/effects", ".json")) files.input("effect", effect);
}

}  // namespace arc
