// nck serve's offsets and tools routes (issue 48 item 8, docs/api.md), on a
// copy of examples/mill in the out folder (examples/ is never written):
// edits, refusals with their IDs, the touch-off arithmetic, save with a
// backup, a save refused after the file changed on disk and one without
// the token. Usage: node tests/serve/offsets_test.mjs --nck BIN --source DIR --out DIR
import fs from "node:fs";
import path from "node:path";

import { check, command, errorId, finish, request, sleep, startServer, state, stopServer, testArgs } from "./serve_client.mjs";

const { nck, src, out } = testArgs("serve-offsets-out");
const machine = path.join(out, "mill");
fs.cpSync(path.join(src, "examples/mill"), machine, { recursive: true });
const zeroFile = path.join(machine, "zero.lis");

const post = (s, target, obj, opts = {}) => request(s, "POST", target, { body: JSON.stringify(obj), ...opts });
const tables = async (s) => JSON.parse((await request(s, "GET", "/api/v1/offsets")).body).channels[0];
const zeroOf = (c, offset) => c.zero.find((z) => z.offset === offset).values_mm;

async function untilState(s, pred, ms, what) {
  const end = Date.now() + ms;
  for (;;) {
    const st = await state(s);
    if (pred(st)) return st;
    if (Date.now() > end) { check(what, false, JSON.stringify(st.channels[0])); return st; }
    await sleep(20);
  }
}

async function edits(s) {
  const c = await tables(s);
  check("GET /api/v1/offsets: G54 of zero.lis", zeroOf(c, "G54").X === 100 && zeroOf(c, "G54").Z === -150, JSON.stringify(c.zero[0]));
  check("GET /api/v1/offsets: the tool table and the clamp groups", c.tools.find((t) => t.tool === 1).length_mm === 100 &&
        c.clamp[1].values_mm.X === 10 && c.files.zero === "zero.lis");
  const r = await post(s, "/api/v1/offsets/zero", { offset: "G55", axis: "Y", value_mm: 12.5 });
  const after = await tables(s);
  check("an edit of G55 Y answers ok and shows", r.status === 200 && zeroOf(after, "G55").Y === 12.5, r.body);
  check("an edit is unsaved until the save", JSON.parse((await request(s, "GET", "/api/v1/offsets")).body).unsaved === true);
  check("the file is not written by an edit", !fs.readFileSync(zeroFile, "utf8").includes("125000"));
  const far = await post(s, "/api/v1/offsets/zero", { offset: "G54", axis: "X", value_mm: 1e9 });
  check("an offset out of the list's range: 422 with 940331", far.status === 422 && errorId(far) === 940331, far.body);
  const g60 = await post(s, "/api/v1/offsets/zero", { offset: "G60", axis: "X", value_mm: 1 });
  check("a non-existent offset: 404 with 940330", g60.status === 404 && errorId(g60) === 940330, g60.body);
  const q = await post(s, "/api/v1/offsets/zero", { offset: "G54", axis: "Q", value_mm: 1 });
  check("a non-existent axis: 404 with 940330", q.status === 404 && errorId(q) === 940330, q.body);
  const extra = await post(s, "/api/v1/offsets/zero", { offset: "G54", axis: "X", value_mm: 1, unit: "inch" });
  check("an unknown field: 400 with 940302", extra.status === 400 && errorId(extra) === 940302, extra.body);
  const noToken = await post(s, "/api/v1/offsets/zero", { offset: "G54", axis: "X", value_mm: 1 }, { token: false });
  check("an edit without the token: 401", noToken.status === 401 && errorId(noToken) === 940304);
  check("nothing of the refused edits changed the table", JSON.stringify(zeroOf(await tables(s), "G54")) === JSON.stringify(zeroOf(c, "G54")));
  const tool = await post(s, "/api/v1/tools/1", { length_mm: 101.25, radius_mm: 5.5 });
  const t1 = (await tables(s)).tools.find((t) => t.tool === 1);
  check("a tool edit: D1 length and radius", tool.status === 200 && t1.length_mm === 101.25 && t1.radius_mm === 5.5, tool.body);
  check("D1's vb_max of 1 (0.001 deg/s) reads 1/6000 rpm, not rounded to 0.0002", Math.abs(t1.vb_max_rpm - 1 / 6000) < 1e-6,
        JSON.stringify(t1));
  const t99 = await post(s, "/api/v1/tools/99", { length_mm: 1 });
  check("a tool the list does not have: 404 with 940330", t99.status === 404 && errorId(t99) === 940330, t99.body);
  const vb = await post(s, "/api/v1/tools/5", { vb_min_rpm: 900 });
  check("vb_min above vb_max (the loader's rule): 422 with 940331", vb.status === 422 && errorId(vb) === 940331, vb.body);
  const clamp = await post(s, "/api/v1/offsets/clamp", { group: 1, axis: "Y", value_mm: -7 });
  check("a clamp-offset edit", clamp.status === 200 && (await tables(s)).clamp[1].values_mm.Y === -7, clamp.body);
  const noGroup = await post(s, "/api/v1/offsets/clamp", { group: 9, axis: "Y", value_mm: -7 });
  check("a clamp group the list does not have: 404 with 940330", noGroup.status === 404 && errorId(noGroup) === 940330);
}

