// arcfire — entry point. Parses the command line and hands over to one of the modes:
// window (play), headless frames / demo / summary, replay, serialization test.
// Exit codes: 0 success, 1 a check failed (a write that failed on the way counts as one), 2 bad
// input or usage (an output path that cannot be used too), 130 or 143 stopped by SIGINT or SIGTERM
// after the mode's files are written (platform/stop_request.h).
#include <cstdio>
#include <exception>

#include "core/error.h"
#include "core/file_writer.h"
#include "game/app/app_options.h"
#include "game/app/effect_preview.h"
#include "game/app/headless_run.h"
#include "game/app/menu_snapshots.h"
#include "game/app/net_run.h"
#include "game/app/replay_player.h"
#include "game/app/serialization_test.h"
#include "game/app/window_loop.h"
#include "game/workbench/workbench_window.h"
#include "platform/platform.h"
#include "platform/stop_request.h"

int main(int argc, char** argv) {
  arc::install_stop_handlers();
  arc::AppOptions options;
  try {
    if (auto code = arc::parse_command_line(argc, argv, options)) return *code;
    // A network match in a window is the window's (window_net.cpp); headless, net_run's.
    if (options.net.active() && options.headless) return arc::run_net(options);
    if (!options.replay_path.empty()) return arc::run_replay(arc::ReplayRunOptions(options));
    if (options.serialization_test > 0) return arc::run_serialization_test(arc::SerializationTestOptions(options));
    if (!options.menu_script.empty()) return arc::run_menu_script(options);
    if (!options.preview_path.empty()) return arc::run_preview(arc::preview_options(options));
    if (options.headless || options.demo) return arc::run_headless(options);
    if (options.workbench)
      return arc::run_workbench({.root_dir = options.game.root_dir, .effect_path = options.workbench_effect,
                                 .settings = options.settings, .width = options.width, .height = options.height,
                                 .vsync = options.vsync});
    return arc::run_window(options);
  } catch (const arc::WriteError& e) {
    std::fprintf(stderr, "arcfire: %s\n", e.what());
    return e.exit_code;
  } catch (const arc::InputError& e) {
    std::fprintf(stderr, "arcfire: %s\n", e.what());
    return arc::kExitBadInput;
  } catch (const arc::PlatformError& e) {
    std::fprintf(stderr, "arcfire: %s\n", e.what());
    return arc::kExitBadInput;
  } catch (const std::exception& e) {
    // Anything else still ends in one line and a code, never an abort without a word.
    std::fprintf(stderr, "arcfire: %s\n", arc::InputError::one_line(e.what()).c_str());
    return arc::kExitBadInput;
  }
}
