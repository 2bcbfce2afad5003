// The programs the browser test runs and what their reports must show,
// worked out by hand from the NC text (extents in machine coordinates, mm).
import fs from "node:fs";
import path from "node:path";

// The common-subset benchmark program (the rule of bench/
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

// A rectangle under G54 and a 90 deg rotation (program coordinates differ
// from machine coordinates by more than a shift), and a feedhold program.
export function writeFrameProgram(file) {
  fs.writeFileSync(file, [
    "N10 G17 G90 G54 G0 X0 Y0 Z5", "N20 #ROTATION ON [ANGLE=90]", "N30 G1 X40 Y0 F3000", "N40 Y20", "N50 X0",
    "N60 Y0", "N70 #ROTATION OFF", "N80 G0 Z20", "N90 M30"].join("\n") + "\n");
}
export function writeHoldProgram(dir) {
  fs.writeFileSync(path.join(dir, "hold.nc"), "N10 G17 G90 G0 X0 Y0 Z0\nN20 G1 X100 F3000\nN30 M30\n");
  // feedhold for 0.8 s from 0.5 s; the feed override drops to 50 % at 1.5 s
  fs.writeFileSync(path.join(dir, "hold.plc"), "0.5 feedhold on\n1.3 feedhold off\n1.5 feed_override 50\n");
  // S1 and S2 waited for at once: speed reached at 0.326 s and 0.54 s
  fs.writeFileSync(path.join(dir, "two_waits.nc"), "N10 S1000 M3 S2[M4 REV3000]\nN20 G4 X0.1\nN30 M30\n");
}

