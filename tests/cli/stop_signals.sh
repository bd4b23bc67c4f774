#!/usr/bin/env bash
# stop_signals.sh ARCFIRE OUT [window|headless]
# Ctrl+C (SIGINT) and `kill` (SIGTERM) end a run as its normal end would (platform/stop_request.h):
#   window    a live session under xvfb-run with --record and --frame-times, keys fed by xdotool:
#             exit 130 / 143, the stop line, the recording ends with `end` at the tick the line
#             names and replays, the frame-time CSV is written; SIGINT then SIGTERM at once
#             exits without writing the CSV, and the recording, cut off as by a crash, replays.
#   headless  --headless --summary --audio-out and a replay: exit 130 / 143, the stop line, the
#             summary of the tick reached, a WAV that is whole, no check failure and no golden
#             updated; a second signal exits at once, writing nothing; a network host alone
#             (--players 1, the AI in every slot): exit 130 / 143, its record replays to its hash.
# The window part exits 77 (ctest: skipped) when xvfb-run or xdotool is missing.
set -u
arcfire="$(realpath "$1")"; out="$(realpath -m "$2")"; part="${3:-headless}"
source "$(dirname "$0")/../replays/live_window.sh"
fail() { echo "stop_signals ($part): $*"; exit 1; }
code_of() { [ "$1" = INT ] && echo 130 || echo 143; }
rm -rf "$out"; mkdir -p "$out"

# after TENTHS PID: waits TENTHS tenths of a second, or less when the run ends first.
after() { for _ in $(seq 1 "$1"); do kill -0 "$2" 2>/dev/null || return; sleep 0.1; done; }
# A run with --audio-out keeps its sound in memory (6.4 KB a tick): a run the signal failed to
# stop ends on this limit, not on the machine's. Run in the background, it is the program itself.
limited() { ulimit -v 3000000; exec "$@"; }

# A WAV as write_wav_stereo16 makes it: RIFF and data sizes that match the file, and as many
# frames as TICKS ticks of sound at 60 ticks a second.
check_wav() {
  local wav="$1" ticks="$2" size riff data rate
  [ -s "$wav" ] || fail "no WAV at $wav"
  size=$(stat -c %s "$wav")
  riff=$(od -An -tu4 -j4 -N4 "$wav" | tr -d ' '); rate=$(od -An -tu4 -j24 -N4 "$wav" | tr -d ' ')
  data=$(od -An -tu4 -j40 -N4 "$wav" | tr -d ' ')
  [ "$riff" = $((size - 8)) ] && [ "$data" = $((size - 44)) ] || fail "$wav: RIFF size $riff, data size $data, file $size bytes"
  local frames=$((data / 4)) want=$((ticks * rate / 60))
  [ $((frames - want)) -le 1 ] && [ $((want - frames)) -le 1 ] || fail "$wav: $frames frames for $ticks ticks at $rate Hz"
}

