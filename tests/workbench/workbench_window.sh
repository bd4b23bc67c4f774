#!/usr/bin/env bash
# workbench_window.sh ARCFIRE TEST_APP OUT_DIR
# The effect workbench in a window (under xvfb-run -a, keys fed by xdotool): it opens on
# ship_explosion, F12 saves a screenshot with the panel, Esc quits with exit code 0; then
# test_app's WorkbenchScreenshot checks the picture is not blank and shows the panel.
# Exits 77 (ctest: skipped) when xvfb-run or xdotool is missing; it installs nothing.
set -u
arcfire="$(realpath "$1")"; test_app="$(realpath "$2")"; out="$(realpath -m "$3")"
for tool in xvfb-run xdotool; do
  command -v "$tool" >/dev/null || { echo "workbench_window: $tool is not installed; skipping"; exit 77; }
done
rm -rf "$out"; mkdir -p "$out"
cd "$out" || exit 1
xvfb-run -a -s "-screen 0 1280x720x24" bash -c '
  arcfire="$1"
  "$arcfire" --workbench assets/effects/ship_explosion.json --size 1280x720 >workbench.log 2>&1 &
  pid=$!
  win=$(timeout 60 xdotool search --sync --onlyvisible --name "Arcfire workbench" | head -n 1)
  if [ -z "$win" ]; then echo "workbench_window: no workbench window appeared"; kill $pid; cat workbench.log; exit 1; fi
  xdotool windowactivate --sync "$win" 2>/dev/null || xdotool windowfocus --sync "$win"
  sleep 3
  xdotool key --window "$win" F12; sleep 2
  xdotool key --window "$win" Escape
  for i in $(seq 1 40); do kill -0 $pid 2>/dev/null || break; sleep 0.5; done
  if kill -0 $pid 2>/dev/null; then echo "workbench_window: Esc did not quit"; kill -TERM $pid; cat workbench.log; exit 1; fi
  wait $pid; rc=$?
  cat workbench.log
  [ $rc -eq 0 ] || { echo "workbench_window: exit code $rc, expected 0"; exit 1; }
' _ "$arcfire" || exit 1
shot="$out/out/screenshots/workbench_0001.png"
[ -s "$shot" ] || { echo "workbench_window: F12 wrote no $shot"; exit 1; }
ARCFIRE_WORKBENCH_SHOT="$shot" "$test_app" --gtest_filter='WorkbenchScreenshot.*' || exit 1
echo "workbench_window: opened, showed the panel, quit with 0 on Esc ($shot)"
