// The HMI's program text beyond its first page (docs/api.md: GET
// /api/v1/program answers at most 2 MiB of JSON): a program of 40,000 long
// comment lines and a move at its end, 3 MB of text. Scrolling to the end
// shows its last lines; after a reload the running move (on the second page)
// is highlighted without any scrolling. Called by hmi_test.mjs with its Hmi
// helper (h) and its checks.
const LINES = 40000;
const PAD = "x".repeat(60);
const lineText = (i) => `; paging test line ${i} ${PAD}`;

// The program view of channel 1: its lines loaded, next page, current line.
const view = (page) => page.evaluate(() => {
  const p = window.nckHmi.panels[0].program;
  return { path: p.path, loaded: p.lines.length, next: p.nextLine, current: p.currentLine };
});

async function waitFor(page, pred, ms) {
  const end = Date.now() + ms;
  for (;;) {
    const v = await view(page);
    if (pred(v) || Date.now() > end) return v;
    await page.waitForTimeout(50);
  }
}

export async function checkProgramPages(h, { expect, fail }) {
  const page = h.page;
  await h.reset();
  const stored = await page.evaluate(async ({ n, pad }) => {
    let text = "";
    for (let i = 1; i <= n; i++) text += `; paging test line ${i} ${pad}\n`;
    text += "N10 G90 G1 X-20 F120\nM30\n";  // about 15 s from where the jog left X
    await window.NckApi.upload("pages.nc", text);
    await window.NckApi.command("load", 1, { program: "pages.nc" });
    return text.length;
  }, { n: LINES, pad: PAD });
  const first = await waitFor(page, (v) => v.path.endsWith("pages.nc") && v.loaded > 0, 10000);
  expect(first.path.endsWith("pages.nc") && first.loaded < LINES && first.next === first.loaded + 1,
    `a ${(stored / 1e6).toFixed(1)} MB program: the first page holds lines 1-${first.loaded}, next_line ${first.next}`,
    `the big program's first page: ${JSON.stringify(first)}`);
  const target = LINES - 5;  // on the second page
  const row = h.ch.locator(`.program-lines li[data-line="${target}"] code`);
  const end = Date.now() + 15000;
  while (Date.now() < end && !(await row.count())) {
    await page.evaluate(() => { const box = document.querySelector(".channel .program"); box.scrollTop = box.scrollHeight; });
    await page.waitForTimeout(100);
  }
  const shown = (await row.count()) ? await row.textContent() : null;
  expect(shown === lineText(target), `scrolled to the end: line ${target} (second page) is shown`,
    `line ${target} after scrolling: ${JSON.stringify(shown)} (${JSON.stringify(await view(page))})`);
  const rows = await h.ch.locator(".program-lines li").count();
  expect(rows < 1000, `only the rows around the view are drawn (${rows} of ${LINES + 2})`);

  await page.reload();
  await page.waitForFunction(() => window.nckHmi && window.nckHmi.ready && window.nckHmi.panels[0].program.lines.length, null,
    { timeout: 10000 });
  const again = await view(page);
  if (again.loaded >= LINES) fail(`after the reload the first page should end before line ${LINES} (${again.loaded})`);
  await h.button("Cycle start").click();
  const moving = await waitFor(page, (v) => v.current === LINES + 1, 10000);
  const marked = await h.currentLine();
  expect(moving.current === LINES + 1 && marked === String(LINES + 1),
    `the running move on line ${LINES + 1} (second page) is highlighted after a reload (${moving.loaded} lines loaded)`,
    `the running move: ${JSON.stringify(moving)}, marked row ${marked}`);
  await h.button("Reset").click();
}
