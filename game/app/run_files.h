// game/app/run_files.h — the files one run reads and writes, checked so no output replaces an input.
//
// A run names its inputs (the level, ship classes, models, effects, a replay script, its golden
// files, bindings, sounds) and its outputs (--summary, --audio-out, --record, frames in --out,
// goldens it updates). check() compares every output with every input before anything is
// written: the same file through another path, a hard link or a symbolic link is caught by its
// device and inode; an output that does not exist yet is compared by its resolved path. A clash
// is InputError (exit 2), one line naming both:
//   --summary d.json is the same file as --level d.json; an output may not replace an input
//
// Example, compiled as AppExamples.RunFiles in tests/unit/app/test_app_examples.cpp:
//   RunFiles files;
//   files.input("--level", "levels/duel.json");
//   files.output("--summary", "out/summary.json");
//   files.output_folder("--out", "out/frames", [](const std::string& name) { return name.ends_with(".png"); });
//   files.check();  // InputError when an output is one of the inputs
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace arc {

struct World;

class RunFiles {
 public:
  // A file the run reads; `what` names it in the message ("--level", "ship class").
  void input(const std::string& what, const std::string& path);
  // A file the run writes (replaced whole).
  void output(const std::string& what, const std::string& path);
  // A folder the run writes files into: `writes(name)` says whether it may write a file of that name.
  void output_folder(const std::string& what, const std::string& dir, std::function<bool(const std::string&)> writes);
  // The inputs and outputs of `other` added to these.
  void add(const RunFiles& other);
  // InputError naming the output and the input when an output is an input.
  void check() const;

 private:
  struct Named {
    std::string what, path;
  };
  struct Folder {
    std::string what, dir;
    std::function<bool(const std::string&)> writes;
  };
  std::vector<Named> inputs_, outputs_;
  std::vector<Folder> folders_;
};

// The files a loaded level read: the level, its ship classes, its models and the effect files.
void add_level_inputs(RunFiles& files, const World& world, const std::string& root_dir);

}  // namespace arc
