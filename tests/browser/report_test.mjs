// Browser test of `nck run --report`: runs nck on example programs, opens
// each report offline in Debian's chromium (playwright-core) and checks
// what a user sees. Usage:
//   node tests/browser/report_test.mjs --nck BIN --source DIR --out DIR
//        [--blocks N] [--images DIR] [--only NAME,...]
// --blocks: size of the generated long program (default 200000, the
// issue's benchmark); --images: also save the README screenshots there;
// --only: run only the cases of these names (while working on one).
import { chromium } from "playwright-core";
import { execFileSync } from "node:child_process";
import fs from "node:fs";
import path from "node:path";
import { caps, expectations, writeCommonProgram, writeFrameProgram, writeHoldProgram } from "./report_cases.mjs";
import { check3d, checkAccel } from "./report_view3d.mjs";
import { checkCursor } from "./report_cursor.mjs";

const args = Object.fromEntries(process.argv.slice(2).reduce((acc, a, i, all) => {
  if (a.startsWith("--")) acc.push([a.slice(2), all[i + 1] && !all[i + 1].startsWith("--") ? all[i + 1] : "1"]);
  return acc;
}, []));
const nck = args.nck, src = path.resolve(args.source || "."), out = path.resolve(args.out || "report-test-out");
const blocks = Number(args.blocks || 200000);
const chromiumPath = process.env.NCK_CHROMIUM || "/usr/bin/chromium";
fs.mkdirSync(out, { recursive: true });
let failures = 0;
const fail = (name, msg) => { failures++; console.error(`FAIL ${name}: ${msg}`); };
const ok = (name, msg) => console.log(`ok   ${name}: ${msg}`);

// withOutputs: the run's --events and --trace beside the report (the cursor's checks)
function runNck(name, machine, programs, plc, withOutputs) {
  const report = path.join(out, name + ".html");
  const outputs = { events: path.join(out, name + ".events.jsonl"), trace: path.join(out, name + ".trace.csv") };
  // run in the source folder with relative names, as a user would (the report shows them)
  const argv = ["run", machine, ...programs, "--report", report, "--no-progress"];
  if (plc) argv.push("--plc", plc);
  if (withOutputs) argv.push("--events", outputs.events, "--trace", outputs.trace);
  const t = Date.now();
  try {
    execFileSync(path.resolve(nck), argv, { cwd: src, stdio: ["ignore", "ignore", "pipe"] });
  } catch (e) {
    if (e.status !== 0 && e.status !== 1) throw new Error(`nck ${argv.join(" ")} exited ${e.status}: ${e.stderr}`);
  }
  return { report, runMs: Date.now() - t, outputs };
}

