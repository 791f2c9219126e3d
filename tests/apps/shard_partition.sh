#!/usr/bin/env bash
# `rodvv run --shard I/K`: the K slices partition the selection. Three shards of the pendulum
# family, run apart, hold each of its cases exactly once, and `report --from` merges them.
# Usage: shard_partition.sh RODVV WORKDIR
set -euo pipefail
rodvv=$1 work=$2
rm -rf "$work"; mkdir -p "$work/parts"
for i in 1 2 3; do "$rodvv" run pendulum --shard "$i/3" --json "$work/parts/$i.json" > /dev/null 2>&1; done
"$rodvv" list pendulum 2> /dev/null | awk '{print $1}' | sort > "$work/all.txt"
cat "$work"/parts/*.json | grep -o '"name": "pendulum/[^"]*"' | sed 's/"name": "\(.*\)"/\1/' | sort > "$work/ran.txt"
if ! diff "$work/all.txt" "$work/ran.txt"; then
  echo "FAIL: the shards do not hold each case exactly once" >&2
  exit 1
fi
"$rodvv" report --from "$work/parts" --out "$work/merged" --no-plots > /dev/null 2>&1
grep -q "pendulum/separatrix/dopri5" "$work/merged/results.csv"
echo "ok: $(wc -l < "$work/all.txt") cases in 3 shards"
