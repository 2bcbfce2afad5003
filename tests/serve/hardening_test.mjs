// nck serve's third robustness pass (issue 45), through the real server on
// 127.0.0.1: each section is one defect of the issue, checked the way it
// was found. Usage: node tests/serve/hardening_test.mjs --nck BIN --source DIR --out DIR
import fs from "node:fs";
import path from "node:path";

import { check, command, errorId, finish, request, runServe, sleep, startServer, state, stopServer,
         testArgs } from "./serve_client.mjs";

const { nck, src, out } = testArgs("serve-hardening-out");
const serve = (extra, machine) => startServer(nck, src, extra, machine);

// Item 3: a tiny speed froze the kernel for good; 1e-300 ran it flat out.
async function slowSpeeds() {
  for (const speed of ["1e-5", "1e-300", "10001", "0"]) {
    const r = await runServe(nck, src, ["examples/mill", "--port", "0", "--no-realtime", "--speed", speed]);
    check(`--speed ${speed} is refused (exit 2, 940320)`, r.code === 2 && r.stderr.includes("940320"),
          `${r.code} ${r.signal} ${r.stderr}`);
  }
  const s = await serve(["--speed", "0.001"]);
  const refused = await command(s, { command: "speed", speed: 1e-5 });
  check("speed 1e-5 is refused (400, 940303)", refused.status === 400 && errorId(refused) === 940303, refused.body);
  const held = await command(s, { command: "feedhold", on: true });
  await sleep(150);  // a cycle is 1 s away at 1e-3: the action must not wait for it
  check("at speed 1e-3 an action acts at once", held.status === 200 && (await state(s)).channels[0]?.feedhold === true);
  const t0 = Date.now();
  const ended = await stopServer(s, "SIGTERM");
  check("at speed 1e-3 SIGTERM ends the server at once (exit 143)", ended?.code === 143 && Date.now() - t0 < 1500,
        `${JSON.stringify(ended)} after ${Date.now() - t0} ms`);
}

async function main() {
  await slowSpeeds();
  finish();
}
main().catch((e) => { console.error(e); process.exit(1); });
