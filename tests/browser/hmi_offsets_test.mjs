// Browser test of the HMI's offsets and tools panel (issue 48 item 8):
// `nck serve` on a copy of examples/mill in the out folder (examples/ is
// never written), the panel opened in Debian's chromium; an out-of-range
// edit shows its refusal with the ID, a touch-off of G54 Z makes Z read 0,
// the save writes zero.lis with the value and keeps zero.lis.bak; an MDI
// #CS ON shows in the panel's coordinate systems.
// Usage: node tests/browser/hmi_offsets_test.mjs --nck BIN --source DIR --out DIR
import { chromium } from "playwright-core";
import fs from "node:fs";
import path from "node:path";
import { startServer } from "./hmi_server.mjs";

const args = Object.fromEntries(process.argv.slice(2).reduce((acc, a, i, all) => {
  if (a.startsWith("--")) acc.push([a.slice(2), all[i + 1] && !all[i + 1].startsWith("--") ? all[i + 1] : "1"]);
  return acc;
}, []));
const src = path.resolve(args.source || "."), out = path.resolve(args.out || "hmi-offsets-out");
fs.rmSync(out, { recursive: true, force: true });
fs.mkdirSync(out, { recursive: true });
const machine = path.join(out, "mill");
fs.cpSync(path.join(src, "examples/mill"), machine, { recursive: true });
const zeroFile = path.join(machine, "zero.lis");
let failures = 0;
const expect = (cond, good, bad) => {
  if (cond) console.log("ok   " + good);
  else { failures++; console.error("FAIL " + (bad || good)); }
};

async function check(page) {
  await page.waitForFunction(() => window.nckHmi && window.nckHmi.ready && window.nckOffsets.tables, null, { timeout: 10000 });
  await page.locator("#offsets-section summary").click();
  const panel = page.locator('#offsets .offsets-channel[data-channel="1"]');
  const g54x = panel.getByLabel("G54 X", { exact: true });
  expect(await g54x.inputValue() === "100", "the panel shows G54 X 100 from zero.lis", `G54 X shows ${await g54x.inputValue()}`);
  // an out-of-range value: refused with its ID in the panel, nothing changed
  await g54x.fill("1e9");
  await g54x.press("Enter");
  await page.waitForFunction(() => window.nckOffsets.refusals > 0, null, { timeout: 5000 }).catch(() => null);
  const shown = await page.locator("#offsets-message").textContent();
  expect(/940331/.test(shown) && await g54x.inputValue() === "100", `an out-of-range edit is refused with its ID: "${shown}"`);
  // Z moved by an MDI block to -12.5 in machine coordinates, then G54 Z
  // touched off so that this position reads 0
  await page.evaluate(() => window.NckApi.command("mdi", 1, { text: "G53 G90 G01 Z-12.5 F6000" }));
  await page.waitForFunction(() => {
    const c = window.nckHmi.state.channels[0];
    return c.state === "idle" && Math.abs(c.mcs.Z + 12.5) < 1e-4;
  }, null, { timeout: 10000 }).catch(() => null);
  const mcsZ = await page.evaluate(() => window.nckHmi.state.channels[0].mcs.Z);
  expect(Math.abs(mcsZ + 12.5) < 1e-4, "MDI moved Z to -12.5", `Z at ${mcsZ}`);
  await panel.getByLabel("offset to touch off").selectOption("G54");
  await panel.getByLabel("reads mm").fill("0");
  await panel.getByRole("button", { name: "Touch off Z", exact: true }).click();
  await page.waitForFunction((z) => Math.abs(window.nckOffsets.tables.channels[0].zero[0].values_mm.Z - z) < 1e-4, mcsZ, { timeout: 5000 })
    .catch(() => null);
  const z = await page.evaluate(() => window.nckOffsets.tables.channels[0].zero[0].values_mm.Z);
  expect(Math.abs(z - mcsZ) < 1e-4 && await page.locator("#offsets-unsaved").isVisible(),
    `touch-off G54 Z reads 0: G54 Z = MCS Z = ${z}, marked unsaved`, `touch-off: G54 Z ${z}, MCS Z ${mcsZ}`);
  const old = fs.readFileSync(zeroFile, "utf8");
  await page.getByRole("button", { name: "Save to the list files" }).click();
  await page.waitForFunction(() => /saved/.test(document.getElementById("offsets-message").textContent), null, { timeout: 5000 }).catch(() => null);
  const text = fs.readFileSync(zeroFile, "utf8");
  const written = new RegExp(`^np_grp\\[1\\]\\.achse\\[2\\]\\.versch\\s+${Math.round(mcsZ * 1e4)}\\s+# G54 Z -150 mm$`, "m");
  expect(written.test(text), `zero.lis has G54 Z = ${Math.round(mcsZ * 1e4)} (0.1 um), its comment kept`, `zero.lis: ${text}`);
  expect(fs.existsSync(zeroFile + ".bak") && fs.readFileSync(zeroFile + ".bak", "utf8") === old, "zero.lis.bak keeps the old file");
  const clean = await page.locator("#offsets-unsaved").waitFor({ state: "hidden", timeout: 5000 }).then(() => true).catch(() => false);
  expect(clean, "no unsaved edits after the save");
  // A coordinate system the program sets (#CS ON) shows in the open panel,
  // read only: it is programmed, not listed.
  const csNone = await panel.locator(".cs-none").isVisible();
  await page.evaluate(() => window.NckApi.command("mdi", 1, { text: "#CS ON [1][10,5,0,0,0,30]" }));
  const csRow = panel.locator('table.cs tr[data-cs="cs"] td.cs-values');
  const csText = await csRow.waitFor({ timeout: 10000 }).then(() => csRow.textContent()).catch(() => "");
  expect(csNone && /X 10 .*Y 5 .*angle3 30/.test(csText) && !(await panel.locator("table.cs input").count()),
    `#CS ON in MDI shows in the panel, without edit boxes: "${csText}"`, `#CS row: "${csText}" (none shown before: ${csNone})`);
}

const server = startServer(path.resolve(args.nck), src, [machine], 60);
const browser = await chromium.launch({ executablePath: process.env.NCK_CHROMIUM || "/usr/bin/chromium", headless: true, args: ["--no-sandbox"] });
try {
  const page = await browser.newPage({ viewport: { width: 1560, height: 1000 } });
  const problems = [];
  page.on("pageerror", (e) => problems.push("page error: " + e.message));
  // the refused edit is answered 422, which the browser logs itself (and a favicon it looks for)
  page.on("console", (m) => { if (m.type() === "error" && !/status of 422/.test(m.text()) && !/favicon/.test(m.location().url)) problems.push(m.text() + " " + m.location().url); });
  page.on("response", (r) => { if (r.status() === 404) problems.push("404 " + r.url()); });
  await page.goto(await server.url);
  await check(page);
  expect(!problems.length, "no page errors", problems.join(" | "));
} catch (e) {
  failures++;
  console.error("FAIL " + (e.stack || e));
} finally {
  await browser.close();
  await server.stop();
}
console.log(failures ? `${failures} failure(s)` : "all offsets checks passed");
process.exit(failures ? 1 : 0);
