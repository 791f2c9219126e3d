#!/usr/bin/env bash
# Every test: install what is missing, build and run the whole CTest suite in the release preset,
# then again under AddressSanitizer + UndefinedBehaviorSanitizer (asan preset).
# RODVV_TEST_PRESETS="release" limits the presets (e.g. for a quick local loop).
set -euo pipefail
cd "$(dirname "$0")/.."
# The browser stack for the report's browser test (tests/reports/test_report_browser.py), which
# must then run, not skip.
scripts/setup.sh chromium chromium-driver python3-selenium
export RODVV_REQUIRE_BROWSER=1
jobs=$(nproc)
for preset in ${RODVV_TEST_PRESETS:-release asan}; do
  echo "=== preset $preset ===" >&2
  cmake --preset "$preset" >/dev/null
  cmake --build --preset "$preset" -j "$jobs"
  ctest --preset "$preset" -j "$jobs"
done
