// The effect workbench window: stage, orbit camera, panel and stats (see the header).
#include "game/workbench/workbench_window.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <imgui.h>
#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "assets/image.h"
#include "assets/model.h"
#include "assets/screenshot_writer.h"
#include "core/data_layers.h"
#include "core/error.h"
#include "core/json.h"
#include "game/workbench/effect_document.h"
#include "game/workbench/orbit_camera.h"
#include "game/workbench/panel_fields.h"
#include "game/workbench/panel_stage.h"
#include "game/workbench/stats_overlay.h"
#include "game/workbench/workbench_stage.h"
#include "gfx/renderer.h"
#include "gfx/screenshot.h"
#include "gfx/ui_texture.h"
#include "particles/sprites.h"
#include "platform/platform.h"
#include "platform/stop_request.h"
#include "ui/imgui_layer.h"

namespace arc {
namespace {

namespace fs = std::filesystem;

constexpr float kPanelWidth = 460.0f;  // px: the longest field label with its unit fits beside its widget

// With mods in use, a mod's effects are listed with the game's and saved where they came from.
std::vector<std::string> effect_files(const std::string& root) { return data_files(root, "assets/effects", ".json"); }

// The ship models (the "model" of each assets/ships/*.json) and the wall, into the renderer.
std::string sprite_path(const std::string& root, std::string_view name) {
  return data_file(root, "assets/textures/sprite_" + std::string(name) + ".png");
}

void load_stage_models(Renderer& renderer, const std::string& root, WorkbenchStage& stage) {
  auto load = [&](const std::string& path) {
    const ModelData data = load_model(data_file(root, path));
    StageModel m;
    m.name = fs::path(path).stem().string();
    m.id = renderer.add_model(data);
    m.bounds_min = data.bounds_min;
    m.bounds_max = data.bounds_max;
    m.radius = std::max(0.5, double(data.radius));
    return m;
  };
  const std::vector<std::string> ship_files = data_files(root, "assets/ships", ".json");
  std::vector<StageModel> ships;
  for (const std::string& f : ship_files) {
    // Parsed as the game parses it (core/json.h): a key written twice is refused here too.
    const std::shared_ptr<const JsonDoc> doc = JsonDoc::load_file(f);
    ships.push_back(load(doc->root().at("model").get<std::string>()));
  }
  stage.set_models(std::move(ships), load("assets/models/wall.glb"));
  std::vector<Image> sprites;
  for (std::string_view name : kSpriteNames)
    sprites.push_back(load_image(sprite_path(root, name)));
  renderer.set_sprites(sprites);
}

// What waits for the user's answer about unsaved edits: another effect, or quitting.
struct PendingLeave {
  bool asked = false;
  bool quit = false;
  size_t effect = 0;
};

class WorkbenchSession {
 public:
  explicit WorkbenchSession(const WorkbenchOptions& o) : options_(o) {}
  ~WorkbenchSession() { report_screenshots(screenshots_.wait()); }
  void setup();
  bool open() const { return !window_->should_close(); }
  double time() const { return window_->time_seconds(); }
  void frame(double frame_seconds);

 private:
  void open_effect(size_t index);
  void leave(bool quit, size_t effect);
  void handle_mouse();
  void handle_keys();
  void frame_effect();
  void save();
  void poll_disk();
  void draw_panel();
  void draw_file_section();
  void draw_leave_prompt();
  void draw_stats(int width, int height);
  void report_screenshots(const std::vector<ScreenshotWriter::Done>& shots);

