// The effect workbench window: stage, orbit camera, panel and stats (see the header).
#include "game/workbench/workbench_window.h"

#include <algorithm>
#include <filesystem>
#include <imgui.h>
#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "assets/image.h"
#include "assets/model.h"
#include "core/error.h"
#include "core/json.h"
#include "game/workbench/orbit_camera.h"
#include "game/workbench/panel_stage.h"
#include "game/workbench/stats_overlay.h"
#include "game/workbench/workbench_stage.h"
#include "gfx/renderer.h"
#include "particles/sprites.h"
#include "platform/platform.h"
#include "ui/imgui_layer.h"

namespace arc {
namespace {

namespace fs = std::filesystem;

constexpr float kPanelWidth = 420.0f;

std::vector<std::string> effect_files(const std::string& root) {
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(fs::path(root) / "assets/effects"))
    if (e.path().extension() == ".json") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

// The ship models (the "model" of each assets/ships/*.json) and the wall, into the renderer.
void load_stage_models(Renderer& renderer, const std::string& root, WorkbenchStage& stage) {
  auto load = [&](const std::string& path) {
    const ModelData data = load_model((fs::path(root) / path).string());
    StageModel m;
    m.name = fs::path(path).stem().string();
    m.id = renderer.add_model(data);
    m.bounds_min = data.bounds_min;
    m.bounds_max = data.bounds_max;
    m.radius = std::max(0.5, double(data.radius));
    return m;
  };
  std::vector<std::string> ship_files;
  for (const auto& e : fs::directory_iterator(fs::path(root) / "assets/ships"))
    if (e.path().extension() == ".json") ship_files.push_back(e.path().string());
  std::sort(ship_files.begin(), ship_files.end());
  std::vector<StageModel> ships;
  for (const std::string& f : ship_files) {
    const nlohmann::json j = nlohmann::json::parse(read_text_file(f), nullptr, true, true);
    ships.push_back(load(j.at("model").get<std::string>()));
  }
  stage.set_models(std::move(ships), load("assets/models/wall.glb"));
  std::vector<Image> sprites;
  for (std::string_view name : kSpriteNames)
    sprites.push_back(load_image((fs::path(root) / ("assets/textures/sprite_" + std::string(name) + ".png")).string()));
  renderer.set_sprites(sprites);
}

class WorkbenchSession {
 public:
  explicit WorkbenchSession(const WorkbenchOptions& o)
      : options_(o), stage_(uint32_t(o.settings.integer("particles.budget"))) {}
  void setup();
  bool open() const { return !window_->should_close(); }
  double time() const { return window_->time_seconds(); }
  void frame(double frame_seconds);

 private:
  void open_effect(size_t index);
  void handle_mouse();
  void handle_keys();
  void frame_effect();
  void draw_panel();

  const WorkbenchOptions& options_;
  WorkbenchStage stage_;
  std::vector<std::string> files_;
  size_t current_ = 0;
  std::string error_;  // the last refused file, shown in the panel
  std::unique_ptr<Window> window_;
  std::unique_ptr<Renderer> renderer_;
  std::unique_ptr<ImGuiLayer> ui_;
  OrbitCamera camera_;
  StatsOverlay stats_;
  InputState devices_;
  RenderView view_;
  bool orbiting_ = false, panning_ = false;
};

void WorkbenchSession::setup() {
  files_ = effect_files(options_.root_dir);
  if (files_.empty()) throw InputError(options_.root_dir + "/assets/effects: no effect files");
  if (!options_.effect_path.empty()) {
    const fs::path wanted = fs::weakly_canonical(options_.effect_path);
    auto same = [&](const std::string& f) { return fs::weakly_canonical(f) == wanted; };
    current_ = size_t(std::find_if(files_.begin(), files_.end(), same) - files_.begin());
    if (current_ == files_.size()) files_.push_back(options_.effect_path);  // outside the folder: listed last
  }
  stage_.set_effect(read_text_file(files_[current_]), files_[current_]);  // bad file: its line, exit 2
  WindowDesc wd;
  wd.width = options_.width;
  wd.height = options_.height;
  wd.vsync = options_.vsync;
  wd.title = "Arcfire workbench";
  window_ = open_window(wd);
  window_->set_mouse_captured(false);
  RendererDesc rd;
  rd.shader_dir = options_.root_dir + "/shaders";
  renderer_ = std::make_unique<Renderer>(rd);
  renderer_->apply_settings(options_.settings);
  renderer_->count_particle_fragments(true);  // the overlay's blended pixels
  renderer_->time_gpu_passes(true);
  load_stage_models(*renderer_, options_.root_dir, stage_);
  ui_ = std::make_unique<ImGuiLayer>();
  stage_.scrub(8);  // a moment in, so the first frame has particles to frame
  frame_effect();
  stage_.scrub(0);
}

void WorkbenchSession::open_effect(size_t index) {
  try {
    stage_.set_effect(read_text_file(files_[index]), files_[index]);
    current_ = index;
    error_.clear();
    stage_.scrub(0);
    stage_.set_playing(true);
  } catch (const InputError& e) {
    error_ = e.what();
  }
}

void WorkbenchSession::frame_effect() {
  glm::dvec3 centre;
  double radius = 1.0;
  stage_.bounds(centre, radius);
  camera_.frame(centre, radius);
}

// Left drag orbits, right drag pans, the wheel zooms, a double click frames: only where the
// panel does not have the mouse.
void WorkbenchSession::handle_mouse() {
  const ImGuiIO& io = ImGui::GetIO();
  if (!ui_->wants_mouse()) {
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) orbiting_ = true;
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Right)) panning_ = true;
    if (io.MouseWheel != 0.0f) camera_.zoom(io.MouseWheel);
    if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) frame_effect();
  }
  if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) orbiting_ = false;
  if (!ImGui::IsMouseDown(ImGuiMouseButton_Right)) panning_ = false;
  if (orbiting_) camera_.drag(io.MouseDelta.x, io.MouseDelta.y);
  if (panning_) {
    const CameraView v = camera_.view();
    const double per_pixel = camera_.distance * 2.0 * std::tan(camera_.fov_y * 0.5) / std::max(1.0f, io.DisplaySize.y);
    camera_.target += v.orientation * glm::dvec3(-io.MouseDelta.x * per_pixel, io.MouseDelta.y * per_pixel, 0.0);
  }
}

