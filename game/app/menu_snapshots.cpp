// The menu headless: scripted UI inputs, the attract demo behind, a PNG and a text per screen.
#include "game/app/menu_snapshots.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

#include "core/data_layers.h"
#include "core/error.h"
#include "core/file_writer.h"
#include "core/json.h"
#include "core/settings.h"
#include "game/app/campaign.h"
#include "game/app/frame_renderer.h"
#include "game/app/key_remap.h"
#include "game/app/quick_battle_files.h"
#include "game/sim/game.h"
#include "game/sim/world.h"
#include "platform/stop_request.h"

namespace arc {
namespace {

constexpr int kTicksPerInput = 20;  // the demo behind moves on a third of a second per input

struct MenuRun {
  const AppOptions& o;
  std::string out;
  Menu menu;
  std::unique_ptr<Game> game;
  std::unique_ptr<FrameRenderer> renderer;
  int shot = 0;

  void advance(int ticks) {
    for (int i = 0; i < ticks && !stop_requested(); ++i) game->step(InputFrame{});
  }

  void load(const std::string& level, Difficulty d, const std::string& ship = "", const std::string& loadout = "") {
    GameOptions g = o.game;
    g.difficulty = d;
    g.difficulty_override = true;
    g.ship = ship;
    g.loadout = loadout;
    game = std::make_unique<Game>(Game::load_level(level, g));
    if (renderer) renderer->load_level(*game);
  }

  void snapshot() {
    const MenuPage page = menu.page();
    char name[64];
    std::snprintf(name, sizeof name, "%02d_%s", shot++, menu_screen_name(menu.screen()));
    const std::string text = describe_page(page);
    std::printf("== %s\n%s", name, text.c_str());
    if (out.empty()) return;
    const std::string base = (std::filesystem::path(out) / name).string();
    write_file_atomic(base + ".txt", text);
    if (!renderer) return;
    HudState hud;
    hud.show_hud = hud.show_outcome = !menu.open();
    HudLayer overlay;
    if (menu.open()) layout_menu(page, o.width, o.height, overlay, nullptr);
    save_image(base + ".png", renderer->render(*game, 1.0, hud, overlay));
  }

  // A launched level is fought without input until decided; the results open over it.
  void fight(const MenuRequest& launch) {
    load(launch.level, launch.difficulty, launch.ship, launch.loadout);
    const int64_t limit = o.ticks > 0 ? o.ticks : 7200;
    for (int64_t t = 0; t < limit && game->world().outcome == Outcome::Undecided && !stop_requested(); ++t)
      game->step(InputFrame{});
    if (stop_requested()) return;  // an unfinished fight has no results to show or keep
    advance(60);
    snapshot();
    carry_out(menu.show_results(launch.level, launch.difficulty, mission_result(game->world())));
  }

