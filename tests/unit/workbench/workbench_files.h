// tests/unit/workbench/workbench_files.h — scratch effect files for the workbench tests.
#pragma once
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include "core/data_root.h"

namespace arc::test {

// A fresh folder under the system temp folder, removed when the object goes.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name) : dir_(std::filesystem::temp_directory_path() / ("arcfire_wb_" + name)) {
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  ~ScratchDir() { std::filesystem::remove_all(dir_); }
  std::string write(const std::string& file, const std::string& text) const {
    const std::string path = (dir_ / file).string();
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }
  std::string copy(const std::string& effect) const {
    return write(effect + ".json", read(arc::data_root() + "/assets/effects/" + effect + ".json"));
  }
  static std::string read(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

 private:
  std::filesystem::path dir_;
};

// A small effect with comments, an inline block, a block laid out one key per line and keyframes.
inline const char* kCommentedEffect = R"(// A test effect: comments must survive every save.
{
  "description": "test puff", // trailing comment
  "clusters": [
    {
      "name": "puff",
      "sprite": "glow",
      /* a block comment */
      "animation": { "type": "linear", "drag": 2 },
      "emitter": { "burst": 10 },
      "particles": { "speed": [1, 3], "lifetime": 0.5 },
      "curves": { "alpha": [[0, 1], [1, 0]] }
    },
    {
      "name": "sparks",
      "sprite": "spark",
      "animation": { "type": "linear" },
      "emitter": { "rate": 30, "duration": 0.2 }
    }
  ]
}
)";

}  // namespace arc::test
