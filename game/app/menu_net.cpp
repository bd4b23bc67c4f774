// The menu's Multiplayer pages: Host (mission, difficulty, port), Join (an address typed in or
// a recent host), the pilot's name, and the lobby (a row per slot, Launch for the host).
#include <algorithm>
#include <cctype>

#include "game/app/menu.h"
#include "game/app/menu_items.h"
#include "platform/platform.h"

namespace arc {
namespace {

std::string row(const std::string& name, const std::string& value) { return name + ": < " + value + " >"; }

bool printable_name(const std::string& n) {
  if (n.empty() || n.size() > 24) return false;
  return std::all_of(n.begin(), n.end(), [](char c) { return c >= 0x20 && c <= 0x7e; });
}

// The character a key types into a text row ("" for none): letters, digits, '.', '-', '_',
// space, and ':' from the semicolon key (no shift state reaches the menu).
std::string typed(int code) {
  const std::string k = key_name(code);
  if (k.size() == 1 && std::isalnum(static_cast<unsigned char>(k[0]))) return std::string(1, char(std::tolower(k[0])));
  if (k == "PERIOD" || k == "KP_DECIMAL") return ".";
  if (k == "MINUS") return "-";
  if (k == "SPACE") return " ";
  if (k == "SEMICOLON") return ":";
  if (k.rfind("KP_", 0) == 0 && k.size() == 4 && std::isdigit(static_cast<unsigned char>(k[3]))) return k.substr(3);
  return "";
}

}  // namespace

std::vector<Menu::Item> Menu::net_items() const {
  switch (screen_) {
    case MenuScreen::Multiplayer: return {Item::NetHostPage, Item::NetJoinPage, Item::NetName, Item::Back};
    case MenuScreen::NetHost: return {Item::NetMission, Item::NetDifficulty, Item::NetPort, Item::NetOpen, Item::Back};
    case MenuScreen::NetJoin: {
      std::vector<Item> v{Item::NetAddress, Item::NetConnect};
      v.insert(v.end(), files_.settings.recent_hosts.size(), Item::NetRecent);
      v.push_back(Item::Back);
      return v;
    }
    case MenuScreen::Lobby: {
      std::vector<Item> v(lobby_.rows.size(), Item::LobbySlot);
      if (lobby_.host) v.push_back(Item::NetLaunch);
      v.push_back(Item::NetLeave);
      return v;
    }
    default: return {};
  }
}

std::string Menu::net_label(Item item, int index) const {
  switch (item) {
    case Item::Multiplayer: return "Multiplayer";
    case Item::NetHostPage: return "Host a match";
    case Item::NetJoinPage: return "Join a match";
    case Item::NetName: return "Pilot name: " + files_.settings.net_name + (editing_ ? "_" : "");
    case Item::NetMission:
      return row("Mission", net_missions_.empty() ? "none with two slots" : net_missions_[size_t(net_mission_)].title);
    case Item::NetDifficulty: return row("Difficulty", difficulty_name(difficulty_));
    case Item::NetPort: return row("Port", std::to_string(net_port_));
    case Item::NetOpen: return "Open the lobby";
    case Item::NetAddress: return "Address: " + net_address_ + (editing_ ? "_" : "");
    case Item::NetRecent: {
      const size_t i = size_t(index - 2);
      return i < files_.settings.recent_hosts.size() ? "Recent: " + files_.settings.recent_hosts[i] : "";
    }
    case Item::NetConnect: return "Join";
    case Item::LobbySlot: return size_t(index) < lobby_.rows.size() ? lobby_.rows[size_t(index)] : "";
    case Item::NetLaunch: return "Launch";
    case Item::NetLeave: return lobby_.standalone ? "Leave (closes the game)" : "Leave";
    default: return "";
  }
}

void Menu::fill_net_page(MenuPage& p) const {
  switch (screen_) {
    case MenuScreen::Multiplayer:
      p.title = "MULTIPLAYER";
      p.subtitle = "two to eight pilots over the network";
      break;
    case MenuScreen::NetHost:
      p.title = "HOST A MATCH";
      p.subtitle = "Left/Right: change   pilots join on this port";
      break;
    case MenuScreen::NetJoin:
      p.title = "JOIN A MATCH";
      p.subtitle = "Enter on Address, type HOST or HOST:PORT (';' types ':'), Enter";
      break;
    case MenuScreen::Lobby:
      p.title = lobby_.title;
      p.subtitle = lobby_.status;
      // The rows' columns (5, 11, 25, 50 characters at the items' larger scale) under the heading's.
      if (lobby_.title == "LOBBY") p.lines.push_back(std::string("Slot Team   Ship            Pilot                        Ping"));
      p.hint = lobby_.host ? "Enter on Launch: start the match   Esc: leave"
                           : "Enter on a free slot: fly it   Esc: leave";
      break;
    default: break;
  }
  if (editing_) p.hint = "type, Backspace: erase, Enter: done";
}

void Menu::open_lobby(NetLobbyView v) {
  lobby_ = std::move(v);
  go(MenuScreen::Lobby);
  selection_ = int(lobby_.rows.size());  // on Launch (the host) or Leave
  message_.clear();
}

void Menu::close_lobby() {
  if (screen_ == MenuScreen::Lobby) go(MenuScreen::Closed);
}

std::vector<MenuRequest> Menu::net_accept(Item item, int index) {
  using K = MenuRequest::Kind;
  switch (item) {
    case Item::Multiplayer: go(MenuScreen::Multiplayer); return {};
    case Item::NetHostPage: go(MenuScreen::NetHost); return {};
    case Item::NetJoinPage: go(MenuScreen::NetJoin); return {};
    case Item::NetName:
    case Item::NetAddress:
      editing_ = capturing_ = true;
      return {};
    case Item::NetMission:
    case Item::NetDifficulty:
    case Item::NetPort: return net_adjust(item, 1);
    case Item::NetOpen:
      if (net_missions_.empty()) {
        message_ = "No mission here has two slots";
        return {};
      }
      return {{K::NetHost, net_missions_[size_t(net_mission_)].path, difficulty_, net_port_}};
    case Item::NetRecent: net_address_ = files_.settings.recent_hosts[size_t(index - 2)]; [[fallthrough]];
    case Item::NetConnect: {
      if (net_address_.empty()) {
        message_ = "Type the host's address first (Enter on Address)";
        return {};
      }
      std::vector<std::string>& recent = files_.settings.recent_hosts;
      std::erase(recent, net_address_);
      recent.insert(recent.begin(), net_address_);
      if (recent.size() > 5) recent.resize(5);
      return {{K::SaveSettings}, {K::NetJoin, net_address_}};
    }
    case Item::LobbySlot:
      if (lobby_.title != "LOBBY") return {};  // the results' rows
      if (lobby_.host || size_t(index) >= lobby_.free.size() || !lobby_.free[size_t(index)]) {
        message_ = lobby_.host ? "The host flies slot 0" : "Pick a free slot";
        return {};
      }
      return {{K::NetPick, "", Difficulty::Normal, index}};
    case Item::NetLaunch: return {{K::NetLaunch}};
    case Item::NetLeave: {
      std::vector<MenuRequest> out;
      net_back(out);
      return out;
    }
    default: return {};
  }
}

std::vector<MenuRequest> Menu::net_adjust(Item item, int step) {
  switch (item) {
    case Item::NetMission:
      if (!net_missions_.empty()) net_mission_ = (net_mission_ + step + int(net_missions_.size())) % int(net_missions_.size());
      break;
    case Item::NetDifficulty: difficulty_ = Difficulty((int(difficulty_) + step % 3 + 3) % 3); break;
    case Item::NetPort: net_port_ = std::clamp(net_port_ + step, 1024, 65535); break;
    default: break;
  }
  return {};
}

// A key while a text row is edited: a character, Backspace, or Enter (done; the name is kept
// when it is a valid one).
std::vector<MenuRequest> Menu::net_type(int code) {
  const std::vector<Item> list = items();
  const bool name = selection_ < int(list.size()) && list[size_t(selection_)] == Item::NetName;
  std::string& text = name ? files_.settings.net_name : net_address_;
  const std::string k = key_name(code);
  if (k == "ENTER" || k == "KP_ENTER") {
    editing_ = capturing_ = false;
    if (!name) return {};
    if (!printable_name(text)) {
      text = "Pilot";
      message_ = "A pilot name has 1 to 24 printable characters";
    }
    return {{MenuRequest::Kind::SaveSettings}};
  }
  if (k == "BACKSPACE") {
    if (!text.empty()) text.pop_back();
    return {};
  }
  const std::string c = typed(code);
  if (!c.empty() && text.size() < (name ? 24u : 64u)) text += name || c != " " ? c : "";
  return {};
}

// Esc: back a page; in the lobby, leave it (the window ends the connection).
bool Menu::net_back(std::vector<MenuRequest>& out) {
  switch (screen_) {
    case MenuScreen::Multiplayer: {
      go(MenuScreen::Main);
      const std::vector<Item> rows = items();
      selection_ = int(std::find(rows.begin(), rows.end(), Item::Multiplayer) - rows.begin());
      return true;
    }
    case MenuScreen::NetHost:
    case MenuScreen::NetJoin: go(MenuScreen::Multiplayer); return true;
    case MenuScreen::Lobby:
      out.push_back({MenuRequest::Kind::NetLeave});
      if (lobby_.standalone) out.push_back({MenuRequest::Kind::Quit});
      go(has_main_ ? MenuScreen::Multiplayer : MenuScreen::Closed);
      return true;
    default: return false;
  }
}

}  // namespace arc