  void carry_out(const std::vector<MenuRequest>& requests) {
    for (const MenuRequest& r : requests) {
      if (r.kind == MenuRequest::Kind::Launch && !r.generated.empty()) write_generated_level(r.level, r.generated);
      if (r.kind == MenuRequest::Kind::Launch) fight(r);
      if (r.kind == MenuRequest::Kind::SaveQuickBattle) save_quick_setup(user_config_dir(), menu.quick_setup());
      if (r.kind == MenuRequest::Kind::SaveSettings) save_settings(user_config_dir(), menu.settings());
      if (r.kind == MenuRequest::Kind::SaveProgress) save_progress(user_config_dir(), menu.progress());
    }
  }
};

Menu make_menu(const AppOptions& o) {
  const std::string root = o.game.root_dir;
  UserFiles files = load_user_files(user_config_dir(), data_file(root, "assets/settings/quality.json"));
  Bindings b = load_bindings(data_file(root, "assets/settings/bindings.json"));
  Bindings flown = b;
  apply_user_settings(files.settings, flown);
  // The window's catalog: the campaign's missions and ship unlocks with the rest.
  Menu menu(load_catalog_with_campaign(root), files, flown, b, data_file(root, "assets/settings/quality.json"));
  offer_quick_battle(menu, root, files.dir);
  return menu;
}

}  // namespace

std::vector<UiInput> parse_ui_inputs(const std::string& text, const std::string& path) {
  std::vector<UiInput> out;
  std::istringstream lines(text);
  std::string line;
  for (int n = 1; std::getline(lines, line); ++n) {
    line = line.substr(0, line.find('#'));
    std::istringstream words(line);
    std::string w;
    auto fail = [&](const std::string& what) {
      const size_t col = line.find(w) + 1;
      throw InputError(path + ":" + std::to_string(n) + ":" + std::to_string(col) + ": " + what);
    };
    while (words >> w) {
      static const std::vector<std::pair<std::string, UiKey>> keys = {
          {"up", UiKey::Up}, {"down", UiKey::Down}, {"left", UiKey::Left}, {"right", UiKey::Right},
          {"accept", UiKey::Accept}, {"back", UiKey::Back}};
      auto k = std::find_if(keys.begin(), keys.end(), [&](const auto& p) { return p.first == w; });
      if (k != keys.end()) {
        out.push_back(UiInput::press(k->second));
        continue;
      }
      std::string arg;
      if ((w != "click" && w != "hover" && w != "bind") || !(words >> arg))
        fail("unknown UI input '" + w + "'; allowed: up, down, left, right, accept, back, click N, hover N, bind KEY");
      if (w == "bind") {
        if (code_of_label(arg) < 0) fail("'" + arg + "' is not a key name (A, SPACE, MOUSE_LEFT, PAD_A, ...)");
        out.push_back(UiInput::bind(code_of_label(arg)));
      } else {
        const int item = std::atoi(arg.c_str());
        out.push_back(w == "click" ? UiInput::click(item) : UiInput::hover(item));
      }
    }
  }
  return out;
}

std::string describe_page(const MenuPage& p) {
  std::string out = "title: " + p.title + "\n";
  if (!p.subtitle.empty()) out += "subtitle: " + p.subtitle + "\n";
  if (!p.paragraph.empty()) out += "paragraph: " + p.paragraph + "\n";
  for (const std::string& l : p.lines) out += "line: " + l + "\n";
  for (size_t i = 0; i < p.items.size(); ++i) out += (int(i) == p.selection ? "> " : "  ") + p.items[i] + "\n";
  if (!p.message.empty()) out += "message: " + p.message + "\n";
  return out;
}

int run_menu_script(const AppOptions& o) {
  const std::vector<UiInput> inputs = parse_ui_inputs(read_text_file(o.menu_script, kMaxScriptFileBytes, "a menu script"), o.menu_script);
  if (!o.out_dir.empty()) check_output_dir(o.out_dir, "--out");  // before any screen is driven
  MenuRun run{o, o.out_dir, make_menu(o), nullptr, nullptr};
  const std::string attract = data_file(o.game.root_dir, "levels/attract.json");
  run.load(attract, o.game.difficulty);
  run.advance(180);
  if (!run.out.empty()) {
    FrameRendererDesc desc;
    desc.width = o.width;
    desc.height = o.height;
    desc.root_dir = o.game.root_dir;
    if (!o.no_render) run.renderer = std::make_unique<FrameRenderer>(desc, o.settings, *run.game);
    if (run.renderer) run.menu.set_machine(run.renderer->gl_renderer());
  }
  if (!stop_requested()) run.snapshot();
  // SIGINT or SIGTERM: at the end of the tick; the screens written so far stay.
  size_t done = 0;
  for (; done < inputs.size() && !stop_requested(); ++done) {
    const MenuScreen before = run.menu.screen();
    run.carry_out(run.menu.handle(inputs[done]));
    if (run.menu.screen() == MenuScreen::Main && before == MenuScreen::Results) run.load(attract, Difficulty::Normal);
    run.advance(kTicksPerInput);
    if (!stop_requested()) run.snapshot();
  }
  if (!stop_requested()) return kExitOk;
  return report_stop("at UI input " + std::to_string(done) + " of " + std::to_string(inputs.size()));
}

}  // namespace arc
