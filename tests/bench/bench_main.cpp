#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "bench_registry.h"

namespace arc::bench {
namespace {
std::vector<std::pair<std::string, std::function<void()>>>& scenes() {
  static std::vector<std::pair<std::string, std::function<void()>>> s;
  return s;
}
std::vector<std::pair<std::string, double>>& metrics() {
  static std::vector<std::pair<std::string, double>> m;
  return m;
}
}  // namespace

void report_metric(const std::string& name, double value) { metrics().emplace_back(name, value); }
double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n == 0 ? 0.0 : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}
SceneRegistrar::SceneRegistrar(const char* name, std::function<void()> fn) {
  scenes().emplace_back(name, std::move(fn));
}

}  // namespace arc::bench

// arcfire-bench [--scenes-only] [--scene NAME] [google benchmark flags]
// No arguments: every micro-benchmark, then every headline scene, then the metric lines.
int main(int argc, char** argv) {
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
  if (!scenes_only && only_scene.empty()) benchmark::RunSpecifiedBenchmarks();
  for (auto& [name, fn] : arc::bench::scenes()) {
    if (filtered && only_scene.empty()) break;
    if (!only_scene.empty() && name != only_scene) continue;
    std::printf("scene %s\n", name.c_str());
    std::fflush(stdout);
    fn();
  }
  for (auto& [name, value] : arc::bench::metrics()) std::printf("metric %s %.6g\n", name.c_str(), value);
  benchmark::Shutdown();
  return 0;
}
