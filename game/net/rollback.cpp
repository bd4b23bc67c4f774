// game/net/rollback.cpp — RollbackSession: inputs by tick, prediction, save, restore, re-simulate.
#include "game/net/rollback.h"

#include <glm/geometric.hpp>

#include "core/error.h"
#include "game/sim/world.h"

namespace arc {

RollbackSession::RollbackSession(Game game, RollbackConfig config) : game_(std::move(game)), cfg_(std::move(config)) {
  if (cfg_.slots < 1 || cfg_.local_slot < 0 || cfg_.local_slot >= cfg_.slots)
    throw InputError("net: local slot " + std::to_string(cfg_.local_slot) + " outside the match's " + std::to_string(cfg_.slots) + " slots");
  cfg_.input_delay = std::clamp(cfg_.input_delay, 0, 4);
  cfg_.max_prediction = std::clamp(cfg_.max_prediction, 1, 60);
  if (cfg_.piloted.empty()) cfg_.piloted.assign(size_t(cfg_.slots), true);
  cfg_.piloted.resize(size_t(cfg_.slots), false);
  known_.resize(size_t(cfg_.slots));
  used_.resize(size_t(cfg_.slots));
  drop_from_.assign(size_t(cfg_.slots), kNever);
  for (int s = 0; s < cfg_.slots; ++s)
    if (!cfg_.piloted[size_t(s)]) drop_from_[size_t(s)] = 1;  // flown by the AI from the start
  game_.set_pilots(cfg_.piloted);
  hashes_.push_back(game_.hash());
  // Every state a rollback can reach: the last confirmed one and the predicted ones after it.
  const size_t n = size_t(cfg_.max_prediction + 2);
  ring_tick_.assign(n, -1);
  ring_.assign(n, game_);
  // The local slot's first ticks, inside the delay, are empty input.
  for (int t = 1; t <= cfg_.input_delay; ++t) known_[size_t(cfg_.local_slot)].push_back(SlotInput{});
}

int64_t RollbackSession::add_local_input(const SlotInput& in) {
  auto& k = known_[size_t(cfg_.local_slot)];
  k.push_back(in);
  return int64_t(k.size());
}

bool RollbackSession::add_remote_input(int slot, int64_t t, const SlotInput& in) {
  if (slot < 0 || slot >= cfg_.slots || slot == cfg_.local_slot || t < 1) return false;
  if (t >= drop_from_[size_t(slot)]) return false;
  auto& k = known_[size_t(slot)];
  if (t != int64_t(k.size()) + 1) return false;  // duplicate, or beyond a gap the sender fills later
  k.push_back(in);
  if (t <= tick_ && used_[size_t(slot)][size_t(t - 1)] != in) pending_ = std::min(pending_, t);
  return true;
}

void RollbackSession::drop_slot(int slot, int64_t from_tick) {
  if (slot < 0 || slot >= cfg_.slots || slot == cfg_.local_slot) return;
  from_tick = std::max<int64_t>(from_tick, int64_t(known_[size_t(slot)].size()) + 1);
  if (from_tick >= drop_from_[size_t(slot)]) return;
  drop_from_[size_t(slot)] = from_tick;
  // Ticks already stepped with the slot's pilot predicted are stepped again by the AI.
  if (from_tick <= tick_) pending_ = std::min(pending_, from_tick);
}

int64_t RollbackSession::received(int slot) const {
  if (drop_from_[size_t(slot)] != kNever) return kNever;
  return int64_t(known_[size_t(slot)].size());
}

int64_t RollbackSession::confirmed() const {
  int64_t c = kNever;
  for (int s = 0; s < cfg_.slots; ++s) {
    int64_t r = int64_t(known_[size_t(s)].size());
    if (drop_from_[size_t(s)] != kNever && r >= drop_from_[size_t(s)] - 1) r = kNever;  // all its pilot's ticks are in
    c = std::min(c, r);
  }
  return c;
}

bool RollbackSession::can_advance() const {
  const int64_t next = tick_ + 1;
  if (int64_t(known_[size_t(cfg_.local_slot)].size()) < next) return false;
  return next - cfg_.max_prediction <= confirmed();  // confirmed() may be kNever: no sum past it
}

const SlotInput& RollbackSession::input_for(int slot, int64_t t, bool* predicted) const {
  static const SlotInput none;
  if (t >= drop_from_[size_t(slot)]) return none;
  const auto& k = known_[size_t(slot)];
  if (t <= int64_t(k.size())) return k[size_t(t - 1)];
  *predicted = true;
  return k.empty() ? none : k.back();
}

void RollbackSession::save_state() {
  const size_t i = size_t(tick_) % ring_.size();
  ring_[i].copy_state_from(game_);
  ring_tick_[i] = tick_;
  ++stats_.saves;
}

void RollbackSession::step_one() {
  const int64_t t = tick_ + 1;
  std::vector<SlotInput> in(size_t(cfg_.slots));
  std::vector<bool> piloted(size_t(cfg_.slots));
  bool predicted = false;
  for (int s = 0; s < cfg_.slots; ++s) {
    piloted[size_t(s)] = t < drop_from_[size_t(s)];
    bool p = false;
    in[size_t(s)] = input_for(s, t, &p);
    if (p) in[size_t(s)].commands.clear();  // a prediction repeats the held input, not its commands
    predicted = predicted || p;
  }
  // A tick stepped on a prediction may be undone: keep the state before it.
  if (predicted) save_state();
  bool same = game_.world().pilots.size() == piloted.size();
  for (size_t s = 0; same && s < piloted.size(); ++s) same = game_.world().pilots[s].piloted == piloted[s];
  if (!same) game_.set_pilots(piloted);
  game_.step_slots(in);
  if (after_step) after_step(game_, t);
  for (int s = 0; s < cfg_.slots; ++s) {
    auto& u = used_[size_t(s)];
    if (int64_t(u.size()) < t) u.resize(size_t(t));
    u[size_t(t - 1)] = in[size_t(s)];
  }
  tick_ = t;
  if (int64_t(hashes_.size()) <= t) hashes_.resize(size_t(t + 1));
  hashes_[size_t(t)] = game_.hash();
  if (predicted) ++stats_.predicted;
}

void RollbackSession::advance() {
  settle();
  step_one();
  ++stats_.ticks;
}

void RollbackSession::settle() {
  if (pending_ != kNever) {
    const int64_t back = pending_ - 1;  // the state before the first wrong tick
    const size_t i = size_t(back) % ring_.size();
    if (ring_tick_[i] != back) throw InputError("net: no kept state at tick " + std::to_string(back) + " to roll back to");
    const int64_t present = tick_;
    std::vector<glm::dvec3> shown;
    for (const Ship& ship : game_.world().ships) shown.push_back(ship.position);
    game_.copy_state_from(ring_[i]);
    tick_ = back;
    pending_ = kNever;
    ++stats_.rollbacks;
    stats_.max_depth = std::max(stats_.max_depth, int(present - back));
    while (tick_ < present) {
      step_one();
      ++stats_.resimulated;
    }
    const auto& ships = game_.world().ships;
    for (size_t k = 0; k < ships.size() && k < shown.size(); ++k)
      if (ships[k].alive) stats_.max_correction_m = std::max(stats_.max_correction_m, glm::length(ships[k].position - shown[k]));
  }
}

}  // namespace arc
