#!/usr/bin/env bash
# tools/gpu/measure.sh OUT_DIR [SECONDS] — docs/performance.md's GPU figures on a machine with a
# GPU, with the bench packed by tools/gpu/pack.sh: the gallery (soft_edge_cost_ratio,
# burn_blend_cost_ratio, particle_fill_efficiency and their GL_TIME_ELAPSED twins), combat_view
# (combat p50 / p99 from both cameras; the slowest frames saved as PNGs), particle_scale
# (particles within 4 ms at 1920x1080) and particle_prep (the CPU's share per particle). Then the
# gallery and combat_view again, while SECONDS (default 420) allow, for ranges over runs.
# Everything goes to OUT_DIR/bench.log as it is printed.
set -uo pipefail
if [ $# -lt 1 ] || [ $# -gt 2 ]; then
  echo "tools/gpu/measure.sh: usage: tools/gpu/measure.sh OUT_DIR [SECONDS]" >&2
  exit 2
fi
out="$1"
budget="${2:-420}"
[[ "$budget" =~ ^[0-9]+$ ]] || { echo "tools/gpu/measure.sh: SECONDS: '$budget' is not a whole number of seconds" >&2; exit 2; }
here="$(cd "$(dirname "$0")" && pwd)"
mkdir -p "$out"
log="$out/bench.log"
{
  date -u
  nvidia-smi -L 2>&1 || echo "no nvidia-smi"
  nproc
} >>"$log"
scene() {  # scene NAME LIMIT_S [ENV...]
  local name="$1" limit="$2"
  shift 2
  echo "=== $name (run at ${SECONDS}s)" >>"$log"
  env "$@" timeout "$limit" "$here/run.sh" --scene "$name" >>"$log" 2>&1
  echo "=== $name: exit $? after ${SECONDS}s" >>"$log"
}
scene render_particle_gallery 150
scene combat_view 200 ARCFIRE_GFX_DUMP="$out"
scene particle_scale 150
scene particle_prep 60
for run in 2 3; do
  [ "$SECONDS" -lt $((budget - 120)) ] || break
  scene render_particle_gallery 100
  [ "$SECONDS" -lt $((budget - 120)) ] || break
  scene combat_view 120
done
grep -E "^metric|^===|GL|NVIDIA" "$log" | head -80