headless() {
  for sig in INT TERM; do
    local base="$out/headless_$sig" code; code=$(code_of $sig)
    limited "$arcfire" --headless --no-render --level levels/attract.json --ticks 1000000 --summary "$base.json" \
      --audio-out "$base.wav" >"$base.out" 2>"$base.err" &
    local pid=$!
    after 20 $pid
    kill -$sig $pid; wait $pid; local rc=$?
    [ "$rc" = "$code" ] || fail "SIG$sig: exit $rc, expected $code: $(cat "$base.err")"
    local line tick
    line=$(grep "stopped by" "$base.err")
    tick=$(sed -n "s/^arcfire: stopped by SIG$sig at tick \([0-9]*\) of 1000000$/\1/p" <<<"$line")
    [ -n "$tick" ] || fail "SIG$sig: no stop line naming the tick: $(cat "$base.err")"
    grep -q "\"tick\": *$tick[,}]" "$base.json" || fail "SIG$sig: the summary is not that of tick $tick: $(head -c 300 "$base.json")"
    check_wav "$base.wav" "$tick"
    grep -q "simulated" "$base.out" && fail "SIG$sig: reported as a whole run"
    echo "headless SIG$sig: exit $rc at tick $tick, summary and WAV written"
  done

  # A replay far longer than the wait, with a hash line it never reaches: no FAIL, no golden.
  mkdir -p "$out/replays"
  printf 'arcfire-replay 1\nlevel tests/replays/levels/range.json\ntick_rate 60\n\n0 axis throttle 1\n900000 hash ?\n1000000 end\n' \
    >"$out/replays/long.replay"
  cp "$out/replays/long.replay" "$out/long.replay.orig"
  for sig in INT TERM; do
    local base="$out/replay_$sig" code extra=(); code=$(code_of $sig)
    [ $sig = TERM ] && extra=(--update-golden)
    limited "$arcfire" --headless --no-render --replay "$out/replays/long.replay" --audio-out "$base.wav" "${extra[@]}" \
      >"$base.out" 2>"$base.err" &
    local pid=$!
    after 20 $pid
    kill -$sig $pid; wait $pid; local rc=$?
    [ "$rc" = "$code" ] || fail "replay SIG$sig: exit $rc, expected $code: $(cat "$base.err")"
    local tick
    tick=$(sed -n "s/^arcfire: stopped by SIG$sig at tick \([0-9]*\) of 1000000.*/\1/p" "$base.err")
    [ -n "$tick" ] || fail "replay SIG$sig: no stop line naming the tick: $(cat "$base.err")"
    ! grep -q "FAIL\|final hash" "$base.out" || fail "replay SIG$sig: reported a failure or a final hash: $(cat "$base.out")"
    check_wav "$base.wav" "$tick"
    echo "replay SIG$sig: exit $rc at tick $tick, no failure, WAV written"
  done
  grep -q "the golden files are unchanged" "$out/replay_TERM.err" || fail "replay --update-golden: $(cat "$out/replay_TERM.err")"
  cmp -s "$out/replays/long.replay" "$out/long.replay.orig" || fail "--update-golden rewrote the script"
  [ ! -e "$out/replays/golden/long/hashes.txt" ] || fail "--update-golden wrote a hash log"

  # A network host alone: the lobby launches at once, the match runs until the signal.
  for sig in INT TERM; do
    local base="$out/net_$sig" code final replayed; code=$(code_of $sig)
    "$arcfire" --headless --host --players 1 --port $((30000 + ($$ + RANDOM) % 20000)) --level levels/duel.json \
      --ticks 1000000 --match-record "$base.replay" >"$base.out" 2>"$base.err" &
    local pid=$!
    after 20 $pid
    kill -$sig $pid; wait $pid; local rc=$?
    [ "$rc" = "$code" ] || fail "net SIG$sig: exit $rc, expected $code: $(cat "$base.out" "$base.err")"
    tick=$(sed -n "s/^arcfire: stopped by SIG$sig at tick \([0-9]*\) of 1000000$/\1/p" "$base.err")
    [ -n "$tick" ] || fail "net SIG$sig: no stop line naming the tick: $(cat "$base.err")"
    final=$(sed -n 's/.*final tick \([0-9]*\) hash \([0-9a-f]*\).*/\1 \2/p' "$base.out")
    [ "${final%% *}" = "$tick" ] || fail "net SIG$sig: final line '$final', stop line tick $tick"
    "$arcfire" --headless --no-render --replay "$base.replay" >"$base.replay.log" 2>&1 ||
      fail "net SIG$sig: the record does not replay: $(tail -3 "$base.replay.log")"
    replayed=$(sed -n 's/^final hash \([0-9a-f]*\) at tick \([0-9]*\).*/\2 \1/p' "$base.replay.log")
    [ "$replayed" = "$final" ] || fail "net SIG$sig: the record replays to '$replayed', the host ended at '$final'"
    echo "net host SIG$sig: exit $rc at tick $tick, the record replays to its hash"
  done

  # Both signals while the run cannot act on the first: the second ends it before any writing.
  local base="$out/twice"
  "$arcfire" --headless --no-render --level levels/attract.json --ticks 10000000 --summary "$base.json" \
    >"$base.out" 2>"$base.err" &
  local pid=$!
  after 20 $pid
  kill -STOP $pid; kill -INT $pid; kill -TERM $pid; kill -CONT $pid
  wait $pid; local rc=$?
  [ "$rc" = 143 ] || [ "$rc" = 130 ] || fail "two signals: exit $rc, expected 143 or 130"
  [ ! -e "$base.json" ] || fail "two signals: the summary was written, the second signal did not end it at once"
  ! grep -q "stopped by" "$base.err" || fail "two signals: $(cat "$base.err")"
  echo "two signals: exit $rc at once"
}

