// Issue 48 item 1: the report's time cursor and hover name the block the
// tool is on. The player is scrubbed over every block of a run (its first,
// middle and last cycle, per the block events of the same run's --events)
// and the block it names, the highlighted program line and the DRO are
// compared with the events and the trace (--trace); then the middle of each
// block's path is hovered in the backplot, where no other block's path is
// as near on the screen.
import fs from "node:fs";
import path from "node:path";

// The block events of channel 1: [{t, line, file (base name)}], in order.
function blockEvents(eventsFile) {
  return fs.readFileSync(eventsFile, "utf8").split("\n").filter(Boolean).map((l) => JSON.parse(l))
    .filter((e) => e.ev === "block" && e.ch === 1).map((e) => ({ t: e.t, line: e.line, file: path.basename(e.file || "") }));
}

// The trace as {t: [...], cols: {X: [...], ...}} (every cycle).
function readTrace(traceFile) {
  const [head, ...rows] = fs.readFileSync(traceFile, "utf8").split("\n").filter(Boolean);
  const names = head.split(",");
  const cols = Object.fromEntries(names.map((n) => [n, new Float64Array(rows.length)]));
  rows.forEach((r, i) => r.split(",").forEach((v, k) => { cols[names[k]][i] = +v; }));
  return { t: cols.t, cols };
}

// Each block that lasts a cycle or more: its first, middle and last cycle
// (the trace's rows), and the block the events say runs then.
function samplesOf(events, trace, cycleS) {
  const rowAt = (t) => Math.round(t / cycleS);
  const samples = [];
  events.forEach((e, k) => {
    const next = k + 1 < events.length ? events[k + 1].t : trace.t[trace.t.length - 1] + cycleS;
    const first = rowAt(e.t), last = rowAt(next) - 1;
    if (last < first || first >= trace.t.length) return;
    const rows = { first, mid: Math.round((first + last) / 2), last: Math.min(last, trace.t.length - 1) };
    for (const [kind, row] of Object.entries(rows))
      samples.push({ kind, row, t: trace.t[row], line: e.line, file: e.file, block: k });
  });
  return samples;
}

export async function checkCursor(page, name, files, { fail, ok }) {
  const events = blockEvents(files.events), trace = readTrace(files.trace);
  const meta = await page.evaluate(() => {
    const D = window.nckReport.data, ch = D.channels[0];
    return { cycleS: D.meta.cycle_s, axes: ch.axes, has: ch.has, error: ch.path_error_mm, byBlock: ch.path_by_block };
  });
  if (!meta.byBlock) fail(name, "the path's segments span blocks (path_by_block false)");
  const samples = samplesOf(events, trace, meta.cycleS);
  const axes = [0, 1, 2].filter((a) => meta.has[a]);
  for (const a of axes) if (!trace.cols[meta.axes[a]]) return fail(name, `the trace has no column ${meta.axes[a]}`);
  // one evaluate for every sample: seek, then read what the page shows
  const shown = await page.evaluate((ts) => ts.map((t) => {
    const p = window.nckReport.player, ch = p.ch;
    p.seek(t);
    const now = document.querySelector("#program .now");
    return {
      block: document.querySelector("#dro .block-now").textContent,
      now: now ? +now.dataset.line : 0,
      file: String(window.nckReport.data.files[ch.file[p.at.i]] || "").split("/").pop(),
      pos: p.at.pos,
      dro: [...document.querySelectorAll("#dro .dro-axes tr")].slice(1).map((tr) => +tr.children[1].textContent),
    };
  }), samples.map((s) => s.t));
  let bad = 0, worst = 0;
  const say = (msg) => { if (++bad <= 8) fail(name, msg); };
  samples.forEach((s, k) => {
    const got = shown[k], where = `at ${s.t.toFixed(3)} s (block event ${s.block}: line ${s.line})`;
    if (!got.block.startsWith("line " + s.line + " ") && got.block !== "line " + s.line) say(`${where} the DRO names "${got.block}"`);
    if (got.now !== s.line) say(`${where} the program panel highlights line ${got.now}`);
    if (got.file !== s.file) say(`${where} the block's file is ${got.file}, the event's ${s.file}`);
    axes.forEach((a, r) => {
      const want = trace.cols[meta.axes[a]][s.row];
      worst = Math.max(worst, Math.abs(got.pos[a] - want));
      if (Math.abs(got.pos[a] - want) > meta.error + 1e-9) say(`${where} the cursor has ${meta.axes[a]} ${got.pos[a]}, the trace ${want}`);
      // the DRO's 3 decimals: the trace's value rounded, or its neighbour where the bound straddles a rounding
      if (Math.abs(got.dro[r] - want) > 0.0005 + meta.error + 1e-9) say(`${where} the DRO reads ${meta.axes[a]} ${got.dro[r]}, the trace ${want}`);
    });
  });
  if (!bad) ok(name, `cursor over ${samples.length} cycles of ${new Set(samples.map((s) => s.block)).size} blocks: block, line and DRO ` +
    `as the events and the trace (worst ${worst.toExponential(1)} mm, bound ${meta.error} mm)`);
  // at t = 0 the motion shown is the one the cause names (item 5: it said feed while the cause said rapid)
  const start = await page.evaluate(() => {
    window.nckReport.player.seek(0);
    const kv = [...document.querySelectorAll("#dro .kv > *")].map((e) => e.textContent);
    return { motion: kv[kv.indexOf("motion") + 1], cause: document.querySelector("#dro .cause-now").textContent };
  });
  if (/^rapid/.test(start.cause) !== /^G0/.test(start.motion)) fail(name, `at 0 s the DRO shows ${start.motion} and cause ${start.cause}`);
  else ok(name, `at 0 s: ${start.motion}, cause ${start.cause}`);
  for (const want of files.at || []) {  // the issue's own cases
    const got = await page.evaluate((t) => {
      window.nckReport.player.seek(t);
      const rows = [...document.querySelectorAll("#dro .dro-axes tr")].slice(1).map((tr) => [tr.children[0].textContent, +tr.children[2].textContent]);
      return { block: document.querySelector("#dro .block-now").textContent, pcs: Object.fromEntries(rows) };
    }, want.t);
    if (!got.block.includes(want.block)) fail(name, `at ${want.t} s the DRO names "${got.block}", expected ${want.block}`);
    else ok(name, `at ${want.t} s the DRO names "${got.block}"`);
    for (const [axis, value] of Object.entries(want.pcs || {}))  // issue 48 item 7: ⌀X under G51
      if (Math.abs(got.pcs[axis] - value) > 1e-3) fail(name, `at ${want.t} s the DRO's PCS ${JSON.stringify(got.pcs)}, expected ${axis} ${value}`);
      else ok(name, `at ${want.t} s the DRO reads PCS ${axis} ${got.pcs[axis]}`);
  }
  await checkHover(page, name, samples.filter((s) => s.kind === "mid"), files.hover || [], { fail, ok });
}

