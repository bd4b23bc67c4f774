#include "game/app/radio.h"

#include <algorithm>
#include <cmath>

#include "audio/adpcm.h"
#include "core/error.h"
#include "core/json.h"
#include "game/sim/world.h"

namespace arc {
namespace {

constexpr double kRadioDuck = 15;       // dB the fight drops under a line
constexpr double kRadioGain = 2.5;      // speech is sparse: lifted over the fight, the limiter takes its peaks
constexpr double kMissileCallGap = 10;  // seconds between two "missile on your six"
constexpr double kKillCallGap = 4;

// The line a wing or reinforcement message speaks, by what the simulation wrote.
std::string line_of(const SimMessage& m) {
  auto ends = [&](const std::string& tail) {
    return m.text.size() >= tail.size() && m.text.compare(m.text.size() - tail.size(), tail.size(), tail) == 0;
  };
  if (m.kind == MessageKind::Friendly) return "friendly_arrive";
  if (m.kind == MessageKind::Hostile) return "hostile_arrive";
  if (m.text.find(": attacking ") != std::string::npos) return "wing_attack";
  if (ends("is down, engaging at will")) return "wing_target_down";
  if (ends("engaging at will")) return "wing_engage";
  if (ends("covering you")) return "wing_cover";
  if (ends("forming up")) return "wing_form_up";
  if (ends("no hostile target to attack")) return "wing_no_target";
  return "";
}

}  // namespace

const RadioLine* RadioLibrary::find(const std::string& id) const {
  for (const RadioLine& l : lines)
    if (l.id == id) return &l;
  return nullptr;
}

std::string radio_sound_name(const std::string& id) { return "radio/" + id; }

RadioLibrary load_radio_library(const std::string& path) {
  auto doc = JsonDoc::load_file(path);
  JsonObject root = JsonValue(doc, "", &doc->root()).object();
  JsonObject speakers = root.require_object("speakers");
  std::vector<std::string> names;
  std::vector<double> gains;  // a speaker's level in the mix; chatter sits under mission lines
  for (auto it = speakers.raw().begin(); it != speakers.raw().end(); ++it) {
    names.push_back(it.key());
    JsonObject sp = speakers.get(it.key())->object();
    gains.push_back(sp.number("gain", 1.0, 0.1, 2.0));
    sp.allow({"voice", "pitch", "speed", "doc"});  // voice parameters are the generator's
    sp.finish();
  }
  speakers.finish();
  RadioLibrary lib;
  JsonObject lines = root.require_object("lines");
  const std::string dir = path.substr(0, path.find_last_of('/') + 1);
  for (auto it = lines.raw().begin(); it != lines.raw().end(); ++it) {
    JsonObject o = lines.get(it.key())->object();
    RadioLine l;
    l.id = it.key();
    l.speaker = o.require_string("speaker");
    if (std::find(names.begin(), names.end(), l.speaker) == names.end())
      o.fail_key("speaker", "'" + o.key_path("speaker") + "' is '" + l.speaker + "'; allowed: " + join_allowed(names));
    l.text = o.require_string("text");
    o.allow({"doc"});
    o.finish();
    DecodedAudio a = load_ima_adpcm_wav(dir + l.id + ".wav");
    l.seconds = double(a.samples.size()) / a.sample_rate;
    SoundDef s;
    s.name = radio_sound_name(l.id);
    s.group = MixGroup::Voice;
    s.positional = false;
    s.priority = 99;
    s.duck = kRadioDuck;
    s.gain = kRadioGain * gains[size_t(std::find(names.begin(), names.end(), l.speaker) - names.begin())];
    s.duck_hold = l.seconds;
    s.duration = l.seconds;
    s.pcm = std::move(a.samples);
    s.pcm_rate = a.sample_rate;
    lib.sounds.push_back(std::move(s));
    lib.lines.push_back(std::move(l));
  }
  lines.finish();
  root.allow({"doc"});
  root.finish();
  return lib;
}

void RadioQueue::say(const RadioLine& line, bool urgent) {
  for (const RadioLine& w : waiting_)
    if (w.id == line.id) return;
  if (urgent) waiting_.push_front(line);
  else waiting_.push_back(line);
  while (waiting_.size() > kMaxWaiting) waiting_.pop_back();
}

std::optional<RadioLine> RadioQueue::advance(double seconds) {
  clock_ += seconds;
  if (waiting_.empty() || clock_ < busy_until_) return std::nullopt;
  speaking_ = waiting_.front();
  waiting_.pop_front();
  busy_until_ = clock_ + speaking_->seconds + kGap;
  shown_until_ = clock_ + speaking_->seconds + kLinger;
  return speaking_;
}

std::optional<Subtitle> RadioQueue::subtitle() const {
  if (!speaking_ || clock_ >= shown_until_) return std::nullopt;
  return Subtitle{speaking_->speaker, speaking_->text};
}

std::vector<std::string> RadioDirector::lines(const World& w, const std::vector<SoundEvent>& events) {
  std::vector<std::string> out;
  if (!w.player) return out;
  if (w.tick < last_tick_) *this = RadioDirector{};  // a restart
  const int64_t since = last_tick_;
  last_tick_ = w.tick;
  const int outcome = int(w.outcome);
  if (outcome != outcome_) {
    outcome_ = outcome;
    if (w.outcome == Outcome::Victory) out.push_back("mission_won");
    if (w.outcome == Outcome::Defeat) out.push_back("mission_lost");
  }
  if (w.outcome != Outcome::Undecided) return out;
  for (const SoundEvent& e : events) {
    if (e.kind == SoundKind::MissileWarning && w.tick >= next_missile_call_) {
      out.push_back("missile_six");
      next_missile_call_ = w.tick + std::llround(kMissileCallGap / w.dt);
    }
    if (e.kind == SoundKind::Kill && w.tick >= next_kill_call_) {
      out.push_back("kill_" + std::to_string(kill_calls_++ % 3 + 1));
      next_kill_call_ = w.tick + std::llround(kKillCallGap / w.dt);
    }
  }
  for (const SimMessage& m : w.messages)
    if (m.tick > since && since >= 0) {
      const std::string id = line_of(m);
      if (!id.empty()) out.push_back(id);
    }
  return out;
}

}  // namespace arc
