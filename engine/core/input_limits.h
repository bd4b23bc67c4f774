// core/input_limits.h — the largest input each loader accepts, checked before the expensive work.
//
// A tweaker who pastes a broken file or a tester fed a corrupted replay must get one line and
// exit code 2 at once, whatever the file holds. Every loader therefore checks the size of its
// input first (a stat, before a byte is read), and JSON text is scanned once, linearly, for
// nesting depth, string length and the length of each value's JSON pointer before nlohmann and
// the position recorder (core/json.cpp) see it: the recorder keeps one pointer string per value,
// so bounded pointers keep its cost linear in the file size.
//
// Example, compiled as CoreExamples.CheckBeforeParsing in tests/unit/core/test_core_examples.cpp:
//   check_file_size("levels/duel.json", kMaxDataFileBytes, "a data file");  // throws InputError
//   check_json_text(text, path, kDataJsonLimits);                           // path:line:col: ...
//
// The figures are stated for users in levels/README.md, assets/effects/README.md and
// tests/replays/README.md; change them there too.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

namespace arc {

// Data files: levels, ship classes, effects, quality presets, key bindings, HUD, AI, sounds,
// the player's settings and progress. The largest honest ones are generated: a ship class of
// 100 000 exhaust points pretty-printed (up to 80 bytes a point, 8 MB) and a level of 10 000
// ships (850 KB); 16 MiB holds both twice over and parses in well under a second.
constexpr size_t kMaxDataFileBytes = size_t(16) << 20;
// glTF models (.glb or .gltf with embedded buffers) and images.
constexpr size_t kMaxModelFileBytes = size_t(64) << 20;
constexpr size_t kMaxImageFileBytes = size_t(32) << 20;
// Decoded images: pixels per side and RGBA8 bytes in all. 16384 a side is what every current
// GPU takes as a texture. Images are handed out as RGBA8, and a decode holds the codec's pixels
// and the RGBA8 copy at once, so a 16384² image (1 GiB of RGBA8) cannot fit the 500 MB a run
// may use: 128 MiB of RGBA8 (16384×2048, 8192×4096, 5792²) keeps a decode within 256 MiB.
constexpr int kMaxImageSide = 16384;
constexpr size_t kMaxImageDecodedBytes = size_t(128) << 20;
// glTF models: vertices and indices after node instancing and flat shading; the
// images of one model decoded together.
constexpr size_t kMaxModelVertices = size_t(4) << 20;
constexpr size_t kMaxModelIndices = size_t(12) << 20;
constexpr size_t kMaxModelImageBytes = size_t(128) << 20;
// Replay scripts and hash logs: bytes, lines and bytes per line.
constexpr size_t kMaxScriptFileBytes = size_t(16) << 20;
constexpr size_t kMaxScriptLines = 1000000;
constexpr size_t kMaxScriptLineBytes = 4096;
// The last tick a script may name, absolute or as the sum of its +N lines: 1e9 ticks is over
// six months of play at 60 Hz, and keeps every tick count far from overflow.
constexpr uint64_t kMaxScriptTick = 1000000000;
// GLSL sources of the shader folder: the largest is a few KiB.
constexpr size_t kMaxShaderFileBytes = size_t(1) << 20;
// Binary world snapshots.
constexpr size_t kMaxSnapshotBytes = size_t(256) << 20;

// Lists in data files, each checked before its elements are read (JsonObject::check_list_length).
// Ships: a generated fleet battle of 10 000 ships, with room to spare; props and placed effects
// cost a draw or an emitter each and scenery needs hundreds, not thousands.
constexpr size_t kMaxLevelShips = 16384;
constexpr size_t kMaxLevelProps = 4096;
constexpr size_t kMaxLevelEffects = 4096;
constexpr size_t kMaxEffectClusters = 64;
constexpr size_t kMaxCurveKeys = 256;
constexpr size_t kMaxEmitterTriangles = 4096;
// Beam mounts and hardpoints each fire a shot a tick at most: 64 is a battleship's broadside.
constexpr size_t kMaxShipPoints = 64;
// Exhausts only glow (an emitter each, its particles within the particle budget): a hull
// outlined in 100 000 vents is meant, with room to spare.
constexpr size_t kMaxShipExhausts = size_t(1) << 17;

struct JsonLimits {
  size_t max_bytes;         // the whole text
  int max_depth;            // nested arrays and objects
  size_t max_string_bytes;  // one string or key, as written (escapes counted as written)
  size_t max_pointer_bytes; // one value's JSON pointer: /key/3/key..., keys as written
  size_t max_objects;       // objects in the whole text (each costs a loader a struct)
  size_t max_values;        // arrays, objects, and elements or members after the first (a comma each)
  size_t max_pointer_total_bytes;  // the pointers of all values together
  const char* kind;         // for messages: "a data file (...) may be at most ..."
};

// Hand-written data files: 16 levels of nesting is twice what any of them uses.
// Objects and values: a generated level of 10 000 ships (about 12 values and 1 object each) and a
// ship class of 100 000 exhaust points (4 values each) fit with room to spare. The position
// recorder keeps one entry and one pointer string per value, so the value count and the pointers'
// total (under 10 MB for either file) bound its memory to about 150 MB whatever the file holds.
constexpr JsonLimits kDataJsonLimits{kMaxDataFileBytes, 16, 4096, 256, 65536, size_t(1) << 20, size_t(32) << 20,
                                     "a data file (level, ship class, effect, settings, bindings)"};
// The JSON of a glTF model: base64 buffers and images may fill the file; tinygltf records no
// pointers, so deeper extras are fine; but it makes a struct of up to a few KB per object (node,
// accessor, material...), so their number is what bounds its memory.
constexpr JsonLimits kModelJsonLimits{kMaxModelFileBytes, 64, kMaxModelFileBytes, SIZE_MAX, 65536, SIZE_MAX, SIZE_MAX,
                                      "a glTF model"};

// "256 KiB", "16 MiB" or "1000 bytes": a limit as the messages and READMEs state it.
std::string byte_size_text(size_t bytes);
// Throws InputError "path: file is N bytes; WHAT may be at most M bytes" when the file is larger
// than `max_bytes`; a missing file passes (the reader reports it).
void check_file_size(const std::string& path, size_t max_bytes, const std::string& what);
// Throws InputError "path: N bytes; WHAT may be at most M bytes" for text already in memory.
void check_text_size(size_t size, const std::string& path, size_t max_bytes, const std::string& what);
// One linear pass over JSON text (comments allowed): throws InputError for text over the size
// limit, then a positioned one at the first value nested too deep, string too long or pointer
// too long. Syntax errors are left to the parser.
void check_json_text(const char* text, size_t size, const std::string& path, const JsonLimits& limits);
inline void check_json_text(const std::string& text, const std::string& path, const JsonLimits& limits) {
  check_json_text(text.data(), text.size(), path, limits);
}

}  // namespace arc
