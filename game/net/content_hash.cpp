// game/net/content_hash.cpp — content hashes compared when a pilot joins.
#include "game/net/content_hash.h"

#include <algorithm>
#include <filesystem>
#include <vector>

#include "core/input_file.h"
#include "core/json.h"
#include "core/rng.h"
#include "game/net/packet.h"

namespace arc {
namespace {

uint64_t add_bytes(uint64_t h, const std::string& bytes) {
  h = mix64(h ^ bytes.size());
  for (size_t i = 0; i < bytes.size(); ++i) h = (h ^ uint8_t(bytes[i])) * 0x100000001B3ull;
  return mix64(h);
}

}  // namespace

uint64_t build_content_id(const char* version) {
  return add_bytes(net::kProtocolVersion, std::string(version));
}

uint64_t level_content_hash(const std::string& level_path) {
  return add_bytes(1, read_text_file(level_path, 64u << 20, "a level"));
}

uint64_t asset_content_hash(const std::string& root) {
  namespace fs = std::filesystem;
  std::vector<std::string> files;
  for (const char* dir : {"assets/ships", "assets/effects"}) {
    std::error_code ec;
    for (fs::directory_iterator it(fs::path(root) / dir, ec), end; !ec && it != end; it.increment(ec))
      if (it->path().extension() == ".json") files.push_back(std::string(dir) + "/" + it->path().filename().string());
  }
  files.push_back("assets/settings/ai.json");
  std::sort(files.begin(), files.end());
  uint64_t h = 2;
  for (const std::string& f : files) {
    h = add_bytes(h, f);
    const std::string full = root + "/" + f;
    h = add_bytes(h, input_path_exists(full) ? read_text_file(full, 64u << 20, "a data file") : std::string());
  }
  return h;
}

}  // namespace arc
