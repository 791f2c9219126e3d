#!/usr/bin/env bash
# Coverage-guided fuzzing of every reader of user input (tests/fuzz): builds the libFuzzer targets
# with clang (the `fuzz` preset: ASan + UBSan + _GLIBCXX_ASSERTIONS) and runs each for SECONDS
# (default 600), starting from the kept corpus tests/fuzz/corpus/<target>/. New inputs go to
# build/fuzz/corpus/<target>/; with --update-corpus, those that add coverage are merged into the
# kept corpus (libFuzzer -merge=1), which CI replays in every preset. A crash stops the script with
# libFuzzer's reproducer (crash-<sha1>) in build/fuzz/artifacts/.
#   scripts/fuzz.sh [--update-corpus] [SECONDS] [TARGET ...]
set -euo pipefail
cd "$(dirname "$0")/.."
update=0
if [[ "${1:-}" == "--update-corpus" ]]; then update=1; shift; fi
seconds=${1:-600}
shift || true
targets=("$@")
((${#targets[@]})) || targets=(fuzz_solution_json fuzz_solution_csv fuzz_results_file fuzz_cli_values)
if ! [[ "$seconds" =~ ^[1-9][0-9]*$ ]]; then
  echo "fuzz: SECONDS must be a whole number of seconds >= 1, got '$seconds'" >&2
  exit 2
fi
scripts/setup.sh clang libclang-rt-14-dev
cmake --preset fuzz >/dev/null
cmake --build build/fuzz -j "$(nproc)" --target "${targets[@]}"
mkdir -p build/fuzz/artifacts
for target in "${targets[@]}"; do
  kept=tests/fuzz/corpus/$target
  work=build/fuzz/corpus/$target
  mkdir -p "$work"
  dictionary=()
  [[ -f tests/fuzz/$target.dict ]] && dictionary=(-dict="tests/fuzz/$target.dict")
  echo "=== $target: ${seconds} s ===" >&2
  # -rss_limit_mb: a reader must not need more than 2 GB for any input; -timeout: nor 10 s.
  build/fuzz/tests/fuzz/"$target" "${dictionary[@]}" -max_total_time="$seconds" -timeout=10 \
      -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix=build/fuzz/artifacts/ "$work" "$kept"
  if ((update)); then
    build/fuzz/tests/fuzz/"$target" -merge=1 "$kept" "$work"
  fi
done