export function expectations(longProgram, blocks, longCaps, out) {
  const sin60 = 30 * Math.sin(Math.PI / 3);  // bolt circle: holes at 60 deg steps, radius 30
  // the 3D view's soft-limit box: the mill's kenngr.swe_neg/swe_pos (x.lis, y.lis, z.lis), mm
  const mill3d = { limits: { min: [-500, -400, -400], max: [500, 400, 200] } };
  return [
    {
      name: "contour", image: "report-contour.png", machine: "examples/mill", programs: ["examples/mill/contour.nc"], play: true,
      minPlots: 2, minCauses: 4,
      // pocket +-40 x +-25; helix r 15; holes r 30 (Y +-25.98); Z from -3 (holes, helix) to 2 + 20 (G91 retract)
      backplots: [{ view: "XY", min: [-40, -sin60, -3], max: [40, sin60, 22], tol: 0.02, view3d: mill3d }],
      // issue 48 item 1: N140 runs from 10.805 to 12.505 s (the cursor named N150 there); hovering the
      // middle of N100 (line 23) named N110
      cursor: { at: [{ t: 11.848, block: "N140" }], hover: [23] }, iso: true,
    },
    {
      // issue 48 item 1: N70 runs from 12.717 to 17.997 s (the cursor named N80 there)
      name: "lathe-diameter", machine: "examples/lathe", programs: ["examples/lathe/diameter.nc"], minPlots: 2,
      // X words are diameters: the face at D60 (X30 radius) to the centre, the profile to Z-45 and D50 (X25)
      backplots: [{ view: "ZX", min: [0, null, -45], max: [30, null, 2], tol: 0.01 }],
      // x.lis is face-turning and the lathe's display_diameter_pos is 1: under G51 X reads as ⌀X (N70
      // at D20); after N110's G52 as a radius again (N120 X30, the end at N130)
      cursor: { at: [{ t: 16.07, block: "N70", pcs: { "\u2300X": 20 } }, { t: 1e9, block: "N130", pcs: { X: 30, Z: 2 } }], hover: [11] },
    },
    {
      // #SLOPE STEP, TRAPEZ, SIN2: the square (X 0..60, Y -10..30) and the G2 bulging to X80; Z0 to Z10
      name: "slope", machine: "examples/mill", programs: ["examples/mill/slope.nc"], minPlots: 3,
      backplots: [{ view: "XY", min: [0, -10, 0], max: [80, 30, 10], tol: 0.01, view3d: true }],
      accel: { panel: "channel 1: path acceleration and jerk" },
    },
    {
      name: "spindle", image: "report-spindle.png", machine: "examples/mill", programs: ["examples/mill/spindle.nc"],
      plc: "examples/mill/spindle.plc", minPlots: 4,
      backplots: [{ view: "XY", min: [0, 0, 0], max: [50, 30, 20], tol: 0.01, view3d: true }],
      wait: { panel: "channel 1: path velocity", reason: "speed_reached", text: /^N\d+ waits \d+\.\d{3} s for S1 speed reached/ },
      // spindle.plc: the HLI override of S1 is 50 % from the start
      marks: [{ panel: "spindle S1: speed", kind: "override", t: 0, text: /^0\.000 s: S1 spindle override 50 %$/ }],
    },
    {
      name: "contour-trc", image: "report-contour-trc.png", machine: "examples/mill", programs: ["examples/mill/contour_trc.nc"],
      minPlots: 2,
      // the tool centre 5 mm (D1) outside the 60 x 40 rectangle: X -5..65, Y -5..45; the start -20/-20;
      // Z from the machine zero to Z10 + the tool length 100 (machine coordinates of the spindle nose)
      backplots: [{ view: "XY", min: [-20, -20, 0], max: [65, 45, 110], tol: 0.02, view3d: true }],
      // three compensated stretches, each programmed line 5 mm from the tool centre
      contour: { runs: 3, radius: 5, tol: 0.05 },
    },
    {
      name: "lathe-trc", machine: "examples/lathe", programs: ["examples/lathe/profile_trc.nc"], minPlots: 2,
      // the tip of D4 (radius 0.8, cutting-edge position 2) from the machine zero to X30 (D60), radius
      // values; at the end of N90 Z-40 the nose centre stands over Z-40, its tip 0.8 mm further
      backplots: [{ view: "ZX", min: [0, null, -40.8], max: [30, null, 5], tol: 0.01 }],
      // tool 4 has cutting-edge position 2: its tip is 0.8 mm below the nose centre in X and Z
      contour: { runs: 1, radius: 0.8, tol: 0.01, axes: [0, 2], tip: [-0.8, -0.8] },
    },
    {
      name: "frames", machine: "examples/mill", programs: [path.join(out, "frames.nc")], minPlots: 1,
      // machine coordinates: G54 (X100 Y50 Z-150) and the rectangle 40 x 20 turned 90 deg about the
      // program zero: X 80..100, Y 50..90; from the machine zero to Z20 (-130)
      backplots: [{ view: "XY", min: [0, 0, -145], max: [100, 90, 0], tol: 0.01, view3d: true }],
      // program coordinates: the rectangle as programmed, X 0..40 Y 0..20 Z 5..20, and the start (the
      // machine zero) in the first block's system: -100 / -50 / 150
      pcs: [{ min: [-100, -50, 5], max: [40, 20, 150], tol: 0.01 }],
    },
    {
      name: "feedhold", machine: "examples/mill", programs: [path.join(out, "hold.nc")], plc: path.join(out, "hold.plc"),
      minPlots: 1,
      backplots: [{ view: "XY", min: [0, 0, 0], max: [100, 0, 0], tol: 0.01, view3d: true }],
      wait: { panel: "channel 1: path velocity", reason: "feedhold", span: [0.5, 1.3],
              text: /^N20 held 0\.800 s by the PLC's feedhold \(HLI\)$/ },
      timeline: { rows: ["channel 1"], bars: [{ party: "operator", t0: 0.5, t1: 1.3, text: /^channel 1 \(N20\) waits 0\.800 s for feed hold/ }] },
      marks: [{ panel: "channel 1: path velocity", kind: "override", t: 1.5, text: /^1\.500 s: feed override 50 %$/ }],
    },
    {
      // overlapping waits count once in the summary (0.540 s, not 0.856 s)
      name: "two-waits", machine: "examples/mill", programs: [path.join(out, "two_waits.nc")],
      minPlots: 1,
      backplots: [{ view: "XY", min: [null, null, null], max: [null, null, null], tol: 0.01, view3d: true }],
      summary: /waitsthe PLC's acknowledgement 0\.010 s, speed reached 0\.540 s/,
    },
    {
      // issue 31 item 5: the channel's axes are X, Y1, Z1 (no Y or Z): the backplot takes its first three
      // linear axes (N40 Y1 0 -> 50, N90 Z1 0 -> -10). Its waits, each pair of spindles at once (events):
      // M3 S1/S2 0.163..0.506 s, M19 1.525..2.273 s, M4 S1/S3 2.879..3.577 s, M5 3.577..4.586 s; counted
      // once per channel and reason: speed reached 0.343 + 0.698 s, in position 0.748 s, standstill 1.009 s
      name: "twin-spindle", machine: "examples/twin-spindle", programs: ["examples/twin-spindle/twin.nc"], minPlots: 3,
      backplots: [{ view: "XY", min: [0, 0, -10], max: [0, 50, 0], tol: 0.01, minPoints: 3,
                    view3d: { limits: { min: [-500, -500, -500], max: [500, 500, 500] } } }],
      summary: /waitsspeed reached 1\.041 s, in position 0\.748 s, standstill 1\.009 swritten bynck [0-9.]+$/,
      links: /Y2 ← Y1, S2 ← S1/,
      // issue 48 item 12: the M19 wait of N50 for S1 in position (S2 reaches 90 deg at the same time)
      timeline: { rows: ["channel 1"], bars: [{ party: "spindle", t0: 1.525, t1: 2.273, text: /^channel 1 \(N50\) waits 0\.748 s for S\d in position \(M19\)/ }] },
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
        { view: "XY", min: [0, 0, 0], max: [20, 20, 5], tol: 0.01, view3d: true },
        { view: "ZX", min: [-30, null, -10], max: [0, null, 5], tol: 0.01 },
      ],
    },
    {
      name: `common-${blocks}`, machine: "examples/mill", programs: [longProgram], minPlots: 3, caps: longCaps,
      // the circle of radius 50 (complete after 629 blocks), Z from -1 to 5, under G54 of the mill
      // (zero.lis: X +100, Y +50, Z -150): X 50..150, Y 0..100, Z -151..-145 in machine
      // coordinates, and the start at the machine zero
      backplots: [{ view: "XY", min: [0, 0, -151], max: [150, 100, 0], tol: 0.02, view3d: true }],
    },
  ];
}
