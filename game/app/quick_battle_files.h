// game/app/quick_battle_files.h — the quick battle's files around the menu: the remembered setup
// offered on the main menu, the generated level written before launch, and its copy beside a recording.
#pragma once
#include <string>

#include "game/app/menu.h"

namespace arc {

// Offers the quick battle on `menu` with the classes of `root_dir` and the setup remembered in
// `user_dir` (a bad file is replaced by the default; the menu and stderr say so).
void offer_quick_battle(Menu& menu, const std::string& root_dir, const std::string& user_dir);
// Writes a generated level at `path` (its folder made if missing), atomically; InputError if it cannot.
void write_generated_level(const std::string& path, const std::string& text);
// Copies the level at `level` beside the recording `record_path` (NAME.level.json for NAME.EXT)
// and returns the copy's path: the recording names it, so it replays without the player's folder.
std::string copy_beside_recording(const std::string& level, const std::string& record_path);

}  // namespace arc
