#!/usr/bin/env bash
# The main job's cost: `rodvv report` (every case at its default levels, then the plots), timed wall
# and CPU, serially (-j 1) and on every core (the default), and its two halves apart: the cases
# (`rodvv run`) and the plots (`rodvv report --from` on those results). Prints one line per run.
# usage: bench/time_main_job.sh [path/to/rodvv]   (default build/release/apps/rodvv)
# The machine is shared and noisy: compare the ratios of one invocation, not absolute seconds.
set -euo pipefail
cd "$(dirname "$0")/.."
rodvv=${1:-build/release/apps/rodvv}
[[ -x "$rodvv" ]] || { echo "time_main_job: no executable '$rodvv' (build the release preset)" >&2; exit 2; }
[[ -x /usr/bin/time ]] || { echo "time_main_job: needs /usr/bin/time (Debian package 'time')" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

timed() {  # label, command...
  local label=$1
  shift
  /usr/bin/time -f "%e %U %S" -o "$work/time" "$@" >"$work/out" 2>&1 || true
  read -r wall user sys <"$work/time"
  printf '%-34s %7.1f s wall %7.1f s CPU\n' "$label" "$wall" "$(awk -v u="$user" -v s="$sys" 'BEGIN { print u + s }')"
}

echo "cores: $(nproc); rodvv: $rodvv"
timed "cases, -j 1 (rodvv run)" "$rodvv" run -j 1 --json "$work/serial.json"
mkdir -p "$work/results"
timed "cases, -j $(nproc) (rodvv run)" "$rodvv" run --json "$work/results/results.json"
timed "plots and pages (report --from)" "$rodvv" report --from "$work/results" --out "$work/from"
timed "main job, -j 1 (rodvv report)" "$rodvv" report -j 1 --out "$work/report1"
timed "main job (rodvv report)" "$rodvv" report --out "$work/report"
