# live_window.sh — sourced by the live-session tests (record_live.sh, record_restart.sh).
# require_tools NAME: exits 77 (ctest: skipped) when xvfb-run or xdotool is missing; installs nothing.
# play_recorded NAME ARCFIRE REC LOG KEYS: starts the game recording REC in a window under
# xvfb-run -a, waits for the window, runs the xdotool commands KEYS (a bash snippet), then
# ends the game with SIGTERM. The level is $LEVEL when set (the snippet may use $level).
require_tools() {
  for tool in xvfb-run xdotool; do
    if ! command -v "$tool" >/dev/null; then
      echo "$1: $tool is not installed; skipping (apt-get install xdotool xvfb)"
      exit 77
    fi
  done
}

play_recorded() {
  xvfb-run -a -s "-screen 0 1280x720x24" bash -c '
    name="$1"; arcfire="$2"; rec="$3"; log="$4"; keys="$5"
    level="${LEVEL:-tests/replays/levels/range.json}"
    "$arcfire" --level "$level" --record "$rec" --size 640x360 >"$log" 2>&1 &
    pid=$!
    win=$(timeout 30 xdotool search --sync --onlyvisible --name "Arcfire" | head -n 1)
    if [ -z "$win" ]; then echo "$name: no Arcfire window appeared"; kill $pid; cat "$log"; exit 1; fi
    xdotool windowactivate --sync "$win" 2>/dev/null || xdotool windowfocus --sync "$win"
    sleep 1
    eval "$keys"
    kill -TERM $pid; wait $pid
    exit 0
  ' _ "$@"
}
