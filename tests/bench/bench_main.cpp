#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "bench_registry.h"
#include "core/data_root.h"
#include "core/error.h"

namespace arc::bench {
namespace {
struct Scene {
  std::string name;
  std::function<void()> fn;
  bool on_request;
};
std::vector<Scene>& scenes() {
  static std::vector<Scene> s;
  return s;
}
bool& failed() {
  static bool f = false;
  return f;
}
std::vector<std::pair<std::string, double>>& metrics() {
  static std::vector<std::pair<std::string, double>> m;
  return m;
}
}  // namespace

void report_metric(const std::string& name, double value) { metrics().emplace_back(name, value); }
void report_failure(const std::string& why) {
  std::printf("FAILED: %s\n", why.c_str());
  failed() = true;
}
double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n == 0 ? 0.0 : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}
SceneRegistrar::SceneRegistrar(const char* name, std::function<void()> fn, bool on_request) {
  scenes().push_back({name, std::move(fn), on_request});
}

}  // namespace arc::bench

// arcfire-bench [--scenes-only] [--scene NAME] [google benchmark flags]
// No arguments: every micro-benchmark, then every headline scene, then the metric lines.
// Scenes registered on request (the soak) run only when --scene names them. Exit 1 when a
// scene reported a failure; exit 2, with one line, for a scene name that does not exist, an
// ARCFIRE_GFX_DUMP folder that does not, or a scene's input it cannot use.
int main(int argc, char** argv) {
  // Mesa's on-disk shader cache off (unless the caller set it either way): every run compiles
  // as a fresh install does, so a variant the renderer's warm-up misses costs its frame in every
  // run (combat_frame_max_ms), and no run's figures depend on the cache the one before left.
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 0);
  bool scenes_only = false;
  bool filtered = false;  // --benchmark_filter: only those micro-benchmarks, no scenes
  std::string only_scene;
  std::vector<char*> rest{argv[0]};
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--scenes-only") == 0) scenes_only = true;
    else if (std::strcmp(argv[i], "--scene") == 0 && i + 1 < argc) only_scene = argv[++i];
    else {
      if (std::strncmp(argv[i], "--benchmark_filter", 18) == 0) filtered = true;
      rest.push_back(argv[i]);
    }
  }
  int n = int(rest.size());
  benchmark::Initialize(&n, rest.data());
  if (benchmark::ReportUnrecognizedArguments(n, rest.data())) return 2;
  if (!only_scene.empty()) {
    std::string names;
    bool known = false;
    for (auto& scene : arc::bench::scenes()) {
      known = known || scene.name == only_scene;
      names += (names.empty() ? "" : ", ") + scene.name;
    }
    if (!known) {
      std::fprintf(stderr, "arcfire-bench: --scene '%s' is not a scene; use one of %s\n", only_scene.c_str(), names.c_str());
      return 2;
    }
  }
  // Scenes save pictures there at their end: a folder that is not there would lose a run's work.
  if (const char* dump = std::getenv("ARCFIRE_GFX_DUMP"); dump && !std::filesystem::is_directory(dump)) {
    std::fprintf(stderr, "arcfire-bench: ARCFIRE_GFX_DUMP='%s' is not a folder; name one that exists\n", dump);
    return 2;
  }
  // Every scene reads the data folder: one line and exit 2 when there is none, before any work.
  if (!filtered || !only_scene.empty()) {
    try {
      (void)arc::data_root();
    } catch (const arc::InputError& e) {
      std::fprintf(stderr, "arcfire-bench: %s\n", e.what());
      return 2;
    }
  }
  if (!scenes_only && only_scene.empty()) benchmark::RunSpecifiedBenchmarks();
  for (auto& [name, fn, on_request] : arc::bench::scenes()) {
    if (filtered && only_scene.empty()) break;
    if (only_scene.empty() ? on_request : name != only_scene) continue;
    std::printf("scene %s\n", name.c_str());
    std::fflush(stdout);
    try {
      fn();
    } catch (const arc::InputError& e) {
      std::fprintf(stderr, "arcfire-bench: scene %s: %s\n", name.c_str(), e.what());
      return 2;
    }
  }
  for (auto& [name, value] : arc::bench::metrics()) std::printf("metric %s %.6g\n", name.c_str(), value);
  benchmark::Shutdown();
  return arc::bench::failed() ? 1 : 0;
}
