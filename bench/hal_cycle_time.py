#!/usr/bin/python3
"""What nck.cycle costs beside Kernel::tick() (issue 46): runs
examples/hal/mill-stepgen.hal (contour.nc through stepgen) in its own
namespaces through scripts/hal-demo.sh, samples every servo cycle's
nck.cycle.time (HAL's time of the function, CPU clocks), nck.tick-time (the
tick's own clocks, the same clock) and nck.clocks-per-us with the `sampler`
component, and prints the component's own share, time - tick, in
microseconds: median, 99th percentile and maximum, over RUNS runs.

  bench/hal_cycle_time.py SOURCE BUILD [--runs 2] [--serve]

--serve starts nck-hal with its API (nck.cycle then also publishes its
state every cycle, docs/hal.md "The HMI") and unloads it after the samples.

Needs root (unshare) and the HAL components (NCK_HAL). The maximum on a
host without PREEMPT_RT says more about the host than about nck.
"""
import argparse, os, re, statistics, subprocess, sys, tempfile

SAMPLES = 29000  # contour.nc runs 29.62 s: one sample per 1 ms servo cycle

ap = argparse.ArgumentParser()
ap.add_argument("source")
ap.add_argument("build")
ap.add_argument("--runs", type=int, default=2)
ap.add_argument("--serve", action="store_true")
a = ap.parse_args()
example = open(os.path.join(a.source, "examples", "hal", "mill-stepgen.hal")).read()
if a.serve:
    example = example.replace("nck-hal $(NCK_MACHINE)", "nck-hal --serve --port 8765 $(NCK_MACHINE)")
head = example[:example.index("\nstart\n")]
tail = f"""
loadrt sampler depth=16384 cfg=ssf
addf sampler.0 servo-thread
net cycle-time nck.cycle.time => sampler.0.pin.0
net tick-time nck.tick-time => sampler.0.pin.1
net clock-rate nck.clocks-per-us => sampler.0.pin.2
start
loadusr -w halsampler -n {SAMPLES}
{"unloadusr" if a.serve else "waitusr"} nck-hal
stop
"""
own_us, tick_us = [], []
for run in range(a.runs):
    with tempfile.NamedTemporaryFile("w", suffix=".hal", delete=False) as f:
        f.write(head + tail)
    env = dict(os.environ, NCK_BUILD_DIR=a.build, NCK_HAL_TIMEOUT="90")
    p = subprocess.run([os.path.join(a.source, "scripts", "hal-demo.sh"), f.name], capture_output=True, text=True,
                       env=env, timeout=120)
    os.unlink(f.name)
    rows = [tuple(map(float, m.groups())) for m in
            re.finditer(r"^(-?\d+) (-?\d+) (-?[\d.]+(?:e[-+]?\d+)?)\s*$", p.stdout, re.M)]
    if p.returncode != 0 or len(rows) < SAMPLES // 2:
        print(p.stdout[-2000:], p.stderr[-2000:])
        sys.exit(f"run {run + 1}: exit {p.returncode}, {len(rows)} samples")
    for cycle, tick, rate in rows:
        if rate > 0 and cycle > 0:  # the first cycle has no rate yet
            own_us.append((cycle - tick) / rate)
            tick_us.append(tick / rate)


def pct(v, q):
    v = sorted(v)
    return v[min(len(v) - 1, int(q * len(v)))]


print(f"{len(own_us)} cycles of contour.nc in {a.runs} run(s), {statistics.median(r[2] for r in rows if r[2] > 0):.1f} clocks/us")
print(f"nck.cycle.time - nck.tick-time: median {statistics.median(own_us):.2f} us, p99 {pct(own_us, 0.99):.2f} us, "
      f"max {max(own_us):.2f} us")
print(f"nck.tick-time:                  median {statistics.median(tick_us):.2f} us, p99 {pct(tick_us, 0.99):.2f} us, "
      f"max {max(tick_us):.2f} us")
