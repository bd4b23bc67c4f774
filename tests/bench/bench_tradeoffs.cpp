// tradeoffs: every setting that trades speed for accuracy, measured against the reference
// preset in one run. Rows go to out/tradeoffs.csv (tools/plot_tradeoffs.py draws
// them, with the Pareto front and the presets, into out/tradeoffs.png).
//
// Rendering: the reference preset with ONE render key changed per row (soft-edge method,
// sorting, depth mode, texture filter, render scale, sky baked at each resolution, HDR, bloom,
// anti-aliasing, particle resolution, overdraw budget), the four presets of
// assets/settings/quality.json as they stand, and the whole configurations (kCandidates) the
// presets were chosen from. Three scenes at 1280×720: the gallery (tick 240),
// the arena battle (tick 600, chase camera) and tests/bench/closeup.json (tick 40: an explosion's
// fire and smoke and an engine plume cut by a Warden's hull, from 30 m). Each row's cost is the
// median over rounds of its frame ÷ the reference's frame of the same round (every row once
// per round, odd rounds backwards, each frame glFinish-bracketed, the overdraw budget's
// smoothing restarted), as the geometric mean over the three scenes; its error is the PSNR of
// its image against the reference's (99 dB when identical) and the share of pixels more than
// 5/255 off in some channel (the golden tolerance). Rows that change the render targets' size
// or format, or the baked sky, draw with a Renderer of their own, so no frame pays for
// reallocating or re-baking.
//
// Simulation: the arena's first 600 ticks (10 s) with the reference preset's simulation keys
// and ONE changed per row (sub-steps 1..8, lightning interval 1..8, particle budget, cull
// distance), each Game stepped tick by tick, interleaved, every step timed. Cost: ms per tick
// ÷ the reference's. Error against sub-steps 16: the farthest any ship is from where it is
// with sub-steps 16 (m), the particles present in one world and not the other (share), and
// the RMS distance between the birth points of particles present in both (m; particles move
// in closed form from their birth, so this is where they differ), and when a ship first
// strayed 1 m from its sub-steps-16 self (the AI's choices make the battle chaotic: once
// apart, ships end up hundreds of metres apart whatever the setting). The budget's rows add the
// share of spawned particles refused; the cull distance's the share of particle updates skipped.
//
// Metrics: preset_psnr_db_<name> (the worst of the three scenes), preset_frame_ratio_<name>
// (geometric mean of the scenes' ratios), tradeoff_rows. ARCFIRE_BENCH_ROUNDS=N (default 3)
// rounds; ARCFIRE_GFX_DUMP=DIR saves each scene's reference and preset images.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "bench_registry.h"
#include "bench_scenes.h"
#include "core/settings.h"
#include "game/app/all_settings.h"
#include "game/app/app_options.h"
#include "game/app/scene_resources.h"
#include "game/render/render_view_builder.h"
#include "game/sim/game.h"
#include "game/sim/input.h"
#include "game/sim/world.h"
#include "gfx/image_compare.h"
#include "gfx/renderer.h"
#include "particles/world_state.h"
#include "platform/platform.h"
#include "core/data_root.h"