// Hover the tool's place at each block's middle cycle in the backplot (a real
// mouse move) and read the info line: it names that block, unless another
// block's path passes within 3 px there (a Z move seen from above, a
// subroutine's Z moves at each hole: a place that two blocks share); the
// lines of `must` have to be among those hovered.
async function checkHover(page, name, samples, must, { fail, ok }) {
  const targets = await page.evaluate((ss) => {
    const b = window.nckReport.backplots[0], ch = b.ch, p = window.nckReport.player;
    b.canvas.scrollIntoView({ block: "center" });
    const r = b.canvas.getBoundingClientRect();
    return ss.map((s) => {
      const at = p.toolAt(ch, s.t);
      const [u, v] = b.projectPoint(at.pos);
      const [x, y] = b.toScreen(u, v);
      // the nearest screen distance of another block's path
      let other = Infinity;
      for (let i = 1; i < b.n; i++) {
        if (ch.line[i] === s.line) continue;
        const [x0, y0] = b.toScreen(b.uv[2 * i - 2], b.uv[2 * i - 1]), [x1, y1] = b.toScreen(b.uv[2 * i], b.uv[2 * i + 1]);
        const dx = x1 - x0, dy = y1 - y0, dd = dx * dx + dy * dy;
        const f = dd > 0 ? Math.max(0, Math.min(1, ((x - x0) * dx + (y - y0) * dy) / dd)) : 0;
        other = Math.min(other, Math.hypot(x - x0 - f * dx, y - y0 - f * dy));
      }
      const inside = x > 2 && y > 2 && x < r.width - 2 && y < r.height - 2;
      return { x: r.left + x, y: r.top + y, line: s.line, t: s.t, clear: inside && other > 3 };
    });
  }, samples);
  let checked = 0, bad = 0;
  const hovered = new Set();
  for (const tg of targets.filter((t) => t.clear)) {
    await page.mouse.move(tg.x, tg.y);
    const text = await page.evaluate(() => window.nckReport.backplots[0].info.textContent);
    checked++;
    hovered.add(tg.line);
    if (!new RegExp(":" + tg.line + "\\s").test(text) && ++bad <= 5) fail(name, `hovering line ${tg.line}'s path at ${tg.t.toFixed(3)} s shows "${text}"`);
  }
  await page.mouse.move(0, 0);
  const missed = must.filter((l) => !hovered.has(l));
  if (missed.length) fail(name, `line(s) ${missed.join(", ")} could not be hovered alone`);
  if (checked < targets.length / 3) fail(name, `only ${checked} of ${targets.length} blocks' paths could be hovered alone`);
  else if (!bad) ok(name, `hovering the middle of ${checked} blocks' paths names each (${targets.length - checked} share their place with another block)`);
}