// The time cursor: play moves the tool marker and the highlighted line;
// clicking a program line and a point of the path moves the cursor there.
async function checkPlayer(page, name) {
  const state = () => page.evaluate(() => {
    const p = window.nckReport.player, now = document.querySelector("#program .now");
    return { t: p.t, marker: window.nckReport.backplots[0].marker, line: now ? +now.dataset.line : 0,
             cause: document.querySelector("#dro .cause-now")?.textContent, dro: document.querySelectorAll("#dro .dro-axes tr").length };
  });
  const before = await state();
  await page.selectOption("#speed", "10");
  await page.click("#play");
  await page.waitForTimeout(600);
  await page.click("#play");  // pause
  const played = await state();
  if (!(played.t > before.t + 1)) fail(name, `play did not move the cursor: ${before.t} -> ${played.t}`);
  else if (JSON.stringify(played.marker) === JSON.stringify(before.marker)) fail(name, "the tool marker did not move");
  else if (!played.line || played.dro < 3 || !played.cause || played.cause === "-") fail(name, `after play: ${JSON.stringify(played)}`);
  else ok(name, `played to ${played.t.toFixed(3)} s: line ${played.line}, cause ${played.cause}, tool at ${played.marker.map((v) => v.toFixed(3))}`);
  // click another program line: the cursor goes to where that line's motion begins
  const target = await page.evaluate((cur) => {
    const rows = [...document.querySelectorAll("#program div[data-line]")].filter((r) => !r.classList.contains("now"));
    const ch = window.nckReport.data.channels[0];
    const r = rows.find((r) => ch.line.includes(+r.dataset.line) && +r.dataset.line !== cur);
    return r ? +r.dataset.line : 0;
  }, played.line);
  if (!target) fail(name, "no other program line with a motion to click");
  else {
    await page.click(`#program div[data-line="${target}"]`);
    const clicked = await state();
    if (clicked.line !== target) fail(name, `clicked line ${target}, the panel shows ${clicked.line}`);
    else ok(name, `a click on line ${target} moved the cursor to ${clicked.t.toFixed(3)} s`);
  }
  // click the middle of a path segment (not a stored point): the cursor goes there
  const seg = await page.evaluate(() => {
    const b = window.nckReport.backplots[0], ch = b.ch;
    b.canvas.scrollIntoView({ block: "center" });
    let best = 1, len = 0;
    for (let i = 1; i < b.n; i++) {
      const d = Math.hypot(b.uv[2 * i] - b.uv[2 * i - 2], b.uv[2 * i + 1] - b.uv[2 * i - 1]);
      if (d > len && !ch.rapid[i]) { len = d; best = i; }
    }
    const [x, y] = b.toScreen((b.uv[2 * best] + b.uv[2 * best - 2]) / 2, (b.uv[2 * best + 1] + b.uv[2 * best - 1]) / 2);
    const r = b.canvas.getBoundingClientRect();
    return { x: r.left + x, y: r.top + y, t0: ch.t[best - 1], t1: ch.t[best], line: ch.line[best] };
  });
  await page.mouse.click(seg.x, seg.y);
  const onPath = await state();
  if (!(onPath.t > seg.t0 && onPath.t < seg.t1)) fail(name, `a click mid-segment (${seg.t0}..${seg.t1} s) set the cursor to ${onPath.t}`);
  else if (onPath.line !== seg.line) fail(name, `a click on line ${seg.line}'s segment highlights line ${onPath.line}`);
  else ok(name, `a click mid-segment moved the cursor to ${onPath.t.toFixed(3)} s (line ${seg.line})`);
}

