#!/usr/bin/env bash
# The main job: install what is missing, build (release preset) and write the full validation
# report to rodvv-report/ (index.html, report.md, results.json, results.csv, junit.xml).
# Extra arguments go to `rodvv report`, e.g. scripts/report.sh --extended --out /tmp/report
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake --preset release >/dev/null
cmake --build --preset release --target rodvv -j "$(nproc)"
exec build/release/apps/rodvv report "$@"
