// game/app/menu_items.h — the menu's row kinds, shared by menu.cpp, menu_settings.cpp and menu_loadout.cpp only.
#pragma once
#include "game/app/menu.h"

namespace arc {

enum class Menu::Item {
  Play, Effects, Settings, Quit,                                   // main
  Mission, Effect, Difficulty, Launch, Back,                       // lists and briefing
  Ship, Loadout,                                                   // the briefing's choice
  Graphics, Sound, Controls, Advanced, ResetProgress,              // the settings screen
  Quality, Scale, Fullscreen, Vsync, Fov,                          // graphics
  MasterVolume, EffectsVolume, Mute,                               // sound
  MusicVolume, WeaponsVolume, ImpactsVolume, EnginesVolume, UiVolume, VoiceVolume, Subtitles,  // sound groups
  Sensitivity, InvertY, Deadzone, RemapKeys,                       // controls
  Action, ResetKeys,                                               // key remapping
  DevPanel, RenderKey, ResetRender,                                // advanced
  Retry, Next, ToMenu,                                             // results
  Resume, Restart, PauseDifficulty, PauseSound, Volume, MainMenu,  // pause (and Quit)
  QuickBattle, QuickPlayer, QuickWingmen, QuickWing, QuickEnemies,  // quick battle
  QuickEnemy, QuickCapital, QuickAsteroids, QuickDifficulty, QuickLaunch,
  Multiplayer, NetHostPage, NetJoinPage, NetName,                   // multiplayer (menu_net.cpp)
  NetMission, NetDifficulty, NetPort, NetOpen,                      // host
  NetAddress, NetRecent, NetConnect,                                // join
  LobbySlot, NetLaunch, NetLeave                                    // lobby
};

}  // namespace arc