// A running program takes an edited zero offset at its next selection (as
// ISG does), not before: G54 X (100 in zero.lis) edited to 120 while the
// program dwells leaves the axis at MCS 100 until the program selects G54
// again and moves to X0, which is then MCS 120. The 1,000 dwell blocks keep
// the second selection out of what preparation has decoded ahead.
async function runningProgram(s) {
  const dwell = Array.from({ length: 1000 }, () => "G04 X0.005").join("\n");
  const text = `N10 G54 G90 G01 X0 Y0 F60000\n${dwell}\nN20 G54 G90 G01 X0 F60000\nN30 M30\n`;
  const up = await request(s, "POST", "/api/v1/upload?name=reselect.nc", { body: text });
  const load = await command(s, { command: "load", program: "reselect.nc" });
  check("upload and load a program that selects G54 twice", up.status === 200 && load.status === 200, load.body);
  await sleep(300);
  await command(s, { command: "cycle_start" });
  const first = await untilState(s, (st) => st.channels[0].state === "running" && Math.abs(st.channels[0].mcs.X - 100) < 1e-6,
                                 10000, "the program stands at G54 X0 = MCS 100");
  const r = await post(s, "/api/v1/offsets/zero", { offset: "G54", axis: "X", value_mm: 120 });
  check("an edit of G54 X while the program runs is taken", r.status === 200, r.body);
  const during = await state(s);
  check("the G54 in force keeps its value: still MCS X 100", during.channels[0].state === "running" &&
        Math.abs(during.channels[0].mcs.X - 100) < 1e-6, JSON.stringify(during.channels[0].mcs));
  const end = await untilState(s, (st) => st.run === first.run && st.channels[0].state !== "running", 20000, "the program ends");
  check("the next G54 selection takes the edit: X0 is MCS 120", Math.abs(end.channels[0].mcs.X - 120) < 1e-6 &&
        Math.abs(end.channels[0].pcs.X) < 1e-6, JSON.stringify(end.channels[0].mcs) + JSON.stringify(end.channels[0].pcs));
  await post(s, "/api/v1/offsets/zero", { offset: "G54", axis: "X", value_mm: 100 });  // as zero.lis has it
}