void WorkbenchSession::handle_keys() {
  if (ui_->wants_keyboard()) return;
  auto pressed = [](const char* name) { return ImGui::IsKeyPressed(key_code(name), false); };
  auto repeated = [](const char* name) { return ImGui::IsKeyPressed(key_code(name), true); };
  if (pressed("ESCAPE")) window_->request_close();
  if (pressed("SPACE")) stage_.set_playing(!stage_.playing());
  if (repeated("LEFT")) stage_.step_by(-1);
  if (repeated("RIGHT")) stage_.step_by(1);
  if (pressed("HOME")) stage_.scrub(0);
  if (pressed("F")) frame_effect();
}

void WorkbenchSession::draw_panel() {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(kPanelWidth, io.DisplaySize.y), ImGuiCond_Always);
  ImGui::Begin("Effect workbench", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                                ImGuiWindowFlags_NoCollapse);
  std::vector<std::string> names;
  for (const std::string& f : files_) names.push_back(fs::path(f).stem().string());
  if (const int chosen = draw_effect_list(names, int(current_)); chosen >= 0) open_effect(size_t(chosen));
  ImGui::TextDisabled("%s", files_[current_].c_str());
  if (!error_.empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", error_.c_str());
  if (ImGui::CollapsingHeader("Stage", ImGuiTreeNodeFlags_DefaultOpen)) {
    draw_backdrop_section(stage_);
    ImGui::TextDisabled("drag: orbit  right drag: pan  wheel: zoom  double-click or F: frame");
  }
  if (ImGui::CollapsingHeader("Time", ImGuiTreeNodeFlags_DefaultOpen)) draw_time_section(stage_);
  ImGui::End();
}

void WorkbenchSession::frame(double frame_seconds) {
  window_->poll(devices_);
  ui_->begin_frame();
  handle_mouse();
  handle_keys();
  draw_panel();
  stats_.record_frame(frame_seconds);
  const int width = window_->framebuffer_width(), height = window_->framebuffer_height();
  StageFigures figures;
  if (const EffectDef* def = stage_.effect())
    for (const ClusterDef& c : def->clusters) figures.cluster_names.push_back(c.name);
  figures.live_per_cluster = stage_.live_per_cluster();
  figures.live = stage_.live_particles();
  figures.budget = stage_.particle_budget();
  figures.scene_pixels = width * height;
  stats_.draw(figures, renderer_->last_stats(), width);
  const CameraView cam = camera_.view();
  ParticleCamera pc;
  pc.position = cam.position;
  pc.orientation = cam.orientation;
  pc.fov_y_radians = cam.fov_y_radians;
  pc.aspect = height > 0 ? double(width) / height : 1.0;
  stage_.set_camera(pc);
  stage_.advance(frame_seconds);
  if (width > 0 && height > 0) {
    stage_.build_view(cam, width, height, view_);
    renderer_->render(view_, width, height);
  }
  ui_->end_frame();
  window_->swap();
}

}  // namespace

int run_workbench(const WorkbenchOptions& options) {
  if (!display_available())
    throw PlatformError("no display available for the workbench (DISPLAY is not set or cannot be opened)");
  WorkbenchSession session(options);
  session.setup();
  double last = session.time();
  while (session.open()) {
    const double now = session.time();
    session.frame(now - last);
    last = now;
  }
  return kExitOk;
}

}  // namespace arc
