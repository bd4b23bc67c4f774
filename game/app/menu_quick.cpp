// The menu's quick battle page: a row per choice of the setup, changed by Left/Right, and Launch.
#include <algorithm>
#include <cstdio>

#include "core/error.h"
#include "game/app/menu.h"
#include "game/app/menu_items.h"
#include "game/app/quick_battle_files.h"

namespace arc {
namespace {

// The next name of `list` after `now`, `step` places on, wrapping.
std::string step_name(const std::vector<std::string>& list, const std::string& now, int step) {
  if (list.empty()) return now;
  const int n = int(list.size());
  const int at = int(std::find(list.begin(), list.end(), now) - list.begin());
  return list[size_t(((at < n ? at : 0) + step % n + n) % n)];
}

std::string row(const std::string& name, const std::string& value) { return name + ": < " + value + " >"; }

}  // namespace

void Menu::set_quick_battle(QuickClasses classes, QuickSetup setup) {
  quick_classes_ = std::move(classes);
  quick_ = std::move(setup);
  has_quick_ = !quick_classes_.fighters.empty();
}

std::vector<Menu::Item> Menu::quick_items() const {
  std::vector<Item> v{Item::QuickPlayer, Item::QuickWingmen};
  if (quick_.wingmen > 0) v.push_back(Item::QuickWing);
  v.insert(v.end(), {Item::QuickEnemies, Item::QuickEnemy});
  if (!quick_classes_.capitals.empty()) v.push_back(Item::QuickCapital);
  v.insert(v.end(), {Item::QuickAsteroids, Item::QuickDifficulty, Item::QuickLaunch, Item::Back});
  return v;
}

std::string Menu::quick_label(Item item) const {
  switch (item) {
    case Item::QuickBattle: return "Quick battle";
    case Item::QuickPlayer: return row("Your ship", quick_player());
    case Item::QuickWingmen: return row("Wingmen", std::to_string(quick_.wingmen));
    case Item::QuickWing: return row("Wing class", quick_.wing);
    case Item::QuickEnemies: return row("Enemies", std::to_string(quick_.enemies));
    case Item::QuickEnemy: return row("Enemy class", quick_.enemy);
    case Item::QuickCapital:
      return row("Capital ship", quick_.capital == "none" ? "none"
                                                          : quick_.capital + (quick_.capital_friendly ? " (yours)" : " (enemy)"));
    case Item::QuickAsteroids: return row("Asteroids", asteroids_name(quick_.asteroids));
    case Item::QuickDifficulty: return row("Difficulty", difficulty_name(quick_.difficulty));
    case Item::QuickLaunch: return "Launch";
    default: return "";
  }
}

void Menu::fill_quick_page(MenuPage& p) const {
  p.title = "QUICK BATTLE";
  p.subtitle = "Left/Right: change   Enter on Launch: fight";
  const int blue = 1 + quick_.wingmen + (quick_.capital != "none" && quick_.capital_friendly ? 1 : 0);
  const int red = quick_.enemies + (quick_.capital != "none" && !quick_.capital_friendly ? 1 : 0);
  const std::string allies = blue == 1 ? "you alone" : "you and " + std::to_string(blue - 1) + (blue == 2 ? " ally" : " allies");
  p.lines.push_back("Blue: " + allies + "   Red: " + std::to_string(red) + (red == 1 ? " ship" : " ships") +
                    "   Destroy every enemy");
  if (const std::string locked = locked_line(quick_classes_.fighters); !locked.empty()) p.lines.push_back(locked);
}

// Enter on a value row steps it on, as Right does.
std::vector<MenuRequest> Menu::quick_accept(Item item) {
  if (item != Item::QuickLaunch) return quick_adjust(item, 1);
  try {
    quick_.player = quick_player();
    const std::string text = quick_level_json(quick_, quick_classes_);
    MenuRequest launch(MenuRequest::Kind::Launch, quick_level_path(files_.dir, text), quick_.difficulty);
    launch.generated = text;
    difficulty_ = quick_.difficulty;
    go(MenuScreen::Closed);
    return {{MenuRequest::Kind::SaveQuickBattle}, launch};
  } catch (const InputError& e) {
    message_ = e.what();
    return {};
  }
}

std::vector<MenuRequest> Menu::quick_adjust(Item item, int step) {
  const std::vector<std::string>& fighters = quick_classes_.fighters;
  auto count = [&](int now, int lo, int hi) { return std::clamp(now + step, lo, hi); };
  switch (item) {
    case Item::QuickPlayer: {
      std::vector<std::string> open;  // only the ships the campaign has unlocked
      for (const std::string& f : fighters)
        if (ship_open(f)) open.push_back(f);
      quick_.player = step_name(open, quick_player(), step);
      break;
    }
    case Item::QuickWingmen: quick_.wingmen = count(quick_.wingmen, 0, kQuickMaxWingmen); break;
    case Item::QuickWing: quick_.wing = step_name(fighters, quick_.wing, step); break;
    case Item::QuickEnemies: quick_.enemies = count(quick_.enemies, 1, kQuickMaxEnemies); break;
    case Item::QuickEnemy: quick_.enemy = step_name(fighters, quick_.enemy, step); break;
    case Item::QuickCapital: {
      // none, then each capital class against the player, then flying with the player.
      std::vector<std::string> choices{"none"};
      for (const std::string& c : quick_classes_.capitals) choices.push_back(c + "|enemy");
      for (const std::string& c : quick_classes_.capitals) choices.push_back(c + "|player");
      const std::string now =
          quick_.capital == "none" ? "none" : quick_.capital + (quick_.capital_friendly ? "|player" : "|enemy");
      const std::string next = step_name(choices, now, step);
      const size_t bar = next.find('|');
      quick_.capital = next.substr(0, bar);
      quick_.capital_friendly = bar != std::string::npos && next.substr(bar + 1) == "player";
      break;
    }
    case Item::QuickAsteroids: quick_.asteroids = QuickAsteroids((int(quick_.asteroids) + step % 3 + 3) % 3); break;
    case Item::QuickDifficulty: quick_.difficulty = Difficulty((int(quick_.difficulty) + step % 3 + 3) % 3); break;
    default: return {};
  }
  // Rows come and go with the wingmen count: the selection stays on the row it was on.
  const std::vector<Item> rows = quick_items();
  selection_ = int(std::find(rows.begin(), rows.end(), item) - rows.begin());
  return {{MenuRequest::Kind::SaveQuickBattle}};
}

}  // namespace arc

namespace arc {

void offer_quick_battle(Menu& menu, const std::string& root_dir, const std::string& user_dir) {
  QuickClasses classes = quick_classes(root_dir);
  std::string message;
  QuickSetup setup = load_quick_setup(user_dir, classes, message);
  if (!message.empty()) {
    std::fprintf(stderr, "arcfire: %s\n", message.c_str());
    menu.set_message(message);
  }
  menu.set_quick_battle(std::move(classes), std::move(setup));
}

}  // namespace arc