namespace arc {
namespace {

constexpr int kWidth = 1280, kHeight = 720;
// A function, not a constant: the data root is looked up when a scene runs, where a missing one
// is the bench's one-line error, not an exception before main.
std::string quality_file() { return arc::data_root() + "/assets/settings/quality.json"; }
const char* const kPresets[] = {"low", "medium", "high", "reference"};

Settings preset(const std::string& name) {
  Settings s = all_settings();
  s.apply_preset_file(quality_file(), name);
  return s;
}

// One row of the table: a configuration and what was measured for it.
struct Row {
  std::string kind;     // "render", "preset" or "sim"
  std::string setting;  // the key changed from the reference ("" for the reference, the preset's name)
  std::string value;
  Settings settings;
  RenderSettings render;
  // rendering, per scene
  std::vector<double> ratio, psnr, off;
  std::vector<std::vector<double>> round_ms;  // [scene][round]
  // simulation
  double sim_ms = 0, ship_m = 0, unmatched = 0, birth_rms_m = 0, refused = 0, skipped = 0;
  double diverged_s = -1;  // game time when a ship first strayed 1 m from sub-steps 16; −1: never
  double diverged_ref_s = -1;  // the same from the reference preset's simulation
  std::vector<double> tick_ms;
  double cost = 0;  // frame or tick ratio against the reference
};

// Whole configurations the presets were chosen from (applied to all_settings(), as a
// preset is): cheap and accurate combinations of the settings above. Two more were chosen and
// are measured as the presets now: "accurate_s1.25_msaa2" (scale 1.25, msaa2, sky 512, bloom
// high, full-resolution particles) became high, "s1_aa_off" (scale 1, no AA, bloom high,
// full-resolution particles) medium; the old high and medium are kept here for comparison.
const std::pair<const char*, const char*> kCandidates[] = {
    {"accurate_s1.5_aa_off", "render.scale=1.5 render.antialias=off render.sky_resolution=512 render.bloom=high render.hdr=true"
                             " render.particle_resolution=full"},
    {"accurate_s1.5_msaa2", "render.scale=1.5 render.antialias=msaa2 render.sky_resolution=512 render.bloom=high render.hdr=true"
                            " render.particle_resolution=full"},
    {"accurate_s1.25_aa_off", "render.scale=1.25 render.antialias=off render.sky_resolution=512 render.bloom=high"
                              " render.hdr=true render.particle_resolution=full"},
    {"s1_aa_off_auto", "render.scale=1 render.antialias=off render.bloom=high render.hdr=true"},
    {"s0.75_aa_off", "render.scale=0.75 render.antialias=off render.bloom=low render.hdr=true"},
    {"s0.75_linear_cluster", "render.scale=0.75 render.antialias=off render.bloom=low render.hdr=true render.soft_edges=linear"
                             " render.sorting=cluster"},
    {"old_high", "render.soft_edges=effect render.sorting=full render.texture_filter=mipmap_nearest render.scale=1"
                 " render.particle_resolution=full render.hdr=true render.bloom=high render.antialias=fxaa"},
    {"old_medium", "render.soft_edges=linear render.sorting=cluster render.texture_filter=mipmap_nearest render.scale=0.75"
                   " render.particle_resolution=auto render.hdr=true render.bloom=low render.antialias=fxaa"},
    {"s0.5_hdr", "render.scale=0.5 render.antialias=off render.bloom=low render.hdr=true render.soft_edges=off"
                 " render.sorting=off render.particle_resolution=half render.sky_resolution=128"},
    {"s0.5_hdr_soft", "render.scale=0.5 render.antialias=off render.bloom=low render.hdr=true render.soft_edges=linear"
                      " render.sorting=cluster render.sky_resolution=128"},
};

using KeySweep = std::vector<std::pair<std::string, std::vector<std::string>>>;

// The reference preset, one row for each value of each key changed from it alone, then each
// preset as it stands. The baked sky's keys switch the reference's exact sky to baked first, or
// they would change nothing.
std::vector<Row> sweep_from_reference(const char* kind, const KeySweep& keys, const char* preset_kind) {
  std::vector<Row> rows;
  Row ref;
  ref.kind = kind;
  ref.settings = preset("reference");
  rows.push_back(ref);
  for (const auto& [key, values] : keys)
    for (const std::string& v : values) {
      Row r = ref;
      r.setting = key;
      r.value = v;
      if (key == "render.sky_resolution" || key == "render.sky_grid") r.settings.set("render.sky", "baked", "tradeoffs");
      r.settings.set(key, v, "tradeoffs");
      rows.push_back(r);
    }
  for (const char* name : kPresets) {
    Row p;
    p.kind = preset_kind;
    p.setting = name;
    p.settings = preset(name);
    rows.push_back(p);
  }
  return rows;
}

std::vector<Row> render_rows() {
  const KeySweep keys = {
      {"render.soft_edges", {"off", "linear", "contrast", "average_density", "density_extent"}},
      {"render.sorting", {"off", "cluster"}},
      {"render.particle_prep", {"cluster"}},
      {"render.depth_mode", {"standard"}},
      {"render.texture_filter", {"nearest", "linear", "mipmap_nearest"}},
      {"render.scale", {"0.5", "0.75", "1", "1.5"}},
      {"render.sky_resolution", {"64", "128", "256", "512", "1024"}},  // with render.sky=baked
      {"render.sky_grid", {"0", "8", "16", "32"}},                       // with render.sky=baked
      {"render.hdr", {"false"}},
      {"render.bloom", {"off", "low"}},
      {"render.antialias", {"off", "fxaa", "msaa2"}},
      {"render.particle_resolution", {"half", "auto"}},
      {"render.overdraw_budget", {"4", "3", "2"}},
  };
  std::vector<Row> rows = sweep_from_reference("render", keys, "preset");
  for (const auto& [name, keys_text] : kCandidates) {
    Row c;
    c.kind = "candidate";
    c.setting = name;
    c.value = keys_text;
    c.settings = all_settings();
    std::istringstream words(keys_text);
    for (std::string kv; words >> kv;) c.settings.set_from_text(kv, "tradeoffs candidate " + c.setting);
    rows.push_back(c);
  }
  return rows;
}

// What decides a Renderer's targets and baked sky: rows that differ in it draw with different
// Renderers, so switching rows between frames reallocates nothing.
std::string target_key(const RenderSettings& s) {
  char k[96];
  std::snprintf(k, sizeof k, "%.3f/%d/%d/%d/%d", s.scale, int(s.hdr), int(s.antialias), s.sky_exact ? 0 : s.sky_resolution,
                int(s.particle_resolution));
  return k;
}

struct Scene {
  const char* name;
  const char* level;
  int tick;
};
const Scene kScenes[] = {{"gallery", "levels/gallery.json", 240},
                         {"battle", "levels/arena.json", 600},
                         {"closeup", "tests/bench/closeup.json", 40}};

double timed_frame(Renderer& r, const Row& row, const RenderView& view) {
  r.set_render_settings(row.render);
  r.restart_smoothing();
  r.finish();
  const double t0 = bench::now_seconds();
  r.render(view, kWidth, kHeight);
  r.finish();
  return (bench::now_seconds() - t0) * 1000.0;
}

// One scene: every row's frame in interleaved rounds, then its image against the reference's.
// Long: the renderers per target key, the warm-up, the rounds and the comparison belong together.
void measure_scene(const Scene& sc, std::vector<Row>& rows, int rounds) {
  const std::string root = arc::data_root();
  GameOptions options;
  options.root_dir = root;
  Game game = Game::load_level(root + "/" + sc.level, options);
  for (int t = 0; t < sc.tick; ++t) game.step(InputFrame{});
  std::map<std::string, std::unique_ptr<Renderer>> renderers;
  std::vector<Renderer*> of_row;
  RenderView view;
  for (Row& row : rows) {
    std::unique_ptr<Renderer>& r = renderers[target_key(row.render)];
    if (!r) {
      r = std::make_unique<Renderer>(RendererDesc{.offscreen = true});
      const std::vector<ModelId> models = load_scene_resources(*r, game.world(), root);
      if (view.meshes.empty() && view.particles.empty()) {
        HudState hud;
        hud.show_hud = false;
        build_render_view(game.world(), models, 1.0, CameraSettings{}, hud, kWidth, kHeight, view);
      }
    }
    of_row.push_back(r.get());
  }
  std::vector<Image> images(rows.size());
  for (size_t i = 0; i < rows.size(); ++i) {  // warm-up (programs, bakes) and the images compared
    timed_frame(*of_row[i], rows[i], view);
    images[i] = of_row[i]->read_pixels();
  }
  for (Row& row : rows) row.round_ms.emplace_back();
  for (int round = 0; round < rounds; ++round)
    for (size_t k = 0; k < rows.size(); ++k) {
      const size_t i = round % 2 ? rows.size() - 1 - k : k;
      rows[i].round_ms.back().push_back(timed_frame(*of_row[i], rows[i], view));
    }
  const std::vector<double>& ref_ms = rows[0].round_ms.back();
  for (size_t i = 0; i < rows.size(); ++i) {
    Row& row = rows[i];
    std::vector<double> q;
    for (int k = 0; k < rounds; ++k) q.push_back(row.round_ms.back()[size_t(k)] / ref_ms[size_t(k)]);
    row.ratio.push_back(bench::median(q));
    const double p = psnr_db(images[0], images[i]);
    row.psnr.push_back(std::isfinite(p) ? std::min(p, 99.0) : 99.0);
    const ImageDiff d = compare_images(images[0], images[i]);
    row.off.push_back(1.0 - d.fraction_within);
  }
  if (const char* dir = std::getenv("ARCFIRE_GFX_DUMP"))
    for (size_t i = 0; i < rows.size(); ++i)
      if (rows[i].kind == "preset")
        save_image(std::string(dir) + "/tradeoffs_" + sc.name + "_" + rows[i].setting + ".png", images[i]);
  std::printf("  %-8s reference frame %.1f ms (median of %d)\n", sc.name, bench::median(ref_ms), rounds);
}


// ---- simulation ------------------------------------------------------------------------------

std::vector<Row> sim_rows() {
  const KeySweep keys = {
      {"sim.substeps", {"16", "8", "2", "1"}},
      {"particles.lightning_interval", {"1", "2", "4", "8"}},
      {"particles.budget", {"200000", "50000", "10000", "2000"}},
      {"particles.cull_distance", {"1000", "300", "100"}},
  };
  std::vector<Row> rows = sweep_from_reference("sim", keys, "preset_sim");
  return rows;
}

// World points where each particle was born, keyed by (cluster serial, particle uid).
std::map<std::pair<uint64_t, uint32_t>, glm::dvec3> birth_points(const ParticleWorld& pw) {
  const ParticleWorldState& w = ParticleWorldAccess::state(pw);
  std::map<std::pair<uint64_t, uint32_t>, glm::dvec3> out;
  for (const Cluster& c : w.slots) {
    if (!c.alive) continue;
    const Pose f = moves_with_frame(c) ? w.emitter_pose(c) : Pose{c.world_origin, glm::dquat(1, 0, 0, 0)};
    const ParticlePool& p = c.pool;
    for (size_t i = 0; i < p.count(); ++i)
      out[{c.serial, p.uid[i]}] = f.position + f.orientation * glm::dvec3(p.p0x[i], p.p0y[i], p.p0z[i]);
  }
  return out;
}

double ship_distance(const World& a, const World& b) {
  double d = 0;
  for (size_t i = 0; i < a.ships.size() && i < b.ships.size(); ++i)
    d = std::max(d, glm::length(a.ships[i].position - b.ships[i].position));
  return d;
}

// Ship and particle divergence of `got` from `want` (the same level and inputs).
void divergence(const World& want, const World& got, Row& row) {
  row.ship_m = ship_distance(want, got);
  const auto a = birth_points(*want.particles), b = birth_points(*got.particles);
  double sum = 0;
  size_t matched = 0;
  for (const auto& [id, p] : a) {
    auto it = b.find(id);
    if (it == b.end()) continue;
    sum += glm::dot(p - it->second, p - it->second);
    ++matched;
  }
  const size_t all = a.size() + b.size() - matched;
  row.unmatched = all ? double(all - matched) / double(all) : 0.0;
  row.birth_rms_m = matched ? std::sqrt(sum / double(matched)) : 0.0;
}

// Particles emitted since the last call (each cluster numbers its particles in turn; `seen`
// keeps each cluster's count by serial).
uint64_t admitted_since(const ParticleWorld& pw, std::map<uint64_t, uint32_t>& seen) {
  uint64_t n = 0;
  for (const Cluster& c : ParticleWorldAccess::state(pw).slots) {
    if (!c.alive) continue;
    uint32_t& last = seen[c.serial];
    n += c.next_uid - last;
    last = c.next_uid;
  }
  return n;
}

// The arena's first 600 ticks under every row's simulation keys, stepped tick by tick in turn.
void measure_simulation(std::vector<Row>& rows) {
  const std::string root = arc::data_root();
  std::vector<Game> games;
  for (const Row& row : rows) {
    GameOptions o;
    o.root_dir = root;
    apply_simulation_settings(row.settings, o);
    games.push_back(Game::load_level(root + "/levels/arena.json", o));
  }
  std::vector<uint64_t> skipped(rows.size(), 0), updates(rows.size(), 0), spawned(rows.size(), 0);
  std::vector<std::map<uint64_t, uint32_t>> uids(rows.size());
  size_t sixteen = 0;
  for (size_t i = 0; i < rows.size(); ++i)
    if (rows[i].setting == "sim.substeps" && rows[i].value == "16") sixteen = i;
  for (int t = 0; t < 600; ++t) {
    for (size_t k = 0; k < rows.size(); ++k) {
      const size_t i = t % 2 ? rows.size() - 1 - k : k;
      const double t0 = bench::now_seconds();
      games[i].step(InputFrame{});
      rows[i].tick_ms.push_back((bench::now_seconds() - t0) * 1000.0);
      const ParticleStats st = games[i].world().particles->stats();
      skipped[i] += st.skipped_particles;
      updates[i] += st.skipped_particles + st.animated_particles;
      spawned[i] += admitted_since(*games[i].world().particles, uids[i]);
    }
    for (size_t i = 0; i < rows.size(); ++i) {
      if (rows[i].diverged_s < 0 && ship_distance(games[sixteen].world(), games[i].world()) > 1.0)
        rows[i].diverged_s = double(t + 1) / 60.0;
      if (rows[i].diverged_ref_s < 0 && ship_distance(games[0].world(), games[i].world()) > 1.0)
        rows[i].diverged_ref_s = double(t + 1) / 60.0;
    }
  }
  for (size_t i = 0; i < rows.size(); ++i) {
    Row& row = rows[i];
    std::vector<double> q;
    for (size_t t = 0; t < row.tick_ms.size(); ++t) q.push_back(row.tick_ms[t] / rows[0].tick_ms[t]);
    row.sim_ms = bench::median(row.tick_ms);
    row.cost = bench::median(q);
    divergence(games[sixteen].world(), games[i].world(), row);
    const ParticleStats st = games[i].world().particles->stats();
    row.refused = double(st.refused_particles) / double(std::max<uint64_t>(1, st.refused_particles + spawned[i]));
    row.skipped = updates[i] ? double(skipped[i]) / double(updates[i]) : 0.0;
  }
}

// ---- output ----------------------------------------------------------------------------------

double geometric_mean(const std::vector<double>& v) {
  double l = 0;
  for (double x : v) l += std::log(std::max(x, 1e-9));
  return v.empty() ? 0.0 : std::exp(l / double(v.size()));
}

std::string label(const Row& r) {
  if (r.kind == "preset" || r.kind == "preset_sim") return "preset " + r.setting;
  if (r.kind == "candidate") return "candidate " + r.setting;
  return r.setting.empty() ? "reference" : r.setting + "=" + r.value;
}

std::string seconds_or_never(double s) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3f", s);
  return s < 0 ? std::string("never") : std::string(b);
}

void write_csv(const std::vector<Row>& render, const std::vector<Row>& sim) {
  std::filesystem::create_directories("out");
  std::FILE* f = std::fopen("out/tradeoffs.csv", "w");
  if (!f) {
    std::printf("  cannot write out/tradeoffs.csv\n");
    return;
  }
  std::fprintf(f, "kind,setting,value,cost_ratio,psnr_min_db,psnr_gallery_db,psnr_battle_db,psnr_closeup_db,"
                  "pixels_off_gallery,pixels_off_battle,pixels_off_closeup,sim_ms_per_tick,ship_divergence_m,"
                  "particles_unmatched_share,particle_birth_rms_m,refused_share,skipped_update_share,ship_diverged_after_s,ship_diverged_from_reference_after_s\n");
  for (const Row& r : render)
    std::fprintf(f, "%s,%s,%s,%.4f,%.3f,%.3f,%.3f,%.3f,%.5f,%.5f,%.5f,,,,,,,,\n", r.kind.c_str(), r.setting.c_str(),
                 r.value.c_str(), r.cost, *std::min_element(r.psnr.begin(), r.psnr.end()), r.psnr[0], r.psnr[1], r.psnr[2],
                 r.off[0], r.off[1], r.off[2]);
  for (const Row& r : sim)
    std::fprintf(f, "%s,%s,%s,%.4f,,,,,,,,%.4f,%.6g,%.5f,%.6g,%.5f,%.5f,%s,%s\n", r.kind.c_str(), r.setting.c_str(),
                 r.value.c_str(), r.cost, r.sim_ms, r.ship_m, r.unmatched, r.birth_rms_m, r.refused, r.skipped,
                 seconds_or_never(r.diverged_s).c_str(), seconds_or_never(r.diverged_ref_s).c_str());
  std::fclose(f);
  std::printf("  wrote out/tradeoffs.csv (%zu rows)\n", render.size() + sim.size());
}

void print_tables(const std::vector<Row>& render, const std::vector<Row>& sim) {
  std::printf("  %-38s %7s %8s %8s %8s %8s  %s\n", "render row", "cost", "worst dB", "gallery", "battle", "closeup",
              "pixels off (g/b/c)");
  for (const Row& r : render)
    std::printf("  %-38s x%6.3f %8.2f %8.2f %8.2f %8.2f  %.4f %.4f %.4f\n", label(r).c_str(), r.cost,
                *std::min_element(r.psnr.begin(), r.psnr.end()), r.psnr[0], r.psnr[1], r.psnr[2], r.off[0], r.off[1], r.off[2]);
  std::printf("  %-38s %7s %9s %10s %10s %10s %8s %8s %9s %9s\n", "simulation row", "cost", "ms/tick", "ship m", "unmatched",
              "birth rms", "refused", "skipped", "1 m at s", "from ref");
  for (const Row& r : sim)
    std::printf("  %-38s x%6.3f %9.3f %10.4g %10.4f %10.4g %8.4f %8.4f %9s %9s\n", label(r).c_str(), r.cost, r.sim_ms,
                r.ship_m, r.unmatched, r.birth_rms_m, r.refused, r.skipped, seconds_or_never(r.diverged_s).c_str(),
                seconds_or_never(r.diverged_ref_s).c_str());
}

}  // namespace

