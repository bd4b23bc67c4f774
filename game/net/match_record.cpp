// game/net/match_record.cpp — writing and replaying match records (match_record.h).
#include "game/net/match_record.h"

#include <cstdio>
#include <sstream>

#include "core/error.h"
#include "core/input_file.h"
#include "core/json.h"

namespace arc {
namespace {

std::string hex(uint64_t v) {
  char b[17];
  std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(v));
  return b;
}

void write_input(std::ostream& o, int64_t t, int slot, const SlotInput& s) {
  const InputFrame& f = s.input;
  o << "in " << t << ' ' << slot;
  for (int8_t a : {f.pitch, f.yaw, f.roll, f.throttle, f.strafe_x, f.strafe_y}) o << ' ' << int(a);
  o << ' ' << f.buttons;
  for (Command c : s.commands) o << ' ' << int(c);
  o << '\n';
}

[[noreturn]] void fail(const std::string& path, int line, const std::string& what) {
  throw InputError(path + ":" + std::to_string(line) + ": " + what);
}

int64_t number(const std::string& path, int line, std::istream& in, int64_t lo, int64_t hi, const char* what) {
  std::string tok;
  if (!(in >> tok)) fail(path, line, std::string("missing ") + what);
  size_t used = 0;
  long long v = 0;
  try {
    v = std::stoll(tok, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != tok.size() || v < lo || v > hi)
    fail(path, line, std::string(what) + " must be an integer in " + std::to_string(lo) + ".." + std::to_string(hi) + ", got '" + tok + "'");
  return v;
}

}  // namespace

std::string match_record_text(const RollbackSession& s, const std::string& level, uint64_t seed,
                              const std::vector<std::string>& names, int hash_every) {
  std::ostringstream o;
  const int slots = s.config().slots;
  const int64_t end = s.final_tick();
  o << "arcfire-match " << kMatchRecordVersion << "\nlevel " << level << "\nseed " << seed << "\nslots " << slots << '\n';
  for (int k = 0; k < slots; ++k) {
    if (!s.config().piloted[size_t(k)]) continue;
    o << "pilot " << k << ' ' << (size_t(k) < names.size() && !names[size_t(k)].empty() ? names[size_t(k)] : "Pilot") << '\n';
    if (s.drop_tick(k) != RollbackSession::kNever) o << "drop " << k << ' ' << s.drop_tick(k) << '\n';
  }
  std::vector<SlotInput> last(static_cast<size_t>(slots));
  for (int64_t t = 1; t <= end; ++t) {
    for (int k = 0; k < slots; ++k) {
      if (!s.config().piloted[size_t(k)] || t >= s.drop_tick(k)) continue;
      const auto& in = s.inputs(k);
      if (t > int64_t(in.size())) continue;
      const SlotInput& cur = in[size_t(t - 1)];
      if (t == 1 || !(cur == last[size_t(k)]) || !cur.commands.empty()) write_input(o, t, k, cur);
      last[size_t(k)] = cur;
      last[size_t(k)].commands.clear();
    }
    if (t % hash_every == 0 || t == end) o << "hash " << t << ' ' << hex(s.hash_at(t)) << '\n';
  }
  o << "end " << end << '\n';
  return o.str();
}

// Long: one pass over the record's lines, each kind checked where it is read.
MatchReplayResult replay_match(const std::string& path, const GameOptions& base) {
  std::istringstream file(read_text_file(path, 256u << 20, "a match record"));
  std::string line_text, level;
  int line = 0, slots = -1;
  uint64_t seed = 0;
  bool have_seed = false;
  std::vector<bool> piloted;
  std::vector<int64_t> drops;
  struct Entry {
    int64_t tick;
    int kind;  // 0 input, 1 hash, 2 end
    int slot;
    SlotInput in;
    uint64_t hash;
    int line;
  };
  std::vector<Entry> body;
  while (std::getline(file, line_text)) {
    ++line;
    std::istringstream in(line_text);
    std::string key;
    if (!(in >> key)) continue;
    if (line == 1) {
      if (key != "arcfire-match") fail(path, line, "a match record starts with 'arcfire-match 1'");
      number(path, line, in, kMatchRecordVersion, kMatchRecordVersion, "format version");
    } else if (key == "level") {
      in >> level;
    } else if (key == "seed") {
      seed = uint64_t(number(path, line, in, 0, 0xFFFFFFFFll, "seed"));
      have_seed = true;
    } else if (key == "slots") {
      slots = int(number(path, line, in, 1, 8, "slot count"));
      piloted.assign(size_t(slots), false);
      drops.assign(size_t(slots), RollbackSession::kNever);
    } else if (slots < 0) {
      fail(path, line, "'slots N' comes before '" + key + "'");
    } else if (key == "pilot") {
      piloted[size_t(number(path, line, in, 0, slots - 1, "slot"))] = true;
    } else if (key == "drop") {
      const int k = int(number(path, line, in, 0, slots - 1, "slot"));
      drops[size_t(k)] = number(path, line, in, 1, 100000000, "tick");
    } else if (key == "in" || key == "hash" || key == "end") {
      Entry e{number(path, line, in, 1, 100000000, "tick"), key == "in" ? 0 : key == "hash" ? 1 : 2, 0, {}, 0, line};
      if (!body.empty() && e.tick < body.back().tick) fail(path, line, "lines must be in tick order");
      if (e.kind == 0) {
        e.slot = int(number(path, line, in, 0, slots - 1, "slot"));
        InputFrame& f = e.in.input;
        for (int8_t* a : {&f.pitch, &f.yaw, &f.roll, &f.throttle, &f.strafe_x, &f.strafe_y})
          *a = int8_t(number(path, line, in, -127, 127, "axis"));
        f.buttons = uint16_t(number(path, line, in, 0, 15, "buttons"));
        std::string more;
        while (in >> more) {
          std::istringstream one(more);
          e.in.commands.push_back(Command(number(path, line, one, 1, int(Command::OrderEngage), "command")));
        }
      } else if (e.kind == 1) {
        std::string h;
        in >> h;
        if (h.size() != 16 || h.find_first_not_of("0123456789abcdef") != std::string::npos)
          fail(path, line, "a hash is 16 lowercase hex digits, got '" + h + "'");
        e.hash = std::stoull(h, nullptr, 16);
      }
      body.push_back(std::move(e));
    } else {
      fail(path, line, "unknown line '" + key + "'; allowed: level, seed, slots, pilot, drop, in, hash, end");
    }
  }
  if (level.empty() || slots < 0 || body.empty() || body.back().kind != 2)
    fail(path, line, "a match record needs 'level', 'slots' and an 'end' line");
  GameOptions options = base;
  if (have_seed) options.seed_override = true, options.seed = seed;
  std::string level_file = input_path_exists(level) ? level : base.root_dir + "/" + level;
  Game game = Game::load_level(level_file, options);
  if (game.slot_count() != size_t(slots)) fail(path, 4, "the level has " + std::to_string(game.slot_count()) + " slots, the record " + std::to_string(slots));
  std::vector<SlotInput> held(static_cast<size_t>(slots));
  MatchReplayResult r;
  size_t i = 0;
  std::vector<bool> flying = piloted;
  game.set_pilots(flying);
  for (int64_t t = 1; i < body.size(); ++t) {
    for (; i < body.size() && body[i].tick == t && body[i].kind == 0; ++i) held[size_t(body[i].slot)] = body[i].in;
    std::vector<bool> want(static_cast<size_t>(slots));
    for (int k = 0; k < slots; ++k) want[size_t(k)] = piloted[size_t(k)] && t < drops[size_t(k)];
    if (want != flying) game.set_pilots(flying = want);
    game.step_slots(held);
    for (SlotInput& h : held) h.commands.clear();
    r.ticks = t;
    r.last_hash = game.hash();
    for (; i < body.size() && body[i].tick == t; ++i) {
      if (body[i].kind == 1) {
        ++r.hashes_checked;
        if (body[i].hash != r.last_hash && r.first_bad_tick < 0) r.first_bad_tick = t;
      } else if (body[i].kind == 2) {
        i = body.size();
      }
    }
  }
  return r;
}

}  // namespace arc
