// assets/image_codec.cpp — finds and loads the image codec module (see image_codec.h).
#include "assets/image_codec.h"

#include <dlfcn.h>
#include <filesystem>
#include <system_error>
#include <vector>

namespace arc {
namespace {

namespace fs = std::filesystem;

// Where the module may lie, in the order tried: beside /proc/self/exe, in <exe>/../lib/arcfire
// (an installed game, packaging/install.cmake), then its build path.
std::vector<std::string> module_candidates() {
  std::vector<std::string> paths;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    paths.push_back((exe.parent_path() / kImageCodecModule).string());
    const fs::path installed = exe.parent_path().parent_path() / "lib" / "arcfire" / kImageCodecModule;
    if (fs::exists(installed, ec)) paths.push_back(installed.string());
  }
  const std::string built = ARCFIRE_IMAGE_CODEC_BUILD_PATH;
  if (paths.empty() || paths.front() != built) paths.push_back(built);
  return paths;
}

template <typename F>
bool resolve(void* handle, const char* symbol, F& out) {
  out = reinterpret_cast<F>(::dlsym(handle, symbol));
  return out != nullptr;
}

struct LoadedCodec {
  ImageCodec codec;
  std::string error;  // why the module could not be loaded; empty once it is
};

LoadedCodec load_from(const std::string& path) {
  LoadedCodec l;
  const std::string what = path + ": cannot load the image codec module (it reads and writes every image): ";
  // RTLD_NOW: a library the module needs that is missing fails here, with its name, not later.
  void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* reason = ::dlerror();
    std::string text = reason ? reason : "unknown reason";
    // glibc's reason starts with the path again ("PATH: file too short").
    if (text.compare(0, path.size() + 2, path + ": ") == 0) text.erase(0, path.size() + 2);
    l.error = what + text;
    return l;
  }
  decltype(&arc_codec_abi_version) version = nullptr;
  ImageCodec& c = l.codec;
  if (!resolve(handle, "arc_codec_abi_version", version) || !resolve(handle, "arc_codec_open", c.open) ||
      !resolve(handle, "arc_codec_read", c.read) || !resolve(handle, "arc_codec_close", c.close) ||
      !resolve(handle, "arc_codec_encode", c.encode) || !resolve(handle, "arc_codec_free", c.free)) {
    const char* reason = ::dlerror();
    l.error = what + (reason ? reason : "a function is missing");
  } else if (version() != ARC_CODEC_ABI_VERSION) {
    l.error = what + "it is from another build (interface version " + std::to_string(version()) + ", this program needs " +
              std::to_string(ARC_CODEC_ABI_VERSION) + "); rebuild";
  }
  // The module stays loaded for the life of the process (OpenImageIO keeps threads and caches),
  // also after a failure above: nothing of it is called then.
  return l;
}

LoadedCodec load_module() {
  const std::vector<std::string> candidates = module_candidates();
  for (const std::string& path : candidates) {
    std::error_code ec;
    if (fs::exists(path, ec)) return load_from(path);
  }
  // Neither is there: the first place looked is the one to name, with the loader's reason.
  LoadedCodec l = load_from(candidates.front());
  if (candidates.size() > 1 && l.error.size()) l.error += " (nor is it at " + candidates.back() + ")";
  return l;
}

}  // namespace

const ImageCodec& image_codec() {
  static const LoadedCodec loaded = load_module();
  if (!loaded.error.empty()) throw ImageCodecUnavailable(loaded.error);
  return loaded.codec;
}

std::string take_codec_message(const ImageCodec& codec, char* message) {
  if (!message) return "";
  std::string text(message);
  codec.free(message);
  return text;
}

}  // namespace arc
