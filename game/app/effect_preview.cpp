// `arcfire --headless --preview`: one effect's filmstrip and stats, rendered without a window.
#include "game/app/effect_preview.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <vector>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "assets/image.h"
#include "assets/model.h"
#include "core/data_layers.h"
#include "core/error.h"
#include "core/file_writer.h"
#include "core/json.h"
#include "game/app/app_options.h"
#include "game/app/scene_resources.h"
#include "game/workbench/effect_timeline.h"
#include "gfx/renderer.h"
#include "platform/platform.h"
#include "platform/stop_request.h"

namespace arc {
namespace {

namespace fs = std::filesystem;

constexpr double kFovY = 0.9;       // radians
constexpr int kGutter = 4;          // pixels between frames
constexpr double kTickRate = 60.0;  // the timeline's default tick

std::vector<std::string> model_names(const std::string& root_dir) {
  std::vector<std::string> names;
  for (const std::string& f : data_files(root_dir, "assets/models", ".glb"))
    if (fs::path(f).stem() != "wall") names.push_back(fs::path(f).stem().string());
  return names;
}

// The ticks of the centres of N equal slices of the effect's life (at least tick 1, all distinct).
std::vector<uint64_t> sample_ticks(double life_seconds, int frames) {
  std::vector<uint64_t> ticks;
  for (int i = 0; i < frames; ++i) {
    const uint64_t t = std::max<uint64_t>(1, uint64_t(std::llround(life_seconds * kTickRate * (i + 0.5) / frames)));
    ticks.push_back(ticks.empty() ? t : std::max(t, ticks.back() + 1));
  }
  return ticks;
}

struct Bounds {
  glm::dvec3 centre{0.0};
  double radius = 5.0;
};

// A sphere around nine in ten particles of all the sampled moments (the farthest strays would
// shrink the effect to a dot), seen from far up the +Z axis with a wide view so none is culled.
Bounds effect_bounds(EffectTimeline& timeline, const std::vector<uint64_t>& ticks) {
  ParticleCamera far;
  far.position = {0.0, 0.0, 5000.0};
  far.fov_y_radians = 3.0;
  far.aspect = 1.0;
  std::vector<glm::dvec3> centres;
  std::vector<double> sizes;
  std::vector<ParticleInstance> drawn;
  for (uint64_t t : ticks) {
    timeline.scrub_to(t, far);
    drawn.clear();
    timeline.world().collect(far, drawn);
    for (const ParticleInstance& p : drawn) {
      centres.push_back(far.position + glm::dvec3(p.pos[0], p.pos[1], p.pos[2]));
      sizes.push_back(p.size + 0.5 * glm::length(glm::dvec3(p.axis[0], p.axis[1], p.axis[2])));
    }
  }
  Bounds b;
  if (centres.empty()) return b;
  glm::dvec3 sum(0.0);
  for (const glm::dvec3& c : centres) sum += c;
  b.centre = sum / double(centres.size());
  std::vector<double> reach;
  for (size_t i = 0; i < centres.size(); ++i) reach.push_back(glm::length(centres[i] - b.centre) + sizes[i]);
  std::sort(reach.begin(), reach.end());
  b.radius = std::max(0.5, reach[reach.size() * 9 / 10]);
  return b;
}

CameraView frame_camera(const Bounds& b, double aspect) {
  const glm::dvec3 toward_camera = glm::normalize(glm::dvec3(0.45, 0.35, 1.0));
  const double half = 0.5 * kFovY * std::min(1.0, aspect);  // the narrower of the two view angles
  CameraView c;
  c.fov_y_radians = kFovY;
  c.position = b.centre + toward_camera * (b.radius / std::sin(half) * 1.05);
  c.orientation = glm::quatLookAt(-toward_camera, glm::dvec3(0, 1, 0));
  c.near_plane = std::clamp(b.radius * 0.01, 0.05, 0.5);
  return c;
}

// The wall behind the effect's centre, its thinnest side facing the camera, wide enough to fill the view.
MeshInstance wall_instance(ModelId id, const ModelData& wall, const Bounds& b, const CameraView& camera) {
  const glm::vec3 size = wall.bounds_max - wall.bounds_min;
  const int thin = size.x <= size.y && size.x <= size.z ? 0 : size.y <= size.z ? 1 : 2;
  glm::dvec3 thin_axis(0.0);
  thin_axis[thin] = 1.0;
  const glm::dvec3 facing = glm::normalize(camera.position - b.centre);
  MeshInstance m;
  m.model = id;
  const double d = glm::dot(thin_axis, facing);
  const glm::dvec3 axis = glm::cross(thin_axis, facing);
  m.orientation = d < -1.0 + 1e-9 ? glm::dquat(1, 0, 0, 0) : glm::normalize(glm::dquat(1.0 + d, axis.x, axis.y, axis.z));
  const float wide = std::max({size[(thin + 1) % 3], size[(thin + 2) % 3], 1e-3f});
  m.scale = 3.0 * b.radius / wide;
  const glm::vec3 mid = (wall.bounds_min + wall.bounds_max) * 0.5f;
  // A third of the way back: most of the effect in front, its far side cut by the wall.
  m.position = b.centre - facing * (b.radius / 3.0) - m.orientation * (glm::dvec3(mid) * m.scale);
  return m;
}

// A trail laid along the emitter's path ("spacing") shows only behind a moving owner.
bool lays_a_trail(const EffectDef& def) {
  for (const ClusterDef& c : def.clusters)
    if (c.emitter.spacing > 0.0) return true;
  return false;
}

std::string label(uint64_t tick, uint32_t particles) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2f s  %u particles", double(tick) / kTickRate, particles);
  return buf;
}

Image filmstrip(const std::vector<Image>& frames) {
  Image strip;
  const int w = frames[0].width, h = frames[0].height, n = int(frames.size());
  strip.width = n * w + (n + 1) * kGutter;
  strip.height = h + 2 * kGutter;
  strip.rgba.assign(size_t(strip.width) * size_t(strip.height) * 4, 0);
  for (size_t i = 0; i < strip.rgba.size(); i += 4) strip.rgba[i] = 24, strip.rgba[i + 1] = 24, strip.rgba[i + 2] = 28, strip.rgba[i + 3] = 255;
  for (int f = 0; f < n; ++f)
    for (int y = 0; y < h; ++y)
      std::copy_n(&frames[size_t(f)].rgba[size_t(y) * size_t(w) * 4], size_t(w) * 4,
                  &strip.rgba[(size_t(y + kGutter) * size_t(strip.width) + size_t(kGutter + f * (w + kGutter))) * 4]);
  return strip;
}

}  // namespace