ARCFIRE_SCENE(tradeoffs) {
  const int rounds = bench::rounds_from_env(3);
  std::vector<Row> sim = sim_rows();
  std::printf(" simulation: levels/arena.json, 600 ticks, %zu configurations interleaved\n", sim.size());
  measure_simulation(sim);
  const std::unique_ptr<HeadlessContext> ctx = bench::context_or_skip();
  if (!ctx) return;
  std::vector<Row> render = render_rows();
  {
    Renderer probe(RendererDesc{.offscreen = true});
    for (Row& r : render) {
      probe.apply_settings(r.settings);
      r.render = probe.render_settings();
    }
  }
  std::printf(" rendering: %zu configurations, 3 scenes at %dx%d, %d interleaved rounds; %s\n", render.size(), kWidth,
              kHeight, rounds, ctx->description().c_str());
  for (const Scene& sc : kScenes) measure_scene(sc, render, rounds);
  for (Row& r : render) r.cost = geometric_mean(r.ratio);
  print_tables(render, sim);
  write_csv(render, sim);
  for (const Row& r : render) {
    if (r.kind != "preset") continue;
    bench::report_metric("preset_psnr_db_" + r.setting, *std::min_element(r.psnr.begin(), r.psnr.end()));
    bench::report_metric("preset_frame_ratio_" + r.setting, r.cost);
  }
  for (const Row& r : sim)
    if (r.kind == "preset_sim") bench::report_metric("preset_sim_tick_ratio_" + r.setting, r.cost);
  bench::report_metric("tradeoff_rows", double(render.size() + sim.size()));
}

}  // namespace arc
