// game/sim/wing.cpp — wing orders and the HUD messages: the order commands set the live
// wingmen's order and post their reply; an attack whose target died falls back to engaging at will.
#include "game/sim/wing.h"

#include <utility>

namespace arc {
namespace {

// "Alpha 2" or "Alpha 2, Alpha 3": who answers an order (the live wingmen, at most three named).
std::string speakers(const World& w) {
  std::string names;
  int n = 0;
  for (const Wingman& m : w.wing) {
    const Ship& s = w.ship(m.ship);
    if (!s.alive) continue;
    if (++n <= 3) names += (names.empty() ? "" : ", ") + s.name;
  }
  if (n > 3) names += " and wing";
  return names;
}

const char* reply(WingOrder o) {
  switch (o) {
    case WingOrder::Cover: return "covering you";
    case WingOrder::FormUp: return "forming up";
    default: return "engaging at will";
  }
}

}  // namespace

void post_message(World& w, MessageKind kind, std::string text) {
  w.messages.push_back({w.tick, kind, std::move(text)});
  if (w.messages.size() > kMaxMessages) w.messages.erase(w.messages.begin());
}

const Wingman* wingman_of(const World& w, ShipId ship) {
  for (const Wingman& m : w.wing)
    if (m.ship == ship) return &m;
  return nullptr;
}

void order_wing(World& w, Command c) {
  WingOrder order;
  switch (c) {
    case Command::OrderAttack: order = WingOrder::Attack; break;
    case Command::OrderCover: order = WingOrder::Cover; break;
    case Command::OrderFormUp: order = WingOrder::FormUp; break;
    case Command::OrderEngage: order = WingOrder::EngageAtWill; break;
    default: return;
  }
  const std::string who = speakers(w);
  if (who.empty()) return post_message(w, MessageKind::Wing, "No wingmen");
  const Ship& p = w.ship(w.player);
  ShipId target;
  if (order == WingOrder::Attack) {
    if (!p.target || !w.ship(p.target).alive || !w.hostile(p, w.ship(p.target)))
      return post_message(w, MessageKind::Wing, who + ": no hostile target to attack");
    target = p.target;
  }
  for (Wingman& m : w.wing) {
    Ship& s = w.ship(m.ship);
    if (!s.alive) continue;
    m.order = order;
    m.target = target;
    s.ai_state.next_think = w.tick;  // obeys at once, not at its next decision
    if (order != WingOrder::EngageAtWill) s.ai_state.mode = AiMode::Attack;
  }
  post_message(w, MessageKind::Wing,
               who + ": " + (order == WingOrder::Attack ? "attacking " + w.ship(target).name : reply(order)));
}

void update_wing_orders(World& w) {
  for (Wingman& m : w.wing) {
    if (m.order != WingOrder::Attack || !w.ship(m.ship).alive) continue;
    if (m.target && w.ship(m.target).alive) continue;
    const std::string target = m.target ? w.ship(m.target).name : "the target";
    m.order = WingOrder::EngageAtWill;
    m.target = {};
    post_message(w, MessageKind::Wing, w.ship(m.ship).name + ": " + target + " is down, engaging at will");
  }
}

}  // namespace arc
