#!/usr/bin/env bash
# Installs the Debian 12 packages nck needs to build and test. Idempotent;
# run as root (or with sudo available).
set -euo pipefail
pkgs=(build-essential g++ cmake ninja-build pkg-config
      libfmt-dev libcli11-dev nlohmann-json3-dev
      libgtest-dev libgmock-dev googletest libbenchmark-dev
      clang-14 libclang-rt-14-dev   # clang 14 + libFuzzer: the fuzz preset
      nodejs chromium)              # the report's uPlot (inlined at build time) and its browser test
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# uPlot and playwright-core at the versions package-lock.json locks; the build
# inlines uPlot into the report, tests/browser drives /usr/bin/chromium.
cd "$(dirname "$0")/.."
command -v npm >/dev/null || { echo "install-deps: npm is missing (Debian: apt-get install npm)" >&2; exit 1; }
npm ci --no-audit --no-fund
