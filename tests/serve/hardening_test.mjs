// nck serve's third robustness pass (issue 45), through the real server on
// 127.0.0.1: each section is one defect of the issue, checked the way it
// was found. Usage: node tests/serve/hardening_test.mjs --nck BIN --source DIR --out DIR
import fs from "node:fs";
import net from "node:net";
import path from "node:path";

import { check, command, errorId, finish, readStream, request, runServe, sleep, startServer, state, stopServer,
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

// Item 5: before the first load, MDI `L FILE` opened any file and its
// diagnostics quoted the file's words.
async function firstRunConfinement() {
  const outside = path.join(out, "outside");
  fs.mkdirSync(outside, { recursive: true });
  const secret = path.join(outside, "secret.nc");
  fs.writeFileSync(secret, "API_KEY=hunter2\n");
  fs.mkdirSync(path.join(out, "cli"), { recursive: true });
  fs.writeFileSync(path.join(out, "cli", "main.nc"), "G0 X1\nM30\n");
  for (const [what, programs] of [["a fresh server", []], ["a server with a program named", [path.join(out, "cli", "main.nc")]]]) {
    const s = await serve(programs);
    try {
      const stream = readStream(s, 1500);
      await sleep(200);
      const r = await command(s, { command: "mdi", text: `L ${secret}` });
      const seen = (await stream).text;
      check(`${what}: MDI L outside the folders -> 920120`, r.status !== 200 || seen.includes('"id":920120'),
            `${r.status} ${seen.slice(-300)}`);
      check(`${what}: no word of the file in any answer or event`, !/API_KEY|hunter2/.test(seen + r.body),
            seen.slice(-300));
    } finally {
      await stopServer(s);
    }
  }
}

// Item 6: the default uploads folder was /tmp/nck-serve-<pid>-uploads,
// predictable, reused and never removed.
async function privateUploads() {
  const s = await serve([]);
  let folder = "";
  try {
    const up = await request(s, "POST", "/api/v1/upload?name=job.nc", { body: "G0 X1\nM30\n" });
    const load = await command(s, { command: "load", program: "job.nc" });
    const program = JSON.parse((await request(s, "GET", "/api/v1/program?channel=1")).body);
    folder = path.dirname(program.path ?? "");
    check("an upload is stored and loaded", up.status === 200 && load.status === 200, up.body + load.body);
    check("the uploads folder's name is not the pid's", !folder.includes(String(s.proc.pid)) && /nck-serve-uploads-/.test(folder),
          folder);
    check("the uploads folder is private (0700)", (fs.statSync(folder).mode & 0o777) === 0o700);
  } finally {
    await stopServer(s);
  }
  check("the uploads folder is removed at the end", folder !== "" && !fs.existsSync(folder), folder);
}

// Item 7: --uploads could name the machine folder (an upload replaced
// startup.lis) or /proc/self.
async function guardedUploads() {
  const programs = path.join(out, "programs");
  fs.mkdirSync(programs, { recursive: true });
  for (const dir of ["examples/mill", "examples", "/proc/self", "/", programs]) {
    const r = await runServe(nck, src, ["examples/mill", "--port", "0", "--no-realtime", "--programs", programs, "--uploads", dir], 3000);
    check(`--uploads ${dir} is refused (exit 2, 940321)`, r.code === 2 && r.stderr.includes("940321"), `${r.code} ${r.signal} ${r.stderr}`);
  }
  const s = await serve(["--uploads", path.join(out, "uploads")]);
  try {
    const slow = "G1 X100 F10\nM30\n";  // ten minutes of feed
    await request(s, "POST", "/api/v1/upload?name=slow.nc", { body: slow });
    await command(s, { command: "load", program: "slow.nc" });
    await command(s, { command: "cycle_start" });
    await sleep(300);
    const replace = await request(s, "POST", "/api/v1/upload?name=slow.nc", { body: "M30\n" });
    check("while a program runs an upload replaces no file (409, 940313)", replace.status === 409 && errorId(replace) === 940313,
          `${replace.status} ${replace.body}`);
    check("the running program's file is unchanged", fs.readFileSync(path.join(out, "uploads", "slow.nc"), "utf8") === slow);
    const other = await request(s, "POST", "/api/v1/upload?name=next.nc", { body: "M30\n" });
    check("a new name is stored meanwhile", other.status === 200, other.body);
  } finally {
    await stopServer(s);
  }
  check("a named uploads folder stays", fs.existsSync(path.join(out, "uploads", "next.nc")));
}

// Item 8: Beast's default body limit (1 MiB) dropped larger uploads
// without a reply whatever --max-program said; too large headers and
// Content-Lengths closed the connection without 431/413; the program's
// text was bounded by its lines' bytes, not by the answer's.
async function requestLimits() {
  const maxProgram = 3 * 1024 * 1024;
  const s = await serve(["--max-program", String(maxProgram)]);
  try {
    const fits = await request(s, "POST", "/api/v1/upload?name=big.nc", { body: ";".repeat(maxProgram) });
    check("an upload of --max-program bytes (3 MiB) is stored", fits.status === 200, `${fits.status} ${fits.body.slice(0, 200)}`);
    const over = await request(s, "POST", "/api/v1/upload?name=over.nc", { body: ";".repeat(maxProgram + 1) });
    check("one byte more -> 413 with 940306", over.status === 413 && errorId(over) === 940306, `${over.status} ${over.body.slice(0, 200)}`);
    const bigCommand = await request(s, "POST", "/api/v1/command", { body: " ".repeat(2 * 1024 * 1024) });
    check("a 2 MiB command -> 413 with 940306", bigCommand.status === 413 && errorId(bigCommand) === 940306, `${bigCommand.status}`);
    const huge = await request(s, "POST", "/api/v1/upload?name=huge.nc",
                               { headers: { "Content-Length": "99999999999" } });
    check("a Content-Length beyond every limit -> 413", huge.status === 413 && errorId(huge) === 940306, `${huge.status} ${huge.body}`);
    const headers = await request(s, "GET", "/api/v1/state", { headers: { "X-Padding": "x".repeat(10 * 1024) } });
    check("headers over 8 KiB -> 431 with 940314", headers.status === 431 && errorId(headers) === 940314, `${headers.status} ${headers.body}`);
    const lower = await request(s, "GET", "/api/v1/state", { headers: { Authorization: `bearer ${s.token}` } });
    check("Authorization: bearer (lower case) is accepted", lower.status === 200, `${lower.status}`);
    const empty = await request(s, "POST", "/api/v1/upload?name=empty-lines.nc", { body: "\n".repeat(maxProgram) });
    const load = await command(s, { command: "load", program: "empty-lines.nc" });
    const page = await request(s, "GET", "/api/v1/program?channel=1");
    const j = JSON.parse(page.body || "{}");
    check("3 MiB of empty lines: the program's answer is at most 2 MiB and names the next page",
          empty.status === 200 && load.status === 200 && page.body.length <= 2 * 1024 * 1024 + 4096 && j.next_line > 1,
          `${page.status} ${page.body.length} bytes, next_line ${j.next_line}`);
    const next = JSON.parse((await request(s, "GET", `/api/v1/program?channel=1&from=${j.next_line}`)).body || "{}");
    check("the next page starts where the first ended", next.first_line === j.next_line && next.lines?.length > 0);
  } finally {
    await stopServer(s);
  }
}

// Item 4: seven sockets that sent nothing took every slot of
// --max-clients 8 (beside the HMI's stream) before any token was checked;
// the operator's stop got 503 for 60 s.
async function idleSockets() {
  const s = await serve(["--max-clients", "8", "--header-timeout", "1.5"]);
  const sockets = [];
  try {
    const stream = readStream(s, 3500);  // the HMI's connection, with the token
    await sleep(200);
    const closedAfter = [];
    for (let i = 0; i < 7; ++i) {
      const t0 = Date.now();
      const sock = net.connect(s.port, "127.0.0.1");
      sock.on("error", () => {});
      sock.on("close", () => closedAfter.push(Date.now() - t0));
      sock.answer = "";
      sock.on("data", (d) => (sock.answer += d));  // reads what comes, so that the server's close is seen
      sockets.push(sock);
    }
    await sleep(300);  // older than the grace in which a browser's connections are not evicted
    const t0 = Date.now();
    const stop = await command(s, { command: "stop" });
    check("seven silent sockets and a stream: the operator's stop is served at once", stop.status === 200 && Date.now() - t0 < 1000,
          `${stop.status} ${stop.body} after ${Date.now() - t0} ms`);
    await sleep(2000);
    check("the silent sockets are closed after the header timeout (1.5 s)", closedAfter.length === 7 &&
          closedAfter.every((ms) => ms < 2600), closedAfter.join());
    // the oldest made room (503, 940316: over 4 per address); the rest timed out (408, 940315)
    check("each silent socket got 503 (940316) or 408 (940315)", sockets.every((x) =>
          (x.answer.includes("503") && x.answer.includes('"id":940316')) || (x.answer.includes("408") && x.answer.includes('"id":940315'))) &&
          sockets.some((x) => x.answer.includes("408")), sockets.map((x) => x.answer.split("\r\n")[0]).join());
    check("the stream with the token stays", (await stream).status === 200);
  } finally {
    sockets.forEach((x) => x.destroy());
    const ended = await stopServer(s, "SIGINT");
    check("SIGINT ends the server with exit 130 (docs/api.md)", ended?.code === 130, JSON.stringify(ended));
  }
}

async function main() {
  await slowSpeeds();
  await firstRunConfinement();
  await privateUploads();
  await guardedUploads();
  await requestLimits();
  await idleSockets();
  finish();
}
main().catch((e) => { console.error(e); process.exit(1); });
