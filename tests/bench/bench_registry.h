// tests/bench/bench_registry.h — headline scenes and metric lines for arcfire-bench.
//
// Google Benchmark runs first (micro-benchmarks registered with BENCHMARK as usual). Then every
// headline scene registered with ARCFIRE_SCENE runs once, in registration order, and reports
// figures with report_metric(); the run ends with one `metric NAME VALUE` line per figure.
// Ratios are measured within the same run, because the machines are shared and noisy.
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace arc::bench {

void report_metric(const std::string& name, double value);
// Marks the run failed (arcfire-bench exits 1 after printing the metrics), with one line why.
void report_failure(const std::string& why);
// Wall-clock seconds (steady clock) for scenes.
double now_seconds();
// The median of a set of timings or ratios (0 when empty).
double median(std::vector<double> v);

struct SceneRegistrar {
  // on_request: run only when named by --scene (long runs such as the soak).
  SceneRegistrar(const char* name, std::function<void()> fn, bool on_request = false);
};

}  // namespace arc::bench

#define ARCFIRE_SCENE_CAT2(a, b) a##b
#define ARCFIRE_SCENE_CAT(a, b) ARCFIRE_SCENE_CAT2(a, b)
#define ARCFIRE_SCENE(name)                                                              \
  static void name();                                                                    \
  static ::arc::bench::SceneRegistrar ARCFIRE_SCENE_CAT(scene_reg_, __LINE__){#name, name}; \
  static void name()
#define ARCFIRE_SCENE_ON_REQUEST(name)                                                         \
  static void name();                                                                          \
  static ::arc::bench::SceneRegistrar ARCFIRE_SCENE_CAT(scene_reg_, __LINE__){#name, name, true}; \
  static void name()
