// The programs the browser test runs and what their reports must show,
// worked out by hand from the NC text (extents in machine coordinates, mm).
import fs from "node:fs";

// The common-subset benchmark program (the rule of ../shared/bench/
// common_program.py, also used by bench/path_bench): G1/G2 moves around a
// circle of radius 50, 0.01 rad per block.
export function writeCommonProgram(file, n) {
  const lines = ["G90 G17 G54", "M3 S1000", "G0 X0 Y0 Z5", "G1 Z-1 F300"];
  let cx = 0, cy = 0;
  for (let i = 0; i < n; i++) {
    const x = 50 * Math.cos(i * 0.01), y = 50 * Math.sin(i * 0.01);
    const xs = x.toFixed(3), ys = y.toFixed(3);
    if (i % 4 === 3) {
      const mx = (cx + +xs) / 2, my = (cy + +ys) / 2;
      lines.push(`G2 X${xs} Y${ys} I${(mx - cx).toFixed(4)} J${(my - cy).toFixed(4)} F1200`);
    } else {
      lines.push(`G1 X${xs} Y${ys} F1500`);
    }
    cx = +xs; cy = +ys;
  }
  lines.push("M5", "M2");
  fs.writeFileSync(file, lines.join("\n") + "\n");
}

// Caps for the long program's report (docs/performance.md states them):
// the file stays bounded whatever the run length, and the page is usable
// within a few seconds even on a loaded 2-core CI machine.
export function caps(blocks) {
  return { bytes: 6e6, loadMs: blocks >= 100000 ? 8000 : 5000 };
}

export function expectations(longProgram, blocks, longCaps) {
  const sin60 = 30 * Math.sin(Math.PI / 3);  // bolt circle: holes at 60 deg steps, radius 30
  return [
    {
      name: "contour", image: "report-contour.png", machine: "examples/mill", programs: ["examples/mill/contour.nc"],
      minPlots: 2,
      // pocket +-40 x +-25; helix r 15; holes r 30 (Y +-25.98); Z from -3 (holes, helix) to 2 + 20 (G91 retract)
      backplots: [{ view: "XY", min: [-40, -sin60, -3], max: [40, sin60, 22], tol: 0.02 }],
    },
    {
      name: "spindle", image: "report-spindle.png", machine: "examples/mill", programs: ["examples/mill/spindle.nc"],
      plc: "examples/mill/spindle.plc", minPlots: 4,
      backplots: [{ view: "XY", min: [0, 0, 0], max: [50, 30, 20], tol: 0.01 }],
      wait: { panel: "channel 1: path velocity", reason: "speed_reached", text: /^N\d+ waits \d+\.\d{3} s for S1 speed reached/ },
    },
    {
      name: "lathe", image: "report-lathe.png", machine: "examples/lathe", programs: ["examples/lathe/turn.nc"],
      minPlots: 2,
      // face to X0, profile to Z-45, retract to X30 Z2 (radius values)
      backplots: [{ view: "ZX", min: [0, null, -45], max: [30, null, 2], tol: 0.01 }],
    },
    {
      name: "two-channel", image: "report-two-channel.png", machine: "examples/two-channel",
      programs: ["examples/two-channel/channel1.nc", "examples/two-channel/channel2.nc"], minPlots: 4,
      backplots: [
        { view: "XY", min: [0, 0, 0], max: [20, 20, 5], tol: 0.01 },
        { view: "ZX", min: [-30, null, -10], max: [0, null, 5], tol: 0.01 },
      ],
    },
    {
      name: `common-${blocks}`, machine: "examples/mill", programs: [longProgram], minPlots: 3, caps: longCaps,
      // the circle of radius 50 (complete after 629 blocks), Z from -1 to 5, under G54 of the mill
      // (zero.lis: X +100, Y +50, Z -150): X 50..150, Y 0..100, Z -151..-145 in machine
      // coordinates, and the start at the machine zero
      backplots: [{ view: "XY", min: [0, 0, -151], max: [150, 100, 0], tol: 0.02 }],
    },
  ];
}