// G55 selected by MDI, the axes moved; touching off G54 X so that X reads 2
// gives G54 X = MCS X - 2 (no tool, no clamp offset), and an MDI G54 X2
// then does not move the axis.
async function touchOff(s) {
  await sleep(300);  // the run the last edit handed the idle kernel is taken
  const mdi = await command(s, { command: "mdi", channel: 1, text: "G55 G90 G01 X7 Y3 F6000" });
  check("MDI G55 G1 X7 accepted", mdi.status === 200, mdi.body);
  const moved = await untilState(s, (st) => st.channels[0].state !== "running" && Math.abs(st.channels[0].pcs.X - 7) < 1e-6,
                                 15000, "the MDI move under G55 ends at X7");
  const mcsX = moved.channels[0].mcs.X;
  const run = moved.run;
  const r = await post(s, "/api/v1/offsets/touch_off", { offset: "G54", axis: "X", reads_mm: 2 });
  const answer = JSON.parse(r.body);
  check("touch-off G54 X reads 2: value = MCS - 2", r.status === 200 && Math.abs(answer.value_mm - (mcsX - 2)) < 1e-4,
        `${r.body} mcs ${mcsX}`);
  check("the touched-off value in the table", Math.abs(zeroOf(await tables(s), "G54").X - (mcsX - 2)) < 1e-4);
  // the edit gave the idle kernel a fresh run: its MDI selects the new value
  await untilState(s, (st) => st.run > run, 5000, "a fresh run after the edit");
  // G54 X2 in absolute: no move, the axis stands where it was touched off
  const sel = await command(s, { command: "mdi", channel: 1, text: "G54 G90 G01 X2 F6000" });
  check("MDI G54 X2 accepted", sel.status === 200, sel.body);
  const st = await untilState(s, (x) => x.channels[0].modal && x.channels[0].modal.zero_offset === "G54" &&
                                        x.channels[0].state === "idle", 5000, "G54 selected");
  check("after G54 X2 the axis did not move and reads 2", Math.abs(st.channels[0].mcs.X - mcsX) < 1e-4 &&
        Math.abs(st.channels[0].pcs.X - 2) < 1e-4, JSON.stringify(st.channels[0].mcs) + JSON.stringify(st.channels[0].pcs));
  const bad = await post(s, "/api/v1/offsets/touch_off", { offset: "G61", axis: "X", reads_mm: 0 });
  check("touch-off of a non-existent offset: 404 with 940330", bad.status === 404 && errorId(bad) === 940330, bad.body);
}

async function save(s) {
  const noToken = await post(s, "/api/v1/offsets/save", {}, { token: false });
  check("a save without the token: 401, nothing written", noToken.status === 401 && !fs.existsSync(zeroFile + ".bak"));
  const old = fs.readFileSync(zeroFile, "utf8");
  const r = await post(s, "/api/v1/offsets/save", {});
  const text = fs.readFileSync(zeroFile, "utf8");
  check("the save answers the files written", r.status === 200 && JSON.parse(r.body).written.includes("zero.lis"), r.body);
  check("zero.lis.bak keeps the old file", fs.readFileSync(zeroFile + ".bak", "utf8") === old);
  check("G55 Y written as 125000 (0.1 um), its comment kept",
        /^np_grp\[2\]\.achse\[1\]\.versch\s+125000\s+# G55 Y 100 mm$/m.test(text), text);
  check("the other lines as they were", text.includes("np_grp[1].achse[1].versch    500000     # G54 Y 50 mm") &&
        text.startsWith("# Zero-offset list of the mill") && text.trimEnd().endsWith("Ende"));
  check("tools.lis written too", /wz\[1\]\.laenge\s+1012500/.test(fs.readFileSync(path.join(machine, "tools.lis"), "utf8")));
  check("no temporary file left", !fs.existsSync(zeroFile + ".tmp"));
  // A change on disk after the load: the next save is refused, nothing written.
  await post(s, "/api/v1/offsets/zero", { offset: "G56", axis: "X", value_mm: 1 });
  fs.appendFileSync(zeroFile, "# edited by hand\n");
  const changed = fs.readFileSync(zeroFile, "utf8");
  const refused = await post(s, "/api/v1/offsets/save", {});
  check("a save after the file changed on disk: 409 with 940333", refused.status === 409 && errorId(refused) === 940333, refused.body);
  check("the refused save wrote nothing", fs.readFileSync(zeroFile, "utf8") === changed);
  const reload = await post(s, "/api/v1/offsets/reload", {});
  const c = await tables(s);
  check("reload: the lists from disk, the unsaved edit gone", reload.status === 200 && zeroOf(c, "G56").X === 0 &&
        zeroOf(c, "G55").Y === 12.5, reload.body);
  const again = await post(s, "/api/v1/offsets/zero", { offset: "G56", axis: "X", value_mm: 3 });
  const saved = await post(s, "/api/v1/offsets/save", {});
  check("after the reload a save goes through", again.status === 200 && saved.status === 200 &&
        fs.readFileSync(zeroFile, "utf8").includes("np_grp[3].achse[0].versch"), saved.body);
}

const s = await startServer(nck, src, [], machine);
try {
  await edits(s);
  await runningProgram(s);
  await touchOff(s);
  await save(s);
} finally {
  await stopServer(s);
}
finish();
