#!/usr/bin/env bash
# Runs a HAL file of examples/hal in its own namespaces, never on a host HAL:
# private mount, IPC (HAL's shared memory), PID and network namespaces and a
# private /dev/shm; ends by itself (the HAL file waits for nck-hal, and a
# time limit stops it otherwise).
#   scripts/hal-demo.sh [HAL_FILE] [PROGRAM] [MACHINE]
# Needs root (unshare) like the rest of scripts/test.sh; RTAPI_UID is set
# so rtapi_app drops to that user where it can.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
hal_file="$(realpath "${1:-$root/examples/hal/mill-stepgen.hal}")"
program="$(realpath "${2:-$root/examples/mill/contour.nc}")"
machine="$(realpath "${3:-$root/examples/mill}")"
build="${NCK_BUILD_DIR:-$root/build/default}"
limit="${NCK_HAL_TIMEOUT:-120}"
if [ ! -x "$build/hal/nck-hal" ] || [ ! -f "$build/hal/nck.so" ]; then
  echo "hal-demo: $build/hal/nck.so or nck-hal is missing (configure with linuxcnc-uspace-dev installed: NCK_HAL=ON)" >&2
  exit 77
fi
export NCK_MACHINE="$machine" NCK_PROGRAM="$program" NCK_MODULE=nck NCK_HAL_BIN="$build/hal"
# rtapi_app refuses uid 0 here: as root, it falls back to nobody.
uid="$(id -u)"; [ "$uid" -eq 0 ] && uid=65534
export RTAPI_UID="${RTAPI_UID:-$uid}"
# rtapi_app's socket, in the private /dev/shm (it binds as RTAPI_UID).
export RTAPI_FIFO_PATH=/dev/shm/rtapi_fifo
# NCK_HAL_SHARE_NET=1 keeps the host's network (a browser reaches nck-hal
# --serve, examples/hal/mill-hmi.hal); the tests leave it unset.
net=--net
[ "${NCK_HAL_SHARE_NET:-0}" = 1 ] && net=
exec timeout --kill-after=5 "$limit" unshare --mount --ipc --pid $net --fork --mount-proc \
  bash -c 'set -e
    mount -t tmpfs -o size=256m,mode=1777 tmpfs /dev/shm
    # loopback up in this network namespace: nck-hal --serve listens there, unreachable from outside
    if [ -n "$2" ]; then ip link set lo up; fi
    # rtapi_app loads modules by name from its own folder only: nck.so joins
    # it in this mount namespace (an overlay; the host folder is untouched).
    mods=/usr/lib/linuxcnc/modules
    mount -t overlay overlay -o "lowerdir=$mods:$1" "$mods"
    halrun -f "$0"' "$hal_file" "$build/hal" "$net"