PreviewOptions preview_options(const AppOptions& app) {
  PreviewOptions o;
  o.effect_path = app.preview_path;
  o.out_dir = app.out_dir;
  if (app.size_given) o.frame_width = app.width, o.frame_height = app.height;
  o.frames = app.preview_frames;
  o.backdrop = app.preview_backdrop;
  o.settings = app.settings;
  return o;
}

std::string check_preview_backdrop(const std::string& backdrop, const std::string& root_dir) {
  if (backdrop == "space" || backdrop == "wall") return "";
  const std::vector<std::string> models = model_names(root_dir);
  if (std::find(models.begin(), models.end(), backdrop) != models.end()) return "";
  std::vector<std::string> allowed{"space", "wall"};
  allowed.insert(allowed.end(), models.begin(), models.end());
  return "--backdrop: must be " + join_allowed(allowed) + ", got '" + backdrop + "'";
}

int run_preview(const PreviewOptions& o) {
  auto fx = std::make_shared<EffectLibrary>();
  fx->load_file(o.effect_path);
  const std::string name = fs::path(o.effect_path).stem().string();
  const std::string backdrop_error = check_preview_backdrop(o.backdrop, o.root_dir);
  if (!backdrop_error.empty()) throw InputError(backdrop_error);
  check_output_dir(o.out_dir, "--out");

  StageOptions stage;
  stage.motion = lays_a_trail(fx->get(name)) ? StageMotion::Circle : StageMotion::Still;
  EffectTimeline timeline(fx, name, stage);
  bool ends = false;
  const double life = EffectTimeline::life_seconds(fx->get(name), &ends);
  const std::vector<uint64_t> ticks = sample_ticks(life, o.frames);
  const Bounds bounds = effect_bounds(timeline, ticks);
  const double aspect = double(o.frame_width) / double(o.frame_height);
  RenderView view;
  view.camera = frame_camera(bounds, aspect);

  auto context = create_headless_context();
  RendererDesc rd;
  rd.shader_dir = o.root_dir + "/shaders";
  rd.offscreen = true;
  Renderer renderer(rd);
  renderer.apply_settings(o.settings);
  renderer.count_particle_fragments(true);
  load_sprites(renderer, o.root_dir);
  if (o.backdrop == "wall") {
    const ModelData wall = load_model(data_file(o.root_dir, "assets/models/wall.glb"));
    view.meshes.push_back(wall_instance(renderer.add_model(wall), wall, bounds, view.camera));
  } else if (o.backdrop != "space") {
    view.meshes.push_back({renderer.add_model(load_model(data_file(o.root_dir, "assets/models/" + o.backdrop + ".glb")))});
  }

  ParticleCamera cam;
  cam.position = view.camera.position;
  cam.orientation = view.camera.orientation;
  cam.fov_y_radians = kFovY;
  cam.aspect = aspect;
  cam.near_plane = view.camera.near_plane;
  std::vector<Image> frames;
  nlohmann::json stats_frames = nlohmann::json::array();
  for (uint64_t t : ticks) {
    if (stop_requested()) break;
    timeline.scrub_to(t, cam);
    const EffectCounts counts = timeline.frame_stats();
    view.particles.clear();
    timeline.world().collect(cam, view.particles);
    view.time_seconds = double(t) / kTickRate;
    const std::string text = label(t, counts.live_particles);
    view.hud.quads = {{2.0f, 2.0f, 8.0f + 7.0f * float(text.size()), 18.0f, {0.0f, 0.0f, 0.0f, 0.6f}}};
    view.hud.texts = {{6.0f, 4.0f, 1.0f, {1.0f, 1.0f, 1.0f, 0.95f}, text}};
    renderer.restart_smoothing();  // each frame stands alone, as if it were the first
    renderer.render(view, o.frame_width, o.frame_height);
    frames.push_back(renderer.read_pixels());
    const FrameStats drawn = renderer.last_stats();
    nlohmann::json clusters = nlohmann::json::object();
    for (size_t c = 0; c < counts.cluster_particles.size(); ++c)
      clusters[fx->get(name).clusters[c].name] = counts.cluster_particles[c];
    stats_frames.push_back({{"tick", t}, {"time_s", double(t) / kTickRate}, {"particles", counts.live_particles},
                            {"clusters", clusters}, {"drawn", drawn.particles_drawn},
                            {"blended_pixels", drawn.particle_fragments}});
  }
  // SIGINT or SIGTERM: a strip short of frames would pass for the effect's whole life.
  if (stop_requested())
    return report_stop("at frame " + std::to_string(frames.size()) + " of " + std::to_string(ticks.size()) +
                       "; no filmstrip written");
  const std::string strip_path = (fs::path(o.out_dir) / "filmstrip.png").string();
  save_image(strip_path, filmstrip(frames));
  const nlohmann::json stats = {{"effect", name}, {"life_s", life}, {"ends", ends}, {"backdrop", o.backdrop},
                                {"frame_size", {o.frame_width, o.frame_height}}, {"frames", stats_frames}};
  write_file_atomic((fs::path(o.out_dir) / "stats.json").string(), stats.dump(2) + "\n");
  std::printf("arcfire: %s: %d frames over %.2f s in %s (stats.json beside it)\n", name.c_str(), o.frames, life,
              strip_path.c_str());
  return kExitOk;
}

}  // namespace arc
