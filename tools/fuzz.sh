#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz/) in build-fuzz/ with clang 14, AddressSanitizer and
# UndefinedBehaviorSanitizer, then runs each in turn for SECONDS (default 60) and reports its
# executions, coverage and any finding with its reproducer path.
#   tools/fuzz.sh [SECONDS] [TARGET...]        e.g. tools/fuzz.sh 600 level replay
#   FUZZ_RUNS=1000000 tools/fuzz.sh 600        stop a target at a million executions if sooner
# New inputs go to build-fuzz/corpus/TARGET/, findings to build-fuzz/findings/TARGET/; copy a
# fixed finding into tests/fuzz/regression/TARGET/ so ctest keeps it fixed. Exit 1 on a finding.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
seconds="${1:-60}"
shift || true
all=(level ship_class effect quality bindings replay snapshot model_glb model_gltf sprite packet)
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=("${all[@]}")
out="${FUZZ_BUILD:-$root/build-fuzz}"

"$root/tools/install-deps.sh"
if ! command -v clang++-14 >/dev/null || ! dpkg-query -W -f='${Status}' libclang-rt-14-dev 2>/dev/null | grep -q "ok installed"; then
  echo "fuzz: installing clang-14 and libclang-rt-14-dev"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends clang-14 libclang-rt-14-dev >/dev/null
fi

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
flags="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
cmake -S "$root" -B "$out" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DARCFIRE_FUZZ=ON \
  -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 "${launcher[@]}" \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
nice -n 19 cmake --build "$out" -j"${FUZZ_JOBS:-2}" --target "${targets[@]/#/fuzz_}"

mkdir -p "$out/logs"
summary=()
status=0
for t in "${targets[@]}"; do
  mkdir -p "$out/corpus/$t" "$out/findings/$t" "$root/tests/fuzz/regression/$t"
  log="$out/logs/$t.log"
  echo "fuzz: $t for ${seconds}s (log: $log)"
  rc=0
  # Leak checks are off: OpenImageIO and Mesa keep caches for the life of the process.
  ASAN_OPTIONS=detect_leaks=0:allocator_may_return_null=0 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    nice -n 19 "$out/fuzz_$t" "$out/corpus/$t" "$root/tests/fuzz/corpus/$t" "$root/tests/fuzz/regression/$t" \
    -dict="$root/tests/fuzz/dict/$t.dict" -max_total_time="$seconds" -runs="${FUZZ_RUNS:--1}" \
    -timeout=5 -rss_limit_mb=2048 -malloc_limit_mb=512 -print_final_stats=1 \
    -artifact_prefix="$out/findings/$t/" >"$log" 2>&1 || rc=$?
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -1 || true)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || true)
  ft=$(grep -o 'ft: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || true)
  found=$(grep -o "Test unit written to [^ ]*" "$log" | sed 's/Test unit written to //' || true)
  line="$t: ${execs:-?} executions, coverage ${cov:-?} edges (${ft:-?} features)"
  if [ $rc -ne 0 ] || [ -n "$found" ]; then
    status=1
    line="$line, FINDING: $(grep -m1 -E 'ERROR: (libFuzzer|AddressSanitizer)|runtime error|deadly signal|uncaught' "$log" || echo "exit $rc") reproducer: ${found:-see $log}"
  fi
  summary+=("$line")
done
echo
printf 'fuzz summary (%ss per target)\n' "$seconds"
printf '  %s\n' "${summary[@]}"
exit $status
