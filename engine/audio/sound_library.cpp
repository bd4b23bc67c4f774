#include "audio/sound_library.h"

#include "core/error.h"
#include "core/json.h"

namespace arc {
namespace {

SoundLayerDef::Source source_of(const std::string& name) {
  if (name == "square") return SoundLayerDef::Source::Square;
  if (name == "saw") return SoundLayerDef::Source::Saw;
  if (name == "triangle") return SoundLayerDef::Source::Triangle;
  if (name == "noise") return SoundLayerDef::Source::Noise;
  return SoundLayerDef::Source::Sine;
}

SoundLayerDef parse_layer(JsonObject o) {
  SoundLayerDef l;
  l.source = source_of(o.choice("source", "sine", {"sine", "square", "saw", "triangle", "noise"}));
  l.freq_start = o.number("freq", l.freq_start, 10, 20000);
  l.freq_end = o.number("freq_end", l.freq_start, 10, 20000);
  l.gain = o.number("gain", l.gain, 0, 4);
  l.delay = o.number("delay", l.delay, 0, 10);
  l.attack = o.number("attack", l.attack, 0.0005, 10);
  l.hold = o.number("hold", l.hold, 0, 10);
  l.decay = o.number("decay", l.decay, 0.001, 20);
  l.decay_curve = o.number("decay_curve", l.decay_curve, 0.25, 8);
  l.lowpass = o.number("lowpass", 0, 0, 20000);
  l.highpass = o.number("highpass", 0, 0, 20000);
  l.burst_period = o.number("burst_period", 0, 0, 5);
  l.burst_length = o.number("burst_length", l.burst_period * 0.5, 0, 5);
  l.jitter = o.number("jitter", 0, 0, 1);
  if (l.burst_period > 0 && l.burst_length > l.burst_period)
    o.fail_key("burst_length", "'" + o.key_path("burst_length") + "' must not be longer than 'burst_period' (" +
                                   std::to_string(l.burst_period) + " s)");
  o.allow({"doc"});
  o.finish();
  return l;
}

MixGroup group_of(const std::string& name) {
  for (int g = 0; g < kMixGroups; ++g)
    if (name == mix_group_name(MixGroup(g))) return MixGroup(g);
  return MixGroup::Weapons;
}

MixDef parse_mix(JsonObject o) {
  MixDef m;
  m.master_db = o.number("master_db", m.master_db, -40, 20);
  m.ceiling_db = o.number("ceiling_db", m.ceiling_db, -20, 0);
  m.limiter_release = o.number("limiter_release", m.limiter_release, 0.01, 5);
  m.duck_hold = o.number("duck_hold", m.duck_hold, 0, 10);
  m.duck_release = o.number("duck_release", m.duck_release, 0.01, 10);
  if (auto v = o.get("ducked")) {
    for (bool& d : m.ducked) d = false;
    for (const JsonValue& g : v->array())
      m.ducked[int(group_of(g.choice({"music", "weapons", "impacts", "engines", "ui", "voice"})))] = true;
  }
  o.allow({"doc"});
  o.finish();
  return m;
}

SoundDef parse_sound(const std::string& name, JsonObject o) {
  SoundDef s;
  s.name = name;
  s.loop = o.boolean("loop", false);
  s.duration = o.number("duration", s.duration, 0.02, 10);
  s.priority = int(o.integer("priority", s.priority, 0, 100));
  s.gain = o.number("gain", s.gain, 0, 4);
  s.positional = o.boolean("positional", true);
  s.reference_distance = o.number("reference_distance", s.reference_distance, 0.01, 1e6);
  s.max_distance = o.number("max_distance", s.max_distance, 0.01, 1e9);
  s.rolloff = o.number("rolloff", s.rolloff, 0, 10);
  s.seed = uint64_t(o.integer("seed", 1, 0, UINT32_MAX));
  s.group = group_of(o.choice("group", s.positional ? "weapons" : "ui", {"weapons", "impacts", "engines", "ui", "voice"}));
  s.max_voices = int(o.integer("max_voices", 0, 0, 128));
  s.duck = o.number("duck", 0, 0, 40);
  s.duck_hold = o.number("duck_hold", -1, -1, 30);
  for (JsonObject layer : o.objects("layers")) s.layers.push_back(parse_layer(layer));
  if (s.layers.empty()) o.fail("sound '" + name + "' needs 'layers': a non-empty array of layer objects");
  o.allow({"doc"});
  o.finish();
  return s;
}

SoundLibraryDef parse_root(const std::shared_ptr<const JsonDoc>& doc) {
  JsonObject root = JsonValue(doc, "", &doc->root()).object();
  SoundLibraryDef lib;
  lib.speed_of_sound = root.number("speed_of_sound", lib.speed_of_sound, 1, 1e6);
  lib.doppler_factor = root.number("doppler_factor", lib.doppler_factor, 0, 10);
  if (root.has("mix")) lib.mix = parse_mix(root.require_object("mix"));
  JsonObject sounds = root.require_object("sounds");
  for (auto it = sounds.raw().begin(); it != sounds.raw().end(); ++it) {
    JsonValue v = *sounds.get(it.key());
    lib.sounds.push_back(parse_sound(it.key(), v.object()));
  }
  sounds.finish();
  root.allow({"doc"});
  root.finish();
  return lib;
}

}  // namespace

const char* mix_group_name(MixGroup g) {
  switch (g) {
    case MixGroup::Music: return "music";
    case MixGroup::Weapons: return "weapons";
    case MixGroup::Impacts: return "impacts";
    case MixGroup::Engines: return "engines";
    case MixGroup::Ui: return "ui";
    case MixGroup::Voice: return "voice";
  }
  return "";
}

SoundLibraryDef load_sound_library(const std::string& path) { return parse_root(JsonDoc::load_file(path)); }

SoundLibraryDef parse_sound_library(const std::string& text, const std::string& path) {
  return parse_root(JsonDoc::parse(text, path));
}

}  // namespace arc