  const WorkbenchOptions& options_;
  WorkbenchStage stage_;
  std::vector<std::string> files_;
  size_t current_ = 0;
  std::unique_ptr<EffectDocument> doc_;
  uint64_t shown_revision_ = ~uint64_t(0);  // the document revision the stage shows
  std::string error_;   // the last refused file or failed save, shown in the panel
  std::string notice_;  // the last save or reload
  bool conflict_ = false;  // changed on disk while there are unsaved edits
  PendingLeave pending_;
  double next_poll_ = 0.0;
  std::unique_ptr<Window> window_;
  std::unique_ptr<Renderer> renderer_;
  std::unique_ptr<ImGuiLayer> ui_;
  std::vector<std::unique_ptr<UiTexture>> thumbnails_;
  EffectPanel panel_;
  OrbitCamera camera_;
  StatsOverlay stats_;
  InputState devices_;
  RenderView view_;
  bool orbiting_ = false, panning_ = false;
  bool want_screenshot_ = false;  // F12: the next frame, panel included
  ScreenshotWriter screenshots_{"out/screenshots", "workbench"};  // written in the background
};

// A written screenshot is one line on stdout; a failed one goes to the panel's error line.
void WorkbenchSession::report_screenshots(const std::vector<ScreenshotWriter::Done>& shots) {
  for (const ScreenshotWriter::Done& shot : shots) {
    if (!shot.error.empty()) {
      std::fprintf(stderr, "arcfire: %s\n", shot.error.c_str());
      error_ = shot.error;
      continue;
    }
    std::printf("arcfire: screenshot %s\n", shot.path.c_str());
    std::fflush(stdout);
  }
}

void WorkbenchSession::setup() {
  files_ = effect_files(options_.root_dir);
  if (!options_.effect_path.empty()) {
    std::error_code ec;
    const fs::path wanted = fs::weakly_canonical(options_.effect_path, ec);
    auto same = [&](const std::string& f) { return fs::weakly_canonical(f, ec) == wanted; };
    current_ = size_t(std::find_if(files_.begin(), files_.end(), same) - files_.begin());
    if (current_ == files_.size()) files_.push_back(options_.effect_path);  // outside the folder: listed last
  }
  if (files_.empty()) throw InputError(options_.root_dir + "/assets/effects: no effect files");
  std::string error;
  doc_ = EffectDocument::open(files_[current_], error);
  if (!doc_) throw InputError(error);  // a bad file: the loader's line, exit 2
  if (!display_available())
    throw PlatformError("no display available for the workbench (DISPLAY is not set or cannot be opened)");
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
  std::vector<uint32_t> names;
  for (std::string_view name : kSpriteNames) {
    thumbnails_.push_back(std::make_unique<UiTexture>(load_image(sprite_path(options_.root_dir, name))));
    names.push_back(thumbnails_.back()->gl_name());
  }
  panel_.set_sprite_thumbnails(std::move(names));
  stage_.set_particle_limits(uint32_t(options_.settings.integer("particles.budget")),
                             int(options_.settings.integer("particles.lightning_interval")));
  stage_.set_effect(doc_->library(), doc_->name());
  shown_revision_ = doc_->revision();
  stage_.set_loop_seconds(stage_.effect_seconds(nullptr) + 0.25);
  stage_.scrub(8);  // a moment in, so there are particles to frame
  frame_effect();
  stage_.scrub(0);
}

void WorkbenchSession::open_effect(size_t index) {
  std::string error;
  std::unique_ptr<EffectDocument> doc = EffectDocument::open(files_[index], error);
  if (!doc) {
    error_ = error;
    return;
  }
  doc_ = std::move(doc);
  current_ = index;
  error_.clear();
  notice_.clear();
  conflict_ = false;
  panel_.forget_errors();
  stage_.set_effect(doc_->library(), doc_->name());
  shown_revision_ = doc_->revision();
  stage_.set_loop_seconds(stage_.effect_seconds(nullptr) + 0.25);
  stage_.scrub(0);
  stage_.set_playing(true);
}

// Another effect or quitting: at once without unsaved edits, else after the user's answer.
void WorkbenchSession::leave(bool quit, size_t effect) {
  if (doc_->dirty()) {
    pending_ = {true, quit, effect};
    return;
  }
  if (quit) window_->request_close();
  else open_effect(effect);
}

void WorkbenchSession::frame_effect() {
  glm::dvec3 centre;
  double radius = 1.0;
  stage_.bounds(centre, radius);
  camera_.frame(centre - stage_.focus(), radius);  // the camera's target is relative to the focus
}

void WorkbenchSession::save() {
  try {
    doc_->save();
    notice_ = "saved " + doc_->path();
    error_.clear();
  } catch (const InputError& e) {
    error_ = e.what();
  }
}

// Twice a second: a file changed on disk reloads unless there are unsaved edits; then the
// panel asks (keep mine / reload).
void WorkbenchSession::poll_disk() {
  if (window_->time_seconds() < next_poll_) return;
  next_poll_ = window_->time_seconds() + 0.5;
  switch (doc_->poll()) {
    case DiskChange::Unchanged: break;
    case DiskChange::Reloaded: notice_ = "reloaded: the file changed on disk"; break;
    case DiskChange::Conflict: conflict_ = true; break;
    case DiskChange::Invalid: error_ = "the file on disk is refused: " + doc_->disk_error(); break;
  }
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

// Ctrl+S, Ctrl+Z, Ctrl+Y (or Ctrl+Shift+Z), and the stage keys; not while a text field types.
// Presses are the window's counts (a tap shorter than a frame still counts); held keys repeat
// at ImGui's key-repeat rate.
void WorkbenchSession::handle_keys() {
  if (ui_->wants_keyboard()) return;
  const ImGuiIO& io = ImGui::GetIO();
  auto pressed = [&](const char* name) { return devices_.key_presses[size_t(key_code(name))] > 0; };
  auto repeated = [&](const char* name) {
    const int code = key_code(name);
    return pressed(name) || (io.KeysDownDuration[code] > io.KeyRepeatDelay && ImGui::IsKeyPressed(code, true));
  };
  auto down = [&](const char* name) { return devices_.keys[size_t(key_code(name))]; };
  const bool ctrl = down("LEFT_CONTROL") || down("RIGHT_CONTROL");
  const bool shift = down("LEFT_SHIFT") || down("RIGHT_SHIFT");
  if (ctrl) {
    if (pressed("S")) save();
    if (repeated("Z") && !shift) doc_->undo();
    if (repeated("Y") || (repeated("Z") && shift)) doc_->redo();
    return;
  }
  if (pressed("ESCAPE")) leave(true, current_);
  if (pressed("SPACE")) stage_.set_playing(!stage_.playing());
  if (repeated("LEFT")) stage_.step_by(-1);
  if (repeated("RIGHT")) stage_.step_by(1);
  if (pressed("HOME")) stage_.scrub(0);
  if (pressed("F")) frame_effect();
  if (pressed("F12")) want_screenshot_ = true;
}

void WorkbenchSession::draw_file_section() {
  std::vector<std::string> names;
  for (const std::string& f : files_) names.push_back(fs::path(f).stem().string());
  if (const int chosen = draw_effect_list(names, int(current_)); chosen >= 0 && size_t(chosen) != current_)
    leave(false, size_t(chosen));
  const fs::path shown = fs::proximate(doc_->path(), options_.root_dir);
  ImGui::TextDisabled("%s", (*shown.begin() == ".." ? fs::absolute(doc_->path()) : shown).c_str());
  if (ImGui::Button("Save")) save();
  ImGui::SameLine();
  ImGui::BeginDisabled(!doc_->can_undo());
  if (ImGui::Button("Undo")) doc_->undo();
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!doc_->can_redo());
  if (ImGui::Button("Redo")) doc_->redo();
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (doc_->dirty()) ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "unsaved edits");
  else ImGui::TextDisabled("%s", notice_.empty() ? "as on disk" : notice_.c_str());
  if (conflict_) {
    ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "The file changed on disk, and you have unsaved edits.");
    if (ImGui::Button("Keep mine")) doc_->keep_mine(), conflict_ = false;
    ImGui::SameLine();
    if (ImGui::Button("Reload from disk")) {
      const EditResult r = doc_->reload();
      if (!r.ok) error_ = r.message;
      else notice_ = "reloaded from disk (Undo brings your edits back)";
      conflict_ = false;
    }
  }
  if (!error_.empty()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", error_.c_str());
    ImGui::PopTextWrapPos();
  }
}

