#!/usr/bin/env bash
# Installs the Debian 12 packages rodvv needs, only those that are missing (idempotent).
# Needs root (or sudo) only when something is missing. Nothing is downloaded at build time.
# Extra package names as arguments are installed too (scripts/fuzz.sh: clang and its runtimes).
set -euo pipefail

packages=(
  cmake ninja-build g++ git pkg-config
  libeigen3-dev libgsl-dev libboost-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libcli11-dev nlohmann-json3-dev libfmt-dev
  python3 python3-matplotlib python3-numpy python3-mpmath
  "$@"
)

missing=()
for package in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$package" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$package")
done

if ((${#missing[@]} == 0)); then
  echo "setup: all ${#packages[@]} packages present" >&2
  exit 0
fi

echo "setup: installing ${missing[*]}" >&2
if [[ $(id -u) -eq 0 ]]; then
  as_root=()
elif command -v sudo >/dev/null 2>&1; then
  as_root=(sudo)
else
  echo "setup: missing packages (${missing[*]}) and not root; rerun as root or install them" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get update -q
"${as_root[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
