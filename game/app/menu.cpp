// The menu state machine: screens, their items, navigation, settings changes, remapping,
// results and the pause screen.
#include "game/app/menu.h"

#include "game/app/campaign.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "game/app/all_settings.h"
#include "game/app/key_remap.h"
#include "game/app/menu_items.h"
#include "game/sim/world.h"

namespace arc {

namespace {

std::string clock_text(double seconds) {
  char buf[32];
  const int minutes = int(seconds / 60.0);
  std::snprintf(buf, sizeof buf, "%d:%04.1f", minutes, seconds - minutes * 60.0);
  return buf;
}

std::string number_text(const char* format, double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string percent(double share) { return number_text("%.0f %%", share * 100.0); }

std::string result_text(const MissionResult& r) {
  return std::string(r.victory ? "won in " : "lost after ") + clock_text(r.seconds) + ", " + std::to_string(r.kills) +
         (r.kills == 1 ? " kill" : " kills");
}

}  // namespace

MissionResult mission_result(const World& w) {
  MissionResult r;
  r.victory = w.outcome == Outcome::Victory;
  r.seconds = double(w.outcome != Outcome::Undecided ? w.outcome_tick : w.tick) * w.dt;
  if (!w.player) return r;
  const Ship& me = w.ship(w.player);
  r.kills = me.kills;
  r.damage_dealt = me.stats.damage_dealt;
  r.damage_taken = me.stats.damage_taken;
  r.beam_accuracy = accuracy(me.stats.beam_hit_ticks, me.stats.beam_ticks);
  r.missile_accuracy = accuracy(me.stats.missiles_hit, me.stats.missiles_fired);
  if (!w.mission) return r;
  for (size_t i = 0; i < w.mission->objectives.size(); ++i) {
    const ObjectiveProgress& o = w.mission->objectives[i];
    const bool primary = w.level.events.objectives[i].kind == ObjectiveKind::Primary;
    if (!primary && !o.revealed) continue;  // a hidden objective never found does not count
    const bool done = o.status == ObjectiveStatus::Done;
    (primary ? r.primary_total : r.bonus_total) += 1;
    (primary ? r.primary_done : r.bonus_done) += done ? 1 : 0;
  }
  return r;
}

const char* menu_screen_name(MenuScreen s) {
  switch (s) {
    case MenuScreen::Main: return "main";
    case MenuScreen::Missions: return "missions";
    case MenuScreen::Effects: return "effects";
    case MenuScreen::Briefing: return "briefing";
    case MenuScreen::Settings: return "settings";
    case MenuScreen::Graphics: return "graphics";
    case MenuScreen::Sound: return "sound";
    case MenuScreen::Controls: return "controls";
    case MenuScreen::Keys: return "keys";
    case MenuScreen::Advanced: return "advanced";
    case MenuScreen::Results: return "results";
    case MenuScreen::Pause: return "pause";
    case MenuScreen::Closed: return "closed";
    case MenuScreen::QuickBattle: return "quick";
    case MenuScreen::Multiplayer: return "multiplayer";
    case MenuScreen::NetHost: return "host";
    case MenuScreen::NetJoin: return "join";
    case MenuScreen::Lobby: return "lobby";
  }
  return "?";
}

Menu::Menu(std::vector<MissionInfo> catalog, UserFiles files, Bindings bindings, Bindings default_bindings,
           const std::string& quality_file)
    : catalog_(std::move(catalog)),
      files_(std::move(files)),
      bindings_(std::move(bindings)),
      default_bindings_(std::move(default_bindings)),
      presets_(Settings::preset_names(quality_file)),
      quality_file_(quality_file),
      message_(files_.message) {
  // The quality file's presets come in name order; offer them from cheap to exact, with the
  // built-in settings ("default") after low.
  presets_.push_back(kDefaultQuality);
  const std::vector<std::string> known = {"low", kDefaultQuality, "medium", "high", "reference"};
  auto rank = [&](const std::string& p) { return std::find(known.begin(), known.end(), p) - known.begin(); };
  std::stable_sort(presets_.begin(), presets_.end(), [&](const auto& a, const auto& b) { return rank(a) < rank(b); });
  refresh_effective();
}

Menu::Menu(UserFiles files) : files_(std::move(files)), screen_(MenuScreen::Closed), has_main_(false) {}

void Menu::refresh_effective() {
  try {
    effective_ = user_quality_settings(files_.settings, quality_file_);
  } catch (const InputError& e) {
    effective_ = all_settings();
    message_ = e.what();
  }
}

std::vector<const MissionInfo*> Menu::listed() const {
  const MissionCategory want = screen_ == MenuScreen::Effects ? MissionCategory::Effects : MissionCategory::Mission;
  std::vector<const MissionInfo*> out;
  for (const MissionInfo& m : catalog_)
    if (m.category == want) out.push_back(&m);
  return out;
}

std::vector<Menu::Item> Menu::items() const {
  switch (screen_) {
    case MenuScreen::Main:
      // Multiplayer and Quick battle before Quit: the rows above keep their places.
      if (has_quick_) return {Item::Play, Item::Effects, Item::Settings, Item::Multiplayer, Item::QuickBattle, Item::Quit};
      return {Item::Play, Item::Effects, Item::Settings, Item::Multiplayer, Item::Quit};
    case MenuScreen::QuickBattle: return quick_items();
    case MenuScreen::Multiplayer:
    case MenuScreen::NetHost:
    case MenuScreen::NetJoin:
    case MenuScreen::Lobby: return net_items();
    case MenuScreen::Missions:
    case MenuScreen::Effects: {
      std::vector<Item> v(listed().size(), screen_ == MenuScreen::Missions ? Item::Mission : Item::Effect);
      if (screen_ == MenuScreen::Missions) v.push_back(Item::Difficulty);
      v.push_back(Item::Back);
      return v;
    }
    case MenuScreen::Briefing: return briefing_items();
    case MenuScreen::Settings:
    case MenuScreen::Graphics:
    case MenuScreen::Sound:
    case MenuScreen::Controls:
    case MenuScreen::Keys:
    case MenuScreen::Advanced: return settings_items();
    case MenuScreen::Results: {
      std::vector<Item> v{Item::Retry};
      if (const MissionInfo* n = next_mission(catalog_, chosen_); n && !mission_locked(catalog_, files_.progress, n->path))
        v.push_back(Item::Next);
      v.push_back(Item::ToMenu);
      return v;
    }
    case MenuScreen::Pause: {
      // After victory or defeat Retry comes first.
      std::vector<Item> v = pause_.outcome.empty() ? std::vector<Item>{Item::Resume, Item::Restart}
                                                   : std::vector<Item>{Item::Restart, Item::Resume};
      v.insert(v.end(), {Item::PauseDifficulty, Item::PauseSound, Item::Volume});
      if (has_main_) v.push_back(Item::MainMenu);
      v.push_back(Item::Quit);
      return v;
    }
    case MenuScreen::Closed: return {};
  }
  return {};
}

std::string Menu::best_text(const std::string& level) const {
  auto it = files_.progress.best.find(progress_key(level, difficulty_name(difficulty_)));
  return it == files_.progress.best.end() ? "no result yet" : result_text(it->second);
}

// "Campaign 3. Cargo Run   best: won in 0:57, 3 kills  gold", or "(locked)" until the one before is won.
std::string Menu::campaign_label(const MissionInfo& m) const {
  std::string label = "Campaign " + std::to_string(m.campaign) + ". " + m.title;
  label.resize(std::max<size_t>(label.size() + 2, 32), ' ');
  if (mission_locked(catalog_, files_.progress, m.path)) return label + "(locked)";
  auto it = files_.progress.best.find(progress_key(m.path, difficulty_name(difficulty_)));
  const std::string medal = it == files_.progress.best.end() ? "" : medal_name(mission_medal(it->second));
  return label + "best: " + best_text(m.path) + (medal.empty() ? "" : "  " + medal);
}

std::string Menu::item_label(Item item, int index) const {
  switch (item) {
    case Item::Play: return "Play";
    case Item::Effects: return "Effects";
    case Item::Settings: return "Settings";
    case Item::Quit: return "Quit";
    case Item::Mission: {
      const MissionInfo& m = *listed()[size_t(index)];
      if (m.campaign > 0) return campaign_label(m);
      std::string label = (m.mod.empty() ? "" : "[" + m.mod + "] ") + std::to_string(m.order) + ". " + m.title;
      label.resize(std::max<size_t>(label.size() + 2, 24), ' ');
      return label + "best: " + best_text(m.path);
    }
    case Item::Effect: return listed()[size_t(index)]->title;
    case Item::Difficulty: return std::string("Difficulty: < ") + difficulty_name(difficulty_) + " >";
    case Item::Launch: return "Launch";
    case Item::Ship:
    case Item::Loadout: return choice_label(item);
    case Item::Back: return "Back";
    case Item::Retry: return "Retry";
    case Item::Next: return "Next mission: " + next_mission(catalog_, chosen_)->title;
    case Item::ToMenu: return "Menu";
    default: {
      if (const std::string net = net_label(item, index); !net.empty()) return net;
      if (const std::string quick = quick_label(item); !quick.empty()) return quick;
      const std::string pause = pause_label(item);
      return pause.empty() ? settings_label(item, index) : pause;
    }
  }
}

void Menu::fill_briefing_page(MenuPage& p) const {
  const MissionInfo* m = find_mission(catalog_, chosen_);
  if (!m) return;
  p.title = m->title;
  p.subtitle = "Objective: " + m->objective;
  p.paragraph = m->chapter.empty() ? m->briefing : m->chapter + " " + m->briefing;
  p.lines.push_back(std::string("Difficulty: ") + difficulty_name(difficulty_) + "   (Left/Right changes it)");
  fill_choice_lines(p);
  p.lines.push_back(std::string("Best (") + difficulty_name(difficulty_) + "): " + best_text(m->path));
}

void Menu::fill_results_page(MenuPage& p) const {
  const MissionInfo* m = find_mission(catalog_, chosen_);
  const MissionResult& r = last_;
  p.title = r.victory ? "VICTORY" : "DEFEAT";
  p.title_tone = r.victory ? 1 : -1;
  p.subtitle = (m ? m->title : is_quick_level(chosen_) ? "Quick battle" : chosen_) + " (" + difficulty_name(difficulty_) + ")";
  p.lines = {"Time              " + clock_text(r.seconds),
             "Kills             " + std::to_string(r.kills),
             "Damage dealt      " + number_text("%.0f", r.damage_dealt),
             "Damage taken      " + number_text("%.0f", r.damage_taken),
             "Beam accuracy     " + percent(r.beam_accuracy),
             "Missile accuracy  " + percent(r.missile_accuracy),
             !last_is_best_ ? "Best so far: " + best_text(chosen_)
             : r.victory    ? "New best!"
                            : "Your best try yet (no win so far)"};
  if (is_quick_level(chosen_)) p.lines.pop_back();  // a generated battle keeps no best
  for (const std::string& ship : new_ships_) p.lines.push_back("New ship unlocked: " + ship);
  if (r.primary_total + r.bonus_total == 0) return;
  const auto best_line = p.lines.end() - 1 - std::ptrdiff_t(new_ships_.size());
  // Objectives and the medal go above the best-so-far line.
  const std::string medal = medal_name(mission_medal(r));
  p.lines.insert(best_line,
                 {"Objectives        " + std::to_string(r.primary_done) + "/" + std::to_string(r.primary_total) +
                      (r.bonus_total ? "   bonus " + std::to_string(r.bonus_done) + "/" + std::to_string(r.bonus_total) : ""),
                  "Medal             " + (medal.empty() ? std::string("none") : medal)});
}

MenuPage Menu::page() const {
  MenuPage p;
  const std::vector<Item> list = items();
  for (size_t i = 0; i < list.size(); ++i) p.items.push_back(item_label(list[i], int(i)));
  p.selection = selection_;
  p.message = message_;
  p.hint = "Up/Down or mouse: choose   Enter / A: select   Esc / B: back";
  switch (screen_) {
    case MenuScreen::Main: p.title = "ARCFIRE"; p.subtitle = "space combat with lightning"; break;
    case MenuScreen::Missions: p.title = "MISSIONS"; p.subtitle = "Left/Right: difficulty"; break;
    case MenuScreen::Effects: p.title = "EFFECTS"; p.subtitle = "every particle effect, on its own"; break;
    case MenuScreen::Briefing: fill_briefing_page(p); break;
    case MenuScreen::Settings:
    case MenuScreen::Graphics:
    case MenuScreen::Sound:
    case MenuScreen::Controls:
    case MenuScreen::Keys:
    case MenuScreen::Advanced: fill_settings_page(p); break;
    case MenuScreen::Results: fill_results_page(p); break;
    case MenuScreen::QuickBattle: fill_quick_page(p); break;
    case MenuScreen::Multiplayer:
    case MenuScreen::NetHost:
    case MenuScreen::NetJoin:
    case MenuScreen::Lobby: fill_net_page(p); break;
    case MenuScreen::Pause:
      p.title = pause_.outcome.empty() ? "PAUSED" : pause_.outcome;
      p.title_tone = pause_.outcome_tone;
      p.hint = "Up/Down or mouse: choose   Enter: select   Left/Right: change   Esc: resume";
      break;
    case MenuScreen::Closed: break;
  }
  return p;
}

void Menu::go(MenuScreen s) {
  screen_ = s;
  selection_ = 0;
  confirm_ = -1;
  capturing_ = false;
  editing_ = false;
}

void Menu::open_main() {
  go(has_main_ ? MenuScreen::Main : MenuScreen::Closed);
  message_.clear();
}

std::vector<MenuRequest> Menu::handle(const UiInput& in) {
  if (screen_ == MenuScreen::Closed) return {};
  if (capturing_) {
    if (in.kind == UiInput::Kind::Bind) return editing_ ? net_type(in.code) : bind(in.code);
    if (in.kind == UiInput::Kind::Key && in.key == UiKey::Back) {
      capturing_ = false;
      message_ = editing_ ? "" : "Remap cancelled";
      editing_ = false;
    }
    return {};
  }
  const std::vector<Item> list = items();
  const int count = int(list.size());
  if (count == 0) return {};
  switch (in.kind) {
    case UiInput::Kind::Bind: return {};
    case UiInput::Kind::Hover:
      if (in.item < 0 || in.item >= count || in.item == selection_) return {};
      selection_ = in.item;
      if (confirm_ >= 0) confirm_ = -1, message_.clear();
      return {};
    case UiInput::Kind::Click:
      if (in.item < 0 || in.item >= count) return {};
      if (in.item != selection_) confirm_ = -1;
      selection_ = in.item;
      return accept(list[size_t(selection_)], selection_);
    case UiInput::Kind::Key: break;
  }
  switch (in.key) {
    case UiKey::Up:
    case UiKey::Down:
      selection_ = (selection_ + (in.key == UiKey::Down ? 1 : -1) + count) % count;
      if (confirm_ >= 0) confirm_ = -1, message_.clear();
      return {};
    case UiKey::Left:
    case UiKey::Right:
      if (confirm_ >= 0) confirm_ = -1, message_.clear();
      return adjust(list[size_t(selection_)], in.key == UiKey::Right ? 1 : -1);
    case UiKey::Accept: return accept(list[size_t(selection_)], selection_);
    case UiKey::Back: return back();
  }
  return {};
}

std::vector<MenuRequest> Menu::accept(Item item, int index) {
  using K = MenuRequest::Kind;
  switch (item) {
    case Item::Play: go(MenuScreen::Missions); return {};
    case Item::Effects: go(MenuScreen::Effects); return {};
    case Item::Settings: go(MenuScreen::Settings); return {};
    case Item::Quit: return {{K::Quit}};
    case Item::Mission:
      if (mission_locked(catalog_, files_.progress, listed()[size_t(index)]->path)) {
        message_ = "Locked: win the campaign mission before it first";
        return {};
      }
      chosen_ = listed()[size_t(index)]->path;
      go(MenuScreen::Briefing);
      reset_choice();
      return {};
    case Item::Effect: {
      const std::string level = listed()[size_t(index)]->path;
      go(MenuScreen::Closed);
      return {{K::Launch, level, difficulty_}};
    }
    case Item::Launch:
      go(MenuScreen::Closed);
      return {launch_request(chosen_)};
    case Item::Back: return back();
    case Item::Retry:
      go(MenuScreen::Closed);
      return {launch_request(chosen_)};
    case Item::Next: {
      const std::string level = next_mission(catalog_, chosen_)->path;
      go(MenuScreen::Closed);
      return {{K::Launch, level, difficulty_}};
    }
    case Item::ToMenu: open_main(); return {};
    case Item::QuickBattle: go(MenuScreen::QuickBattle); return {};
    case Item::Resume:
    case Item::Restart:
    case Item::PauseDifficulty:
    case Item::PauseSound:
    case Item::Volume:
    case Item::MainMenu: return pause_accept(item);
    case Item::QuickPlayer:
    case Item::QuickWingmen:
    case Item::QuickWing:
    case Item::QuickEnemies:
    case Item::QuickEnemy:
    case Item::QuickCapital:
    case Item::QuickAsteroids:
    case Item::QuickDifficulty:
    case Item::QuickLaunch: return quick_accept(item);
    case Item::Multiplayer:
    case Item::NetHostPage:
    case Item::NetJoinPage:
    case Item::NetName:
    case Item::NetMission:
    case Item::NetDifficulty:
    case Item::NetPort:
    case Item::NetOpen:
    case Item::NetAddress:
    case Item::NetRecent:
    case Item::NetConnect:
    case Item::LobbySlot:
    case Item::NetLaunch:
    case Item::NetLeave: return net_accept(item, index);
    default: return settings_accept(item);
  }
}

std::vector<MenuRequest> Menu::adjust(Item item, int step) {
  using K = MenuRequest::Kind;
  switch (item) {
    case Item::Mission:
    case Item::Launch:
    case Item::Difficulty: difficulty_ = Difficulty((int(difficulty_) + step + 3) % 3); return {};
    case Item::Ship:
    case Item::Loadout: adjust_choice(item, step); return {};
    case Item::PauseDifficulty:
      return {{K::SetDifficulty, "", Difficulty((int(pause_.next) + step + 3) % 3)}};
    case Item::Volume: return {{K::StepVolume, "", Difficulty::Normal, step}};
    case Item::QuickPlayer:
    case Item::QuickWingmen:
    case Item::QuickWing:
    case Item::QuickEnemies:
    case Item::QuickEnemy:
    case Item::QuickCapital:
    case Item::QuickAsteroids:
    case Item::QuickDifficulty: return quick_adjust(item, step);
    case Item::NetMission:
    case Item::NetDifficulty:
    case Item::NetPort: return net_adjust(item, step);
    default: return settings_adjust(item, step);
  }
}

std::vector<MenuRequest> Menu::back() {
  message_.clear();
  switch (screen_) {
    case MenuScreen::Pause: return {{MenuRequest::Kind::Resume}};
    case MenuScreen::Briefing: {
      go(MenuScreen::Missions);
      const std::vector<const MissionInfo*> list = listed();
      for (size_t i = 0; i < list.size(); ++i)
        if (list[i]->path == chosen_) selection_ = int(i);
      break;
    }
    case MenuScreen::Main: break;
    case MenuScreen::Multiplayer:
    case MenuScreen::NetHost:
    case MenuScreen::NetJoin:
    case MenuScreen::Lobby: {
      std::vector<MenuRequest> out;
      net_back(out);
      return out;
    }
    case MenuScreen::QuickBattle: {
      go(MenuScreen::Main);
      const std::vector<Item> rows = items();
      selection_ = int(std::find(rows.begin(), rows.end(), Item::QuickBattle) - rows.begin());
      break;
    }
    default:
      if (!settings_back()) go(MenuScreen::Main);
      break;
  }
  return {};
}

std::vector<MenuRequest> Menu::bind(int code) {
  capturing_ = false;
  if (selection_ < 0 || selection_ >= int(remap_actions().size())) return {};
  const RemapOutcome r = remap_key(bindings_, remap_actions()[size_t(selection_)].id, code);
  message_ = r.message;
  if (!r.changed) return {};
  files_.settings.keys = key_overrides(bindings_, default_bindings_);
  return {{MenuRequest::Kind::SaveSettings}, {MenuRequest::Kind::ApplyBindings}};
}

std::vector<MenuRequest> Menu::show_results(const std::string& level, Difficulty d, const MissionResult& r) {
  go(MenuScreen::Results);
  chosen_ = level;
  difficulty_ = d;
  last_ = r;
  message_.clear();
  last_is_best_ = false;
  new_ships_.clear();
  if (is_quick_level(level)) return {};  // a generated battle keeps no best
  const std::vector<std::string> locked_before = locked_ships(catalog_, files_.progress);
  last_is_best_ = record_result(files_.progress, progress_key(level, difficulty_name(d)), r);
  for (const std::string& ship : locked_before)
    if (!ship_locked_by(catalog_, files_.progress, ship)) new_ships_.push_back(ship);
  if (!last_is_best_) return {};
  return {{MenuRequest::Kind::SaveProgress}};
}

PauseState pause_state_of(const World& w) {
  PauseState s;
  s.playing = Difficulty(w.difficulty);
  if (w.outcome == Outcome::Undecided) return s;
  s.outcome = outcome_text(w);
  s.outcome_tone = w.outcome == Outcome::Victory ? 1 : w.outcome == Outcome::Defeat ? -1 : 0;
  return s;
}

void Menu::pause(const PauseState& s) {
  if (screen_ != MenuScreen::Closed && screen_ != MenuScreen::Pause) return;
  if (screen_ == MenuScreen::Closed) {
    go(MenuScreen::Pause);
    message_.clear();
  }
  pause_ = s;
  selection_ = std::min(selection_, int(items().size()) - 1);
}

void Menu::close_pause() {
  if (screen_ == MenuScreen::Pause) go(MenuScreen::Closed);
}

std::string Menu::pause_label(Item item) const {
  const bool decided = !pause_.outcome.empty();
  const std::string ends = pause_.recording ? " (ends the recording)" : "";
  switch (item) {
    case Item::Resume: return "Resume";
    case Item::Restart: return (decided ? "Retry" : "Restart") + ends;
    case Item::PauseDifficulty:
      return std::string("Difficulty: < ") + difficulty_name(pause_.next) + " >" +
             (pause_.next != pause_.playing ? (decided ? " (applies on retry)" : " (applies on restart)") : "");
    case Item::PauseSound: return pause_.muted ? "Sound: muted (M)" : "Sound: on (M)";
    case Item::Volume: return "Volume: < " + std::to_string(int(std::lround(pause_.volume * 100))) + "% >";
    case Item::MainMenu: return "Main menu" + ends;
    default: return "";
  }
}

// Enter on a value steps it up, wrapping: the volume from full back to silent.
std::vector<MenuRequest> Menu::pause_accept(Item item) {
  using K = MenuRequest::Kind;
  switch (item) {
    case Item::Resume: return {{K::Resume}};
    case Item::Restart: return {{K::Restart}};
    case Item::PauseDifficulty: return adjust(item, 1);
    case Item::PauseSound: return {{K::ToggleMute}};
    case Item::Volume: return adjust(item, pause_.volume >= 1.0 ? -10 : 1);
    case Item::MainMenu: return {{K::MainMenu}};
    default: return {};
  }
}

}  // namespace arc
