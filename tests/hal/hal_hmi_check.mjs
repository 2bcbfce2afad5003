// The HMI page against nck-hal --serve (hal_test.py's `serve` case, run by
// serve_client.py inside the HAL session's namespaces while contour.nc
// runs): the page shows the kernel in the HAL thread, offers what nck-hal
// offers and not what the HAL file owns, and its Feedhold button holds the
// path there. Prints `ok: ...` per check, `FAILED: ...` and exits 1 at the
// first failure.
//   node hal_hmi_check.mjs URL
import { chromium } from "playwright-core";

const url = process.argv[2];
const check = (cond, what) => {
  console.log((cond ? "ok: " : "FAILED: ") + what);
  if (!cond) process.exit(1);
};

const browser = await chromium.launch({ executablePath: process.env.NCK_CHROMIUM || "/usr/bin/chromium", headless: true,
  args: ["--no-sandbox"] });
try {
  const page = await browser.newPage({ viewport: { width: 1400, height: 1000 } });
  const problems = [];
  page.on("pageerror", (e) => problems.push(e.message));
  await page.goto(url);
  await page.waitForFunction(() => window.nckHmi && window.nckHmi.ready && document.body.classList.contains("hal"),
    null, { timeout: 15000 });
  check(true, "the page shows nck-hal's state (body.hal)");
  const hidden = await page.evaluate(() => [".panel.jog", ".panel.mdi", "button.home", "button.load", ".run-pace"]
    .filter((sel) => { const e = document.querySelector(sel); return e && e.offsetParent !== null; }));
  check(!hidden.length, `jog, MDI, homing, loading and the pace are not offered (shown: ${hidden.join(", ") || "none"})`);
  check(await page.locator("#estop").isDisabled(), "the E-stop button is a HAL pin's: disabled");
  const state = () => page.evaluate(() => window.nckHmi.state.channels[0]);
  check((await state()).state === "running", "the page shows the program running");
  await page.getByRole("button", { name: "Feedhold" }).click();
  await page.waitForFunction(() => window.nckHmi.state.channels[0].feedhold &&
    window.nckHmi.state.channels[0].path_velocity_mm_s === 0, null, { timeout: 5000 });
  check(true, "the page's Feedhold holds the path in the HAL thread");
  await page.getByRole("button", { name: "Feedhold" }).click();
  await page.waitForFunction(() => !window.nckHmi.state.channels[0].feedhold, null, { timeout: 5000 });
  check(true, "a second click releases it");
  const errors = await page.evaluate(() => window.nckHmi.errors.map((e) => `${e.kind} ${e.id} ${e.message}`));
  check(!errors.length && !problems.length, `no errors on the page (${[...errors, ...problems].join(" | ") || "none"})`);
} finally {
  await browser.close();
}
