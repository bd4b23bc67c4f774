// game/net/content_hash.h — what two peers must share byte for byte to play one match: the
// build, the level file and the data the simulation reads (ship classes, effects, AI table).
#pragma once
#include <cstdint>
#include <string>

namespace arc {

// The build: its version string and the packet protocol.
uint64_t build_content_id(const char* version);
// The level file's bytes (InputError when unreadable).
uint64_t level_content_hash(const std::string& level_path);
// assets/ships/*.json, assets/effects/*.json and assets/settings/ai.json under `root`, in path order.
uint64_t asset_content_hash(const std::string& root);

}  // namespace arc
