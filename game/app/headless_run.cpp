// `arcfire --headless` and `--demo`: a level simulated without a window, frames and a contact sheet.
#include "game/app/headless_run.h"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <vector>

#include "core/error.h"
#include "core/file_writer.h"
#include "game/app/audio_session.h"
#include "game/app/contact_sheet.h"
#include "game/app/frame_renderer.h"
#include "game/app/run_files.h"
#include "game/sim/game.h"
#include "game/sim/world.h"
#include "platform/stop_request.h"

namespace arc {
namespace {

std::string frame_name(const std::string& dir, uint64_t tick) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "frame_%06llu.png", static_cast<unsigned long long>(tick));
  return (std::filesystem::path(dir) / buf).string();
}

}  // namespace

int run_headless(const AppOptions& o) {
  const bool demo = o.demo;
  const std::string& level = o.level;
  std::string out = o.out_dir;
  if (demo && out.empty()) out = "out/demo";
  int64_t ticks = o.ticks > 0 ? o.ticks : (demo ? 3600 : 600);
  int64_t every = o.every > 0 ? o.every : (demo ? 60 : 30);
  const bool render = !o.no_render && !out.empty();

  // Every output is checked before the first tick: a bad path is refused, not found at the end.
  if (!out.empty()) check_output_dir(out, "--out");
  if (!o.summary_path.empty()) check_output_file(o.summary_path, "--summary");
  Game game = Game::load_level(level, o.game);
  RunFiles files = o.files;  // the ship classes, models and effects are known once the level is loaded
  add_level_inputs(files, game.world(), o.game.root_dir);
  if (demo && o.out_dir.empty())
    files.output_folder("--demo's folder", out, [](const std::string& n) { return n.ends_with(".png"); });
  files.check();
  std::unique_ptr<FrameRenderer> renderer;
  if (render) {
    FrameRendererDesc desc;
    desc.width = o.width;
    desc.height = o.height;
    renderer = std::make_unique<FrameRenderer>(desc, o.settings, game);
  }

  std::unique_ptr<AudioCapture> audio;
  if (!o.audio_out.empty()) audio = std::make_unique<AudioCapture>(o.sounds_path, o.settings, o.audio_out);

  std::vector<Image> frames;
  std::vector<std::string> written;
  // The demo ends two seconds after the battle is decided, so the sheet shows the fight.
  int64_t demo_end = -1;
  for (int64_t t = 1; t <= ticks; ++t) {
    if (demo && demo_end < 0 && game.world().outcome != Outcome::Undecided) demo_end = t + 120;
    if (t == demo_end) ticks = t;
    game.step(InputFrame{});
    if (audio) audio->after_tick(game.world());
    if (renderer && t % every == 0) {
      Image img = renderer->render(game);
      std::string path = frame_name(out, game.tick());
      save_image(path, img);
      written.push_back(path);
      if (demo) frames.push_back(std::move(img));
    }
    if (stop_requested()) break;  // SIGINT or SIGTERM: what the ticks so far made is written below
  }
  // Each write throws WriteError on failure (exit 1, one line): nothing below reports a file
  // that is not complete on disk.
  if (!o.summary_path.empty()) write_file_checked(o.summary_path, game.summary_json());
  if (audio) audio->finish();
  if (!written.empty())
    std::printf("arcfire: wrote %zu frames to %s/ (%s .. %s)\n", written.size(), out.c_str(),
                std::filesystem::path(written.front()).filename().c_str(),
                std::filesystem::path(written.back()).filename().c_str());
  if (demo && !frames.empty()) {
    std::string sheet = (std::filesystem::path(out) / "contact_sheet.png").string();
    save_image(sheet, make_contact_sheet(frames, 6, 320));
    std::printf("arcfire: contact sheet: %s\n", sheet.c_str());
  }
  if (!o.summary_path.empty()) std::printf("arcfire: summary: %s\n", o.summary_path.c_str());
  if (stop_requested()) return report_stop("at tick " + std::to_string(game.tick()) + " of " + std::to_string(ticks));
  std::printf("arcfire: simulated %lld ticks of %s\n", static_cast<long long>(ticks), level.c_str());
  return kExitOk;
}

}  // namespace arc