# One live session: keys for a few seconds, then SIG (or STOP, INT, TERM, CONT for "twice").
window_run() {
  local sig="$1" base="$out/window_$1"
  xvfb-run -a -s "-screen 0 1280x720x24" bash -c '
    arcfire="$1"; base="$2"; sig="$3"
    "$arcfire" --level tests/replays/levels/range.json --size 640x360 --record "$base.replay" \
      --frame-times "$base.csv" >"$base.out" 2>"$base.err" &
    pid=$!
    win=$(timeout 30 xdotool search --sync --onlyvisible --name "Arcfire" | head -n 1)
    if [ -z "$win" ]; then echo "no Arcfire window appeared"; kill $pid; cat "$base.err"; exit 1; fi
    xdotool windowactivate --sync "$win" 2>/dev/null || xdotool windowfocus --sync "$win"
    # The first hash line: a second of the game has been played (shaders compiled, frames drawn).
    for _ in $(seq 1 600); do grep -q "^[0-9]* hash " "$base.replay" 2>/dev/null && break; sleep 0.1; done
    xdotool keydown w; sleep 1.5; xdotool keyup w; xdotool key t; sleep 1
    if [ "$sig" = twice ]; then kill -STOP $pid; kill -INT $pid; kill -TERM $pid; kill -CONT $pid
    else kill -$sig $pid; fi
    wait $pid; echo $? >"$base.code"
  ' _ "$arcfire" "$base" "$sig" || fail "SIG$sig: the window session did not run"
}

window() {
  require_tools cli_stop_signals_window
  for sig in INT TERM; do
    local base="$out/window_$sig" code; code=$(code_of $sig)
    window_run $sig
    local rc; rc=$(cat "$base.code")
    [ "$rc" = "$code" ] || fail "SIG$sig: exit $rc, expected $code: $(cat "$base.err")"
    local tick
    tick=$(sed -n "s/^arcfire: stopped by SIG$sig at tick \([0-9]*\)$/\1/p" "$base.err")
    [ -n "$tick" ] || fail "SIG$sig: no stop line naming the tick: $(cat "$base.err")"
    [ "$(tail -n 1 "$base.replay")" = "$tick end" ] || fail "SIG$sig: the recording ends '$(tail -n 1 "$base.replay")', not '$tick end'"
    [ "$(tail -c 1 "$base.replay" | od -An -c | tr -d ' ')" = '\n' ] || fail "SIG$sig: the recording ends in a cut line"
    grep -qE '^[0-9]+ axis throttle ' "$base.replay" || fail "SIG$sig: the throttle was not recorded"
    "$arcfire" --headless --no-render --replay "$base.replay" --out "$base.replayed" >"$base.replay.log" 2>&1 ||
      fail "SIG$sig: the recording does not replay: $(cat "$base.replay.log")"
    grep -q "^final hash [0-9a-f]* at tick $tick$" "$base.replay.log" || fail "SIG$sig: the replay does not reach tick $tick"
    grep -qE "^arcfire: [0-9]+ frames in [0-9.]+ s" "$base.out" || fail "SIG$sig: no frame-time summary: $(cat "$base.out")"
    head -1 "$base.csv" | grep -q "^time_s,frame_ms,tick," || fail "SIG$sig: no frame-time CSV at $base.csv"
    [ "$(($(wc -l <"$base.csv") - 1))" -ge 10 ] || fail "SIG$sig: only $(($(wc -l <"$base.csv") - 1)) frames in the CSV"
    echo "window SIG$sig: exit $rc at tick $tick, recording replays, $(($(wc -l <"$base.csv") - 1)) frames logged"
  done
  window_run twice
  local base="$out/window_twice" rc; rc=$(cat "$base.code")
  [ "$rc" = 143 ] || [ "$rc" = 130 ] || fail "two signals: exit $rc, expected 143 or 130"
  [ ! -e "$base.csv" ] || fail "two signals: the frame-time CSV was written, the second signal did not end it at once"
  # Cut off without its `end`, as by a crash: whole lines still, and it replays.
  [ "$(tail -c 1 "$base.replay" | od -An -c | tr -d ' ')" = '\n' ] || fail "two signals: the recording ends in a cut line"
  ! grep -q " end$" "$base.replay" || fail "two signals: the recording was ended, the second signal did not end it at once"
  "$arcfire" --headless --no-render --replay "$base.replay" --out "$base.replayed" >"$base.replay.log" 2>&1 ||
    fail "two signals: the recording does not replay: $(cat "$base.replay.log")"
  echo "window, two signals: exit $rc at once, the recording cut off without \`end\` replays"
}

case "$part" in
  window) window ;;
  headless) headless ;;
  *) fail "part must be window or headless" ;;
esac