void WorkbenchSession::draw_leave_prompt() {
  if (pending_.asked && !ImGui::IsPopupOpen("Unsaved edits")) ImGui::OpenPopup("Unsaved edits");
  if (!ImGui::BeginPopupModal("Unsaved edits", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  ImGui::Text("%s has unsaved edits.", doc_->name().c_str());
  const bool save_it = ImGui::Button("Save");
  ImGui::SameLine();
  const bool discard = ImGui::Button("Discard");
  ImGui::SameLine();
  const bool cancel = ImGui::Button("Cancel");
  if (save_it) save();
  if ((save_it && !doc_->dirty()) || discard) {
    const PendingLeave p = pending_;
    pending_ = {};
    ImGui::CloseCurrentPopup();
    if (p.quit) window_->request_close();
    else open_effect(p.effect);
  } else if (cancel || (save_it && doc_->dirty())) {
    pending_ = {};
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

void WorkbenchSession::draw_panel() {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(kPanelWidth, io.DisplaySize.y), ImGuiCond_Always);
  ImGui::Begin("Effect workbench", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                                ImGuiWindowFlags_NoCollapse);
  draw_file_section();
  if (ImGui::CollapsingHeader("Stage", ImGuiTreeNodeFlags_DefaultOpen)) {
    draw_backdrop_section(stage_);
    ImGui::TextDisabled("drag orbit, right-drag pan, wheel zoom, double-click frame");
  }
  if (ImGui::CollapsingHeader("Time", ImGuiTreeNodeFlags_DefaultOpen)) draw_time_section(stage_);
  if (ImGui::CollapsingHeader("Effect file", ImGuiTreeNodeFlags_DefaultOpen)) panel_.draw(*doc_);
  draw_leave_prompt();
  ImGui::End();
}

void WorkbenchSession::draw_stats(int width, int height) {
  const EffectCounts counts = stage_.counts();
  StageFigures figures;
  if (const EffectDef* def = stage_.effect())
    for (const ClusterDef& c : def->clusters) figures.cluster_names.push_back(c.name);
  figures.live_per_cluster = counts.cluster_particles;
  figures.live = counts.live_particles;
  figures.budget = stage_.particle_budget();
  figures.scene_pixels = width * height;
  stats_.draw(figures, renderer_->last_stats(), width);
}

void WorkbenchSession::frame(double frame_seconds) {
  window_->poll(devices_);
  ui_->begin_frame();
  poll_disk();
  handle_mouse();
  handle_keys();
  draw_panel();
  if (doc_->revision() != shown_revision_) {  // an edit, undo, redo or reload: the next frame shows it
    stage_.set_effect(doc_->library(), doc_->name());
    shown_revision_ = doc_->revision();
  }
  stats_.record_frame(frame_seconds);
  const int width = window_->framebuffer_width(), height = window_->framebuffer_height();
  draw_stats(width, height);
  OrbitCamera following = camera_;  // on the circling ship, the camera flies with it
  following.target += stage_.focus();
  CameraView cam = following.view();
  if (width > 0 && height > 0) {
    // Slid sideways, not turned: the target shows in the middle of the view beside the panel.
    const double half_width = std::tan(cam.fov_y_radians * 0.5) * following.distance * double(width) / height;
    cam.position -= cam.orientation * glm::dvec3(half_width * kPanelWidth / width, 0.0, 0.0);
  }
  ParticleCamera pc;
  pc.position = cam.position;
  pc.orientation = cam.orientation;
  pc.fov_y_radians = cam.fov_y_radians;
  pc.aspect = height > 0 ? double(width) / height : 1.0;
  pc.near_plane = cam.near_plane;
  stage_.set_camera(pc);
  stage_.advance(frame_seconds);
  if (width > 0 && height > 0) {
    stage_.build_view(cam, width, height, view_);
    renderer_->render(view_, width, height);
  }
  ui_->end_frame();
  // Read before the swap leaves the back buffer undefined; encoded and written by a worker.
  if (want_screenshot_ && width > 0 && height > 0) screenshots_.save(read_window_pixels(width, height));
  want_screenshot_ = false;
  report_screenshots(screenshots_.finished());
  window_->swap();
}

}  // namespace

int run_workbench(const WorkbenchOptions& options) {
  WorkbenchSession session(options);
  session.setup();
  double last = session.time();
  while (session.open() && !stop_requested()) {  // Ctrl+C or a kill closes as the close button does
    const double now = session.time();
    session.frame(now - last);
    last = now;
  }
  return stop_requested() ? report_stop("in the workbench") : kExitOk;  // ~WorkbenchSession waits for the screenshots
}

}  // namespace arc