async function check(browser, c) {
  const { report, runMs, outputs } = runNck(c.name, c.machine, c.programs, c.plc, !!c.cursor);
  const sizeBytes = fs.statSync(report).size;
  const context = await browser.newContext({ offline: true, viewport: { width: 1320, height: 900 }, deviceScaleFactor: 1 });
  const page = await context.newPage();
  const problems = [], requests = [];
  // Chromium's software GL says "GPU stall due to ReadPixels" when it composites a WebGL canvas
  // (the 3D view) headless: a note of the driver, not of the page.
  const driverNote = (m) => /^\[\.WebGL-[^\]]*\]GL Driver Message .*GPU stall due to ReadPixels/.test(m.text());
  page.on("console", (m) => {
    if ((m.type() === "error" || m.type() === "warning") && !driverNote(m)) problems.push(m.type() + ": " + m.text());
  });
  page.on("pageerror", (e) => problems.push("page error: " + e.message));
  await page.route("**/*", (route) => {
    const url = route.request().url();
    if (url.startsWith("file:")) return route.continue();
    requests.push(url);
    return route.abort();
  });
  const t = Date.now();
  await page.goto("file://" + report, { waitUntil: "load" });
  await page.waitForFunction(() => window.nckReport && window.nckReport.ready, null, { timeout: 30000 });
  const loadMs = Date.now() - t;
  const info = await page.evaluate(() => {
    const r = window.nckReport;
    return {
      plots: r.plots.map((p) => ({
        title: p.title,
        points: p.u.data[0].length,
        series: p.u.data.slice(1).map((s) => s.filter((v) => v != null && Number.isFinite(v)).length),
      })),
      backplots: r.backplots.map((b) => ({ n: b.n, extents: b.extents(), has: b.ch.has, view: b.select.value })),
      views3d: r.views3d.length,
      waits: r.data.waits.length,
    };
  });
  const name = c.name;
  if (c.summary) {
    const text = await page.locator("#summary").textContent();
    if (!c.summary.test(text)) fail(name, `summary "${text}" does not match ${c.summary}`); else ok(name, "summary " + c.summary);
  }
  if (problems.length) fail(name, "console: " + problems.join(" | ")); else ok(name, "no console errors or warnings");
  if (requests.length) fail(name, "network requests: " + requests.join(", ")); else ok(name, "no network request");
  if (info.plots.length < c.minPlots) fail(name, `${info.plots.length} time plots, expected >= ${c.minPlots}`);
  for (const p of info.plots) {
    if (p.points < 2 || p.series.some((n) => n < 2)) fail(name, `plot "${p.title}" has no data (${p.points} points, ${p.series})`);
  }
  ok(name, `${info.plots.length} time plots with data: ${info.plots.map((p) => p.title).join("; ")}`);
  // issue 31: what a new user tripped over
  const looks = await page.evaluate(() => {
    const r = window.nckReport;
    const blocksHead = [...document.querySelectorAll("#cycletime h3")].map((h) => h.textContent).find((t) => t.startsWith("Longest"));
    const blocksRows = [...document.querySelectorAll("#cycletime div:nth-child(2) tr")].filter((tr) => tr.querySelector("td")).length;
    return {
      eventsText: document.querySelector("#events").textContent,
      blocksHead, blocksRows,
      ticks: r.plots.map((p) => ({ title: p.title, values: (p.u.axes[1]._values || []).map(String) })),
      legends: r.plots.map((p) => ({ title: p.title, marks: p.marks.length + p.waits.length,
                                     legend: !!p.u.root.parentElement.querySelector(".marks-legend") })),
    };
  });
  if (/\bnull\b|\{"/.test(looks.eventsText)) fail(name, "the event table shows null or raw JSON");
  else ok(name, "event fields without null or raw JSON");
  const shown = looks.blocksHead && +looks.blocksHead.match(/\((\d+) of/)[1];
  if (looks.blocksHead && shown !== looks.blocksRows) fail(name, `"${looks.blocksHead}" over ${looks.blocksRows} rows`);
  for (const t of looks.ticks)
    if (new Set(t.values).size !== t.values.length) fail(name, `plot "${t.title}" repeats y tick labels: ${t.values.join(" ")}`);
  for (const l of looks.legends)
    if (l.marks && !l.legend) fail(name, `plot "${l.title}" shades or marks without a legend`);
  ok(name, "block count, y ticks and legends");
  // issue 31 item 1: time by cause, a stacked bar and two tables per channel
  const causes = await page.evaluate(() => [...document.querySelectorAll("#causes .cause-channel")].map((d) => ({
    bar: [...d.querySelectorAll(".cause-bar span")].reduce((s, x) => s + parseFloat(x.style.width), 0),
    colours: [...d.querySelectorAll(".cause-bar span")].map((x) => x.style.background),
    causes: [...d.querySelectorAll(".cause-table tr")].filter((tr) => tr.querySelector("td")).length,
    lines: [...d.querySelectorAll(".blocks tr")].filter((tr) => tr.querySelector("td")).map((tr) => tr.children[1].textContent),
  })));
  if (!causes.length) fail(name, "no time-by-cause section");
  for (const [i, ch] of causes.entries()) {
    if (Math.abs(ch.bar - 100) > 0.5) fail(name, `cause bar ${i + 1} spans ${ch.bar} %`);
    if (new Set(ch.colours).size !== ch.colours.length) fail(name, `cause bar ${i + 1} repeats colours: ${ch.colours.join(" ")}`);
    if (ch.causes < (c.minCauses || 1)) fail(name, `cause table ${i + 1} has ${ch.causes} rows, expected ${c.minCauses || 1}`);
    if (!ch.lines.length || ch.lines.some((t) => !t.trim())) fail(name, `block table ${i + 1}: a row without its NC line`);
  }
  ok(name, `time by cause: ${causes.map((ch) => ch.causes + " causes, " + ch.lines.length + " blocks").join("; ")}`);
  if (info.backplots.length !== c.backplots.length) fail(name, `${info.backplots.length} backplots, expected ${c.backplots.length}`);
  c.backplots.forEach((want, i) => {
    const got = info.backplots[i];
    if (!got) return;
    if (want.view && got.view !== want.view) fail(name, `backplot ${i + 1} shows ${got.view}, expected ${want.view}`);
    if (want.minPoints && got.n < want.minPoints) fail(name, `backplot ${i + 1} has ${got.n} points, expected >= ${want.minPoints}`);
    for (let a = 0; a < 3; a++) {
      if (want.min[a] == null) continue;
      const dmin = Math.abs(got.extents.min[a] - want.min[a]), dmax = Math.abs(got.extents.max[a] - want.max[a]);
      if (dmin > want.tol || dmax > want.tol)
        fail(name, `backplot ${i + 1} axis ${"XYZ"[a]} spans ${got.extents.min[a]}..${got.extents.max[a]}, the program ${want.min[a]}..${want.max[a]}`);
    }
    ok(name, `backplot ${i + 1} (${got.view}) extents ${JSON.stringify(got.extents)}`);
  });
  if (c.wait) {
    // hover the middle of the wait in the panel that shades it; read the tooltip
    const found = await page.evaluate((want) => {
      const r = window.nckReport;
      const p = r.plots.find((p) => p.title === want.panel);
      if (!p) return "no panel " + want.panel;
      const w = p.waits.find((w) => w.reason === want.reason);
      if (!w) return "no wait " + want.reason;
      if (want.span && (Math.abs(w.t0 - want.span[0]) > 0.002 || Math.abs(w.t1 - want.span[1]) > 0.002))
        return `the ${want.reason} spans ${w.t0}..${w.t1} s, expected ${want.span[0]}..${want.span[1]}`;
      p.u.root.scrollIntoView({ block: "center" });
      p.u.setScale("x", { min: Math.max(0, w.t0 - 1), max: w.t1 + 1 });
      return "";
    }, c.wait);
    await page.waitForTimeout(200);  // uPlot redraws on the next frame
    const tipText = found || await page.evaluate((want) => {
      const p = window.nckReport.plots.find((p) => p.title === want.panel);
      const w = p.waits.find((w) => w.reason === want.reason);
      const x = p.u.valToPos((w.t0 + w.t1) / 2, "x"), rect = p.u.over.getBoundingClientRect();
      return { x: rect.left + x, y: rect.top + rect.height / 2 };
    }, c.wait);
    if (typeof tipText === "string") fail(name, tipText);
    else {
      await page.mouse.move(tipText.x, tipText.y);
      const text = await page.locator(".tip").textContent({ timeout: 2000 }).catch(() => "");
      if (!text.split(" · ").some((part) => c.wait.text.test(part))) fail(name, `hovering the wait shows "${text}", expected ${c.wait.text}`);
      else ok(name, `hovering the wait shows "${text}"`);
      await page.evaluate(() => { for (const p of window.nckReport.plots) p.u.setScale("x", { min: p.u.data[0][0], max: p.u.data[0][p.u.data[0].length - 1] }); window.scrollTo(0, 0); });
      await page.mouse.move(0, 0);
      await page.waitForTimeout(200);
    }
  }
  for (const want of c.marks || []) {
    // zoom round the mark, hover it, read the tooltip
    const at = await page.evaluate((want) => {
      const p = window.nckReport.plots.find((p) => p.title === want.panel);
      if (!p) return "no panel " + want.panel;
      const m = p.marks.find((m) => m.kind === want.kind && Math.abs(m.t - want.t) < 0.002);
      if (!m) return `no ${want.kind} mark at ${want.t} s (marks: ${JSON.stringify(p.marks)})`;
      p.u.root.scrollIntoView({ block: "center" });
      p.u.setScale("x", { min: m.t - 0.05, max: m.t + 0.05 });
      return { t: m.t };
    }, want);
    if (typeof at === "string") { fail(name, at); continue; }
    await page.waitForTimeout(200);
    const xy = await page.evaluate(([want, t]) => {
      const p = window.nckReport.plots.find((p) => p.title === want.panel);
      const rect = p.u.over.getBoundingClientRect();
      return { x: rect.left + p.u.valToPos(t, "x"), y: rect.top + rect.height / 2 };
    }, [want, at.t]);
    await page.mouse.move(xy.x, xy.y);
    const text = await page.locator(".tip").textContent({ timeout: 2000 }).catch(() => "");
    if (!text.split(" · ").some((part) => want.text.test(part))) fail(name, `hovering the ${want.kind} mark shows "${text}", expected ${want.text}`);
    else ok(name, `hovering the ${want.kind} mark shows "${text}"`);
    await page.evaluate(() => { for (const p of window.nckReport.plots) p.u.setScale("x", { min: p.u.data[0][0], max: p.u.data[0][p.u.data[0].length - 1] }); window.scrollTo(0, 0); });
    await page.mouse.move(0, 0);
    await page.waitForTimeout(100);
  }
  if (c.contour) {
    // the programmed contour beside the tool-centre path: each programmed segment's middle lies the
    // tool radius from the path (selection and departure lines left out: they lead onto the contour)
    const r = await page.evaluate((want) => {
      const b = window.nckReport.backplots[0];
      const runs = b.contour, ch = b.ch;
      const [h, v] = want.axes || [0, 1];  // the plane's axes: X Y, or X Z on a lathe
      const P = [ch.x, ch.y, ch.z];
      // the tool-centre path of the same stretch (its blocks' lines): the three contours overlap
      const dist = (px, py, lines) => {
        let best = Infinity;
        for (let i = 1; i < ch.x.length; i++) {
          if (ch.line[i] < lines[0] || ch.line[i] > lines[1]) continue;
          const ax = P[h][i - 1], ay = P[v][i - 1], dx = P[h][i] - ax, dy = P[v][i] - ay;
          const len2 = dx * dx + dy * dy;
          const f = len2 > 0 ? Math.max(0, Math.min(1, ((px - ax) * dx + (py - ay) * dy) / len2)) : 0;
          best = Math.min(best, Math.hypot(px - ax - f * dx, py - ay - f * dy));
        }
        return best;
      };
      const bad = [];
      let checked = 0;
      for (const run of runs)
        for (let k = 2; k < run.x.length - 1; k++) {
          const R = [run.x, run.y, run.z];
          const mx = (R[h][k - 1] + R[h][k]) / 2, my = (R[v][k - 1] + R[v][k]) / 2;
          // a turning tool's trace is its theoretical tip, `tip` away from the nose centre
          const [sh, sv] = want.tip || [0, 0];
          const d = dist(mx + sh, my + sv, run.lines);
          checked++;
          if (Math.abs(d - want.radius) > want.tol) bad.push(`(${mx.toFixed(3)}, ${my.toFixed(3)}): ${d.toFixed(4)}`);
        }
      return { runs: runs.length, checked, bad, drawn: b.el.querySelector(".legend-key.programmed") != null };
    }, c.contour);
    if (r.runs !== c.contour.runs) fail(name, `${r.runs} programmed-contour runs, expected ${c.contour.runs}`);
    if (!r.drawn) fail(name, "no legend for the programmed contour");
    if (r.checked < 8 || r.bad.length) fail(name, `programmed contour vs tool centre (${r.checked} checked): ${r.bad.slice(0, 5).join("; ")}`);
    else ok(name, `${r.runs} programmed-contour runs; ${r.checked} segment middles lie ${c.contour.radius} mm from the tool centre`);
  }
  for (const [i, want] of (c.pcs || []).entries()) {
    const got = await page.evaluate((i) => {
      const b = window.nckReport.backplots[i];
      b.coords.value = "pcs";
      b.coords.dispatchEvent(new Event("change"));
      return b.extents();
    }, i);
    const off = [0, 1, 2].filter((a) => Math.abs(got.min[a] - want.min[a]) > want.tol || Math.abs(got.max[a] - want.max[a]) > want.tol);
    if (off.length) fail(name, `backplot ${i + 1} in program coordinates spans ${JSON.stringify(got)}, expected ${JSON.stringify(want)}`);
    else ok(name, `backplot ${i + 1} in program coordinates: ${JSON.stringify(got)}`);
  }
  if (c.links) {  // issue 48 item 5: the coupling table as Y2 ← Y1, not raw JSON
    const text = await page.evaluate(() => [...document.querySelectorAll("section h2")]
      .find((h) => h.textContent.startsWith("Synchronous"))?.parentElement.textContent || "");
    if (!c.links.test(text) || /[[\]"]/.test(text)) fail(name, `coupling table "${text}", expected ${c.links}`);
    else ok(name, `coupling table "${text.slice(0, 80)}…"`);
  }
  if (c.timeline) {  // issue 48 item 12: who waits for whom, one bar per wait of the run
    const got = await page.evaluate(() => ({ bars: window.nckReport.timeline, waits: window.nckReport.data.waits.length,
      drawn: document.querySelectorAll("#timeline rect.tl-bar").length,
      rows: [...document.querySelectorAll("#timeline .tl-row")].map((r) => r.textContent) }));
    if (got.bars.length !== got.waits || got.drawn !== got.waits || got.waits === 0)
      fail(name, `timeline: ${got.drawn} bars drawn, ${got.bars.length} listed for ${got.waits} waits`);
    else ok(name, `timeline: a bar for each of the ${got.waits} waits`);
    if (JSON.stringify(got.rows) !== JSON.stringify(c.timeline.rows)) fail(name, `timeline rows ${JSON.stringify(got.rows)}, expected ${JSON.stringify(c.timeline.rows)}`);
    for (const want of c.timeline.bars) {
      const b = got.bars.find((b) => b.party === want.party && Math.abs(b.t0 - want.t0) < 1e-3 && Math.abs(b.t1 - want.t1) < 1e-3);
      if (!b || !want.text.test(b.text)) fail(name, `timeline: no ${want.party} bar ${want.t0}..${want.t1} s like ${want.text} (${JSON.stringify(b)})`);
      else ok(name, `timeline bar "${b.text}"`);
    }
  }
  if (c.iso) {  // issue 48 item 5: the isometric view has no tick labels (no axis runs along the screen)
    const texts = await page.evaluate(() => {
      const b = window.nckReport.backplots[0], drawn = [], fill = b.ctx.fillText;
      b.ctx.fillText = function (t, ...rest) { drawn.push(String(t)); return fill.call(this, t, ...rest); };
      b.select.value = "ISO";
      b.select.dispatchEvent(new Event("change"));
      b.draw();
      b.ctx.fillText = fill;
      b.select.value = "XY";
      b.select.dispatchEvent(new Event("change"));
      return drawn;
    });
    const numbers = texts.filter((t) => /^-?[\d.]+$/.test(t.trim()));
    if (numbers.length || !texts.some((t) => t.startsWith("isometric"))) fail(name, `the isometric view draws ${JSON.stringify(texts)}`);
    else ok(name, `the isometric view draws no tick labels (${JSON.stringify(texts)})`);
  }
  if (c.cursor) await checkCursor(page, name, { ...outputs, ...c.cursor }, { fail, ok });
  if (c.play) await checkPlayer(page, name);
  // a 3D view for each channel with three linear axes, none otherwise
  const want3d = c.backplots.filter((b) => b.view3d).length;
  if (info.views3d !== want3d) fail(name, `${info.views3d} 3D views, expected ${want3d}`);
  if (typeof c.backplots[0].view3d === "object") await check3d(page, name, c.backplots[0].view3d, { fail, ok });
  if (c.accel) await checkAccel(page, name, c.accel, { fail, ok });
  if (c.caps) {
    if (sizeBytes > c.caps.bytes) fail(name, `report is ${sizeBytes} bytes, cap ${c.caps.bytes}`);
    if (loadMs > c.caps.loadMs) fail(name, `report loads in ${loadMs} ms, cap ${c.caps.loadMs}`);
  }
  ok(name, `run ${runMs} ms, report ${(sizeBytes / 1e6).toFixed(2)} MB, load ${loadMs} ms`);
  await page.screenshot({ path: path.join(out, name + ".png"), fullPage: true });
  if (args.images && c.image) {
    await page.evaluate(() => { const e = document.querySelector("#events"); if (e) e.style.maxHeight = "260px"; });
    await page.screenshot({ path: path.join(args.images, c.image), fullPage: true });
  }
  await context.close();
}

const browser = await chromium.launch({ executablePath: chromiumPath, headless: true, args: ["--no-sandbox"] });
try {
  const longProgram = path.join(out, `common_${blocks}.nc`);
  writeCommonProgram(longProgram, blocks);
  writeFrameProgram(path.join(out, "frames.nc"));
  writeHoldProgram(out);
  for (const c of expectations(longProgram, blocks, caps(blocks), out))
    if (!args.only || args.only.split(",").includes(c.name)) await check(browser, c);
} catch (e) {
  fail("browser test", e.stack || String(e));
} finally {
  await browser.close();
}
console.log(failures ? `${failures} failure(s)` : "all report checks passed");
process.exit(failures ? 1 : 0);
