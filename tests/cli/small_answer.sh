#!/usr/bin/env bash
# small_answer.sh LIMIT_KB EXIT_CODE -- COMMAND...
# COMMAND must exit with EXIT_CODE having used at most LIMIT_KB of resident memory at its peak
# (GNU time's maximum resident set size; a memory figure, not a timing). Skipped (77) without
# /usr/bin/time, and for a sanitizer build (tools/sanitize.sh), whose shadow memory and
# quarantine are most of any figure.
set -u
limit="$1"; want="$2"; shift 3
[ -x /usr/bin/time ] || { echo "skipped: /usr/bin/time (GNU time) is not installed"; exit 77; }
if ldd "$1" 2>/dev/null | grep -Eq 'lib(asan|tsan|msan)'; then echo "skipped: $1 is built with a sanitizer"; exit 77; fi
peak="$(mktemp)"
/usr/bin/time -o "$peak" -f '%M' "$@" >/dev/null 2>&1
got=$?
kb=$(tail -1 "$peak"); rm -f "$peak"
[ "$got" -eq "$want" ] || { echo "exit $got, expected $want"; exit 1; }
[ "$kb" -le "$limit" ] || { echo "peak resident memory $kb KB, the limit is $limit KB"; exit 1; }
echo "ok: exit $got, peak resident memory $kb KB (limit $limit KB)"
