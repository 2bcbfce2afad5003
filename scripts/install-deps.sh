#!/usr/bin/env bash
# Installs the Debian 12 packages nck needs to build and test. Idempotent;
# run as root (or with sudo available).
set -euo pipefail
pkgs=(build-essential g++ cmake ninja-build pkg-config
      libfmt-dev libcli11-dev nlohmann-json3-dev
      libgtest-dev libgmock-dev googletest libbenchmark-dev
      clang-14 libclang-rt-14-dev)  # clang 14 + libFuzzer: the fuzz preset
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
