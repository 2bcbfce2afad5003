#!/usr/bin/env bash
# Installs the Debian 12 packages nck needs to build and test. Idempotent;
# run as root (or with sudo available).
set -euo pipefail
pkgs=(build-essential g++ cmake ninja-build pkg-config
      libfmt-dev libcli11-dev nlohmann-json3-dev
      libgtest-dev libgmock-dev googletest libbenchmark-dev
      clang-14 libclang-rt-14-dev   # clang 14 + libFuzzer: the fuzz preset
      libboost1.74-dev              # Boost.Beast + Asio: nck serve
      nodejs chromium               # the report's uPlot and three.js (inlined at build time) and its browser test
      pybind11-dev python3-dev python3-numpy   # the Python module (python/, docs/python.md)
      python3-pytest python3-distributed       # its tests; nck.batch on Dask
      python3-pandas                           # nck.batch(as_frame=True) (optional for users)
      python3-matplotlib                       # examples/python/accel_sweep.py plots (CSV without it)
      python3-setuptools python3-wheel python3-build python3-venv python3-pip  # the wheel (python/pyproject.toml)
      python3-jsonschema                       # docs/openapi.json checked against the API tests
      linuxcnc-uspace linuxcnc-uspace-dev      # the HAL components nck.so / nck-hal (docs/hal.md)
      iproute2)                                # scripts/hal-demo.sh: loopback up in its network namespace
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
if ((${#missing[@]})); then
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# uPlot, three, esbuild and playwright-core at the versions package-lock.json locks; the build
# inlines uPlot and bundles three.js (esbuild) into the report, tests/browser drives /usr/bin/chromium.
cd "$(dirname "$0")/.."
# Debian's nodejs comes without npm (a NodeSource nodejs brings its own).
if ! command -v npm >/dev/null; then
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends npm
fi
npm ci --no-audit --no-fund
