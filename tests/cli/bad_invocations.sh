#!/usr/bin/env bash
# bad_invocations.sh ARCFIRE
# Contradictory options, options the mode would ignore and empty values: each invocation of the
# table exits 2 with exactly one line on stderr naming the option and what is allowed.
set -u
arcfire="$1"; expect="$(dirname "$0")/expect.sh"
replay=tests/replays/range_beam_shield.replay
failed=0
row() {  # row REGEX ARGS...
  local regex="$1"; shift
  "$expect" 2 "$regex" -- "$arcfire" "$@" || { echo "  in: arcfire $*"; failed=1; }
}
row "^arcfire: --quality: empty value; allowed: low, medium, high or reference$" --headless --no-render --ticks 1 --quality ""
row "^arcfire: --difficulty: empty value; allowed: easy, normal or hard$" --headless --no-render --ticks 1 --difficulty ""
row "^arcfire: --level: empty value; allowed: a file name$" --headless --no-render --ticks 1 --level ""
row "^arcfire: --summary: empty value; allowed: a file name$" --headless --no-render --ticks 1 --summary ""
row "^arcfire: --out: empty value; allowed: a folder$" --headless --ticks 1 --out ""
row "^arcfire: --bindings: empty value" --headless --no-render --ticks 1 --bindings ""
row "^arcfire: --set: empty value; allowed: key=value$" --headless --no-render --ticks 1 --set ""
row "^arcfire: --replay and --demo: one mode at a time" --replay "$replay" --demo
row "^arcfire: --replay and --serialization-test: one mode at a time" --replay "$replay" --serialization-test 10
row "^arcfire: --ticks: not with --replay: the script decides" --replay "$replay" --no-render --ticks 5
row "^arcfire: --level: not with --replay: the script names its level" --replay "$replay" --no-render --level levels/duel.json
row "^arcfire: --seed: not with --replay" --replay "$replay" --no-render --seed 3
row "^arcfire: --difficulty: not with --replay" --replay "$replay" --no-render --difficulty hard
row "^arcfire: --size: not with --replay" --replay "$replay" --size 64x64
row "^arcfire: --summary: only with --headless or --demo$" --replay "$replay" --no-render --summary x.json
row "^arcfire: --update-golden: only with --replay$" --headless --no-render --ticks 1 --update-golden
row "^arcfire: --fullscreen: only in a window$" --headless --no-render --ticks 1 --fullscreen
row "^arcfire: --fps: only in a window$" --headless --no-render --ticks 1 --fps
row "^arcfire: --dev: only in a window$" --replay "$replay" --no-render --dev
row "^arcfire: --record: only in a window" --headless --no-render --ticks 1 --record x.replay
row "^arcfire: --every: only with --headless and --out" --headless --no-render --ticks 30 --every 30
row "^arcfire: --out: not with --no-render" --headless --no-render --ticks 1 --out out/never
row "^arcfire: --demo: not with --no-render" --headless --demo --no-render
row "^arcfire: --ticks: only with --headless, --demo, --serialization-test, --host or --join$" --ticks 10
row "^arcfire: --no-render: only with --headless or --replay$" --no-render
exit $failed
