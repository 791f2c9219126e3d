#!/usr/bin/env bash
# Which solver code `rodvv run` never executes (issue 13, class 5): builds rodvv with gcov instrumentation
# (preset `coverage`, -O1, atomic counters: `rodvv run` runs cases on 2 threads, and plain counters raced into
# negative branch counts that gcovr cannot parse), runs every case at its default levels (or --extended), and writes with gcovr
# (Debian's, installed by setup.sh if missing):
#   build/coverage/report/summary.txt   line coverage per file of solvers/, references/, invariants/
#   build/coverage/report/uncalled.txt  the functions of solvers/ that no case calls (demangled, by file)
#   build/coverage/report/index.html    the annotated sources
# About 15 minutes on 2 cores for the build and 5 for the run. A case that fails still counts its coverage;
# the run's exit code is printed, not the script's.
#   scripts/coverage.sh [--extended]
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh gcovr
cmake --preset coverage >/dev/null
cmake --build build/coverage --target rodvv -j "$(nproc)"
find build/coverage -name '*.gcda' -delete
set +e
build/coverage/apps/rodvv run "$@" > build/coverage/run.log 2>&1
status=$?
set -e
echo "coverage: rodvv run $* exited with $status ($(tail -n 1 build/coverage/run.log))" >&2
mkdir -p build/coverage/report
gcovr --root . --object-directory build/coverage --filter 'solvers/' --filter 'references/' --filter 'invariants/' \
  --exclude-unreachable-branches --txt build/coverage/report/summary.txt --json build/coverage/report/coverage.json \
  --html-details build/coverage/report/index.html
python3 scripts/uncalled_functions.py build/coverage/report/coverage.json solvers/ > build/coverage/report/uncalled.txt
tail -n 4 build/coverage/report/summary.txt >&2
echo "coverage: $(grep -c '^    ' build/coverage/report/uncalled.txt || true) solver functions never called;" \
  "build/coverage/report/uncalled.txt" >&2
