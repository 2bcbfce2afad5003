// The attacks of tests/serve/attack_test.mjs, each an async function of a
// context: ctx.s (the server), ctx.expect(name, cond, detail), ctx.probe(what)
// (the operator's action during the attack), ctx.out (a folder of the test),
// ctx.limits ({maxClients, headerTimeoutMs, maxProgram}), ctx.random().
// An attacker has no token unless the attack says so (a stream needs one).
import { execFileSync } from "node:child_process";
import fs from "node:fs";
import net from "node:net";
import path from "node:path";
import { Worker } from "node:worker_threads";

import { command, errorId, request, sleep } from "./serve_client.mjs";

// A raw TCP connection that records what it gets (up to `keep` bytes) and
// when the server closes it. read: false leaves what comes unread (a frozen client).
export function rawSocket(s, { read = true, keep = 65536 } = {}) {
  const sock = net.connect(s.port, "127.0.0.1");
  const t0 = performance.now();
  sock.answer = "";
  sock.on("error", () => {});
  if (read) sock.on("data", (d) => { if (sock.answer.length < keep) sock.answer += d.toString("latin1"); });
  sock.gone = new Promise((done) => sock.on("close", () => done(performance.now() - t0)));
  sock.connected = new Promise((done) => { sock.on("connect", done); sock.on("error", done); });
  return sock;
}

// Beside another attack (ctx.mixed), a connection without the token may
// be the one that makes room for a newer one: 503 (940308/940316).
const roomMade = (ctx, a) => ctx.mixed && a.status === 503 && (a.id === 940308 || a.id === 940316);

// Status and JSON error ID of the first answer a raw socket got.
export function firstAnswer(text) {
  const status = Number((/^HTTP\/1\.1 (\d{3})/.exec(text) || [])[1] || 0);
  const body = text.slice(text.indexOf("\r\n\r\n") + 4);
  const m = /"error":\{"id":(\d+)/.exec(body);
  return { status, id: m ? Number(m[1]) : null };
}

// Every answer of a raw socket: [{status, id}] (a pipelined connection gets many).
function allAnswers(text) {
  return [...text.matchAll(/HTTP\/1\.1 (\d{3})[^]*?\r\n\r\n(\{"error":\{"id":(\d+))?/g)]
    .map((m) => ({ status: Number(m[1]), id: m[3] ? Number(m[3]) : null }));
}

const head = (s, target, lines = []) =>
  [`GET ${target} HTTP/1.1`, `Host: 127.0.0.1:${s.port}`, ...lines].join("\r\n") + "\r\n\r\n";

// Waits for every socket's close, at most `ms`; the times (ms from each one's start, null: still open).
async function closings(socks, ms) {
  const limit = sleep(ms).then(() => null);
  return Promise.all(socks.map((x) => Promise.race([x.gone, limit])));
}

// Headers dribbled a byte every 50 ms by a dozen connections, never ending:
// each must be closed after the header timeout (408) or make room for a newer one (503).
export async function slowloris(ctx) {
  const { s } = ctx;
  const text = `GET /api/v1/state HTTP/1.1\r\nHost: 127.0.0.1:${s.port}\r\nAuthorization: Bearer ${"0".repeat(32)}\r\nX-Slow: `;
  const socks = Array.from({ length: 12 }, () => rawSocket(s));
  let i = 0;
  const timer = setInterval(() => {
    for (const x of socks) if (!x.destroyed) x.write(i < text.length ? text[i] : "a");
    ++i;
  }, 50);
  try {
    await sleep(400);  // past the grace in which new connections are not evicted
    await ctx.probe("during slowloris");
    const closed = await closings(socks, ctx.limits.headerTimeoutMs + 1500);
    const answers = socks.map((x) => firstAnswer(x.answer));
    ctx.expect("slowloris: every dribbling connection is closed within the header timeout + 1 s",
               closed.every((ms) => ms !== null && ms < ctx.limits.headerTimeoutMs + 1000), closed.map((ms) => ms && Math.round(ms)).join());
    ctx.expect("slowloris: each got 408 (940315) or 503 (940316/940308)", answers.every(({ status, id }) =>
      (status === 408 && id === 940315) || (status === 503 && (id === 940316 || id === 940308))),
               answers.map((a) => `${a.status}/${a.id}`).join());
  } finally {
    clearInterval(timer);
    socks.forEach((x) => x.destroy());
  }
}

// Commands whose body is slow to come, with five newer connections from
// the same address meanwhile. Without the token: refused (401) as soon as
// the header is in, before the body. With it: the header makes the
// connection a client, no newcomer takes its place, and it gets one answer.
export async function slowBody(ctx) {
  const { s } = ctx;
  const percent = 7 + Math.floor(ctx.random() * 40);  // below every value the operator sets
  const body = `{"command":"feed_override","percent":${percent}}`;
  const post = (lines) => [`POST /api/v1/command HTTP/1.1`, `Host: 127.0.0.1:${s.port}`, ...lines,
    `Content-Length: ${body.length}`].join("\r\n") + "\r\n\r\n" + body.slice(0, 20);
  const stranger = rawSocket(s), client = rawSocket(s);
  await Promise.all([stranger.connected, client.connected]);
  stranger.write(post([]));
  client.write(post([`Authorization: Bearer ${s.token}`]));
  await sleep(350);  // older than the grace in which a new connection is spared
  const early = firstAnswer(stranger.answer);
  const newer = Array.from({ length: 5 }, () => rawSocket(s));
  try {
    await sleep(200);
    client.write(body.slice(20));
    for (let i = 0; i < 100 && !/\r\n\r\n/.test(client.answer); ++i) await sleep(10);
    await sleep(50);
    const answers = allAnswers(client.answer);
    const st = JSON.parse((await request(s, "GET", "/api/v1/state", { timeout: 2000 })).body || "{}");
    ctx.expect("slow body without the token: 401 before the body came", (early.status === 401 && early.id === 940304) || roomMade(ctx, early),
               JSON.stringify(stranger.answer.slice(0, 200)));
    // beside a flood another attack's connection may take the place first
    ctx.expect("slow body with the token: one answer, 200", answers.length === 1 && (answers[0].status === 200 || ctx.mixed),
               JSON.stringify(client.answer.slice(0, 400)));
    if (answers[0]?.status === 200)
      ctx.expect(`slow body with the token: feed override ${percent} % applied`, st.channels?.[0].feed_override_pct === percent,
                 `${st.channels?.[0].feed_override_pct}`);
  } finally {
    [stranger, client, ...newer].forEach((x) => x.destroy());
  }
}

// More silent connections than --max-clients: the operator still gets in,
// and the silent ones are gone after the header timeout.
export async function idleFill(ctx) {
  const socks = Array.from({ length: ctx.limits.maxClients + 4 }, () => rawSocket(ctx.s));
  try {
    await sleep(300);
    await ctx.probe("beside silent connections");
    const closed = await closings(socks, ctx.limits.headerTimeoutMs + 1500);
    ctx.expect(`idle: ${socks.length} silent connections closed within the header timeout + 1 s`,
               closed.every((ms) => ms !== null && ms < ctx.limits.headerTimeoutMs + 1000), closed.map((ms) => ms && Math.round(ms)).join());
  } finally {
    socks.forEach((x) => x.destroy());
  }
}

// New connections from the same address as fast as they open, for 1.5 s
// (flood_worker.mjs, in a thread of its own): silent ones, ones with a
// request without the token, ones closed at once; or (oneByte) each with
// the first byte of a request. The operator acts in the middle of it.
async function flood(ctx, oneByte) {
  const worker = new Worker(new URL("./flood_worker.mjs", import.meta.url), { workerData: { port: ctx.s.port, ms: 1500, oneByte } });
  const opened = new Promise((done, fail) => { worker.on("message", done); worker.on("error", fail); });
  const what = oneByte ? "a flood of connections sending one byte" : "a connection flood";
  await sleep(500);
  await ctx.probe(`during ${what}`);
  await sleep(300);
  await ctx.probe(`during ${what} (later)`);
  const n = await opened;
  ctx.expect(`${what}: ${n} connections opened in 1.5 s`, n > 100, `${n}`);
  ctx.note(oneByte ? "one_byte_flood_connections" : "flood_connections", n);
}
export const connectionFlood = (ctx) => flood(ctx, false);
export const oneByteFlood = (ctx) => flood(ctx, true);

// Pipelined requests on one connection: without the token (401, then 429
// past the rate), with it (200, then 429), and a pipeline whose answers are
// never read (the server's writes block; the operator is not held up).
export async function requestFlood(ctx) {
  const { s } = ctx;
  for (const [who, lines] of [["without the token", []], ["with the token", [`Authorization: Bearer ${s.token}`]]]) {
    const x = rawSocket(s, { keep: 1 << 20 });
    const n = 300, t0 = performance.now();
    x.write(head(s, "/api/v1/state", lines).repeat(n));
    for (let i = 0; i < 100 && allAnswers(x.answer).length < n; ++i) await sleep(20);
    const seconds = (performance.now() - t0) / 1000;
    const answers = allAnswers(x.answer);
    const served = answers.filter((a) => a.status === (lines.length ? 200 : 401)).length;
    const limited = answers.filter((a) => a.status === 429 && a.id === 940307).length;
    x.destroy();
    // beside a flood the connection without the token may make room: its last answer is then the 503
    const cut = !lines.length && answers.length > 0 && roomMade(ctx, answers.at(-1));
    ctx.expect(`request flood ${who}: ${n} pipelined requests all answered, ${served} served, ${limited} 429`,
               (cut || (answers.length === n && limited > 0)) && served + limited === answers.length - (cut ? 1 : 0) &&
               served <= 50 + 50 * seconds + 1,
               `${answers.length} answers, ${served} served, ${limited} limited in ${seconds.toFixed(2)} s`);
  }
  const deaf = rawSocket(s, { read: false });
  await deaf.connected;
  const chunk = head(s, "/api/v1/errors").repeat(200);  // each answer is ~60 KB
  for (let i = 0; i < 50; ++i) deaf.write(chunk);
  try {
    await sleep(300);
    await ctx.probe("beside a pipeline that never reads its answers");
  } finally {
    deaf.destroy();
  }
}

// Stream clients (with the token) that never read: the server drops each
// once it owes 64 frames, so they neither hold a slot for long nor grow its
// memory. The operator acts meanwhile. After the hold they read again: a
// dropped client reads its backlog to the end, a live one gets frames on.
export async function frozenStreams(ctx) {
  const { s } = ctx;
  // three: with the two of keyFlood and the operator's two they stay within --max-clients 8
  const socks = Array.from({ length: 3 }, () => rawSocket(s, { read: false }));
  await Promise.all(socks.map((x) => x.connected));
  socks.forEach((x) => x.write(head(s, "/api/v1/stream", [`Authorization: Bearer ${s.token}`])));
  try {
    await sleep(500);
    await ctx.probe("beside three frozen streams");
    await sleep(ctx.limits.frozenStreamMs - 500);
    const ended = await Promise.all(socks.map((x) => new Promise((done) => {
      x.on("end", () => done(true));
      x.resume();
      setTimeout(() => done(false), 2000);
    })));
    ctx.expect(`frozen streams: all three dropped by the server within ${ctx.limits.frozenStreamMs} ms`, ended.every(Boolean),
               ended.join());
  } finally {
    socks.forEach((x) => x.destroy());
  }
}

// Sends `text` on a raw connection and waits for the first answer (or the close).
async function exchange(s, text, ms = 3000) {
  const x = rawSocket(s);
  await x.connected;
  x.write(text);
  const t0 = performance.now();
  while (performance.now() - t0 < ms && !/\r\n\r\n/.test(x.answer) && !x.destroyed && x.readable) await sleep(10);
  await Promise.race([x.gone, sleep(50)]);
  x.destroy();
  return { ...firstAnswer(x.answer), text: x.answer };
}

// Too large headers (431, 940314) and bodies (413, 940306), with and
// without the token, declared or chunked: each a JSON refusal.
export async function oversized(ctx) {
  const { s } = ctx;
  const auth = `Authorization: Bearer ${s.token}`;
  const post = (target, lines, body = "") =>
    [`POST ${target} HTTP/1.1`, `Host: 127.0.0.1:${s.port}`, ...lines].join("\r\n") + "\r\n\r\n" + body;
  const chunked = (n) => `${n.toString(16)}\r\n${"x".repeat(n)}\r\n`;
  const cases = [
    ["one 10 KiB header", head(s, "/api/v1/state", [`X-Pad: ${"x".repeat(10240)}`]), 431, 940314],
    ["one 10 KiB header with the token", head(s, "/api/v1/state", [auth, `X-Pad: ${"x".repeat(10240)}`]), 431, 940314],
    ["600 small headers", head(s, "/api/v1/state", Array.from({ length: 600 }, (_, i) => `X-H${i}: 0123456789`)), 431, 940314],
    ["a 10 KiB target", head(s, `/api/v1/state?${"q".repeat(10240)}`), 431, 940314],
    ["Content-Length 100 KiB to a command", post("/api/v1/command", [auth, "Content-Length: 102400"]), 413, 940306],
    ["Content-Length 10^20", post("/api/v1/command", [auth, "Content-Length: 100000000000000000000"]), 413, 940306],
    ["an upload one byte over --max-program", post("/api/v1/upload?name=over.nc", [auth, `Content-Length: ${ctx.limits.maxProgram + 1}`]), 413, 940306],
    ["a chunked command of 100 KiB", post("/api/v1/command", [auth, "Transfer-Encoding: chunked"], chunked(60000) + chunked(60000) + "0\r\n\r\n"), 413, 940306],
    // without the token the header is refused before any of the body is read
    ["a chunked command without the token", post("/api/v1/command", ["Transfer-Encoding: chunked"], chunked(60000) + chunked(60000) + "0\r\n\r\n"), 401, 940304],
    ["an upload of --max-program bytes without the token", post("/api/v1/upload?name=x.nc", [`Content-Length: ${ctx.limits.maxProgram}`]), 401, 940304],
  ];
  for (const [what, text, status, id] of cases) {
    const a = await exchange(s, text);
    ctx.expect(`oversized: ${what} -> ${status} (${id})`, (a.status === status && a.id === id) || roomMade(ctx, a),
               `${a.status}/${a.id} ${a.text.slice(0, 120)}`);
  }
}

// Command bodies that are no JSON object, or one with a key twice: 400
// with 940300 (or 940301..940303 for a well-formed object that is no
// command), never anything else.
export async function malformed(ctx) {
  const { s } = ctx;
  const random = Array.from({ length: 24 }, () => Buffer.from(Array.from({ length: 1 + Math.floor(ctx.random() * 200) },
    () => Math.floor(ctx.random() * 256))).toString("latin1"));
  const bodies = ["", " ", "{", "}", "[]", "null", "1e999", '"stop"', '{"command":"stop"} {}', '{"command":"stop"}x',
    '{"command":"stop",}', "{'command':'stop'}", '{"command":"st\\ud800op"}', "[".repeat(30000),
    '{"a":'.repeat(10000) + "1" + "}".repeat(10000), '{"command":"feed_override","percent":1' + "0".repeat(400) + "}",
    '{"command":"feed_override","percent":NaN}', '{"command":"\u0000stop"}', '{"command":["stop"]}', ...random];
  let bad = [];
  for (const body of bodies) {
    const r = await command(s, {}, { body, timeout: 3000 });
    const id = errorId(r);
    if (!(r.status === 400 && id >= 940300 && id <= 940303)) bad.push(`${JSON.stringify(body.slice(0, 30))}: ${r.status}/${id}`);
  }
  ctx.expect(`malformed: ${bodies.length} bodies that are no command -> 400 with 9403xx`, bad.length === 0, bad.slice(0, 4).join("; "));
  const twice = ['{"command":"stop","command":"reset"}', '{"command":"feed_override","percent":50,"percent":150}',
    '{"command":"feed_override","channel":1,"channel":1,"percent":50}', '{"command":"stop","comm\\u0061nd":"reset"}',
    '{"command":"action","line":"x","x":{"a":1,"a":2}}'];
  bad = [];
  for (const body of twice) {
    const r = await command(s, {}, { body, timeout: 3000 });
    if (!(r.status === 400 && errorId(r) === 940300)) bad.push(`${body}: ${r.status}/${errorId(r)}`);
  }
  ctx.expect(`duplicate keys: ${twice.length} objects with a key twice -> 400 (940300)`, bad.length === 0, bad.join("; "));
}

// The most keys a command may hold: one object of 64 KiB of distinct short keys.
function manyKeys() {
  const keys = [];
  for (let i = 0, n = 12; n < 65000; ++i) { keys.push(`"${i.toString(36)}":0`); n += keys.at(-1).length + 1; }
  return `{${keys.join(",")}}`;
}

// Two connections with the token (a client gone mad) pipelining objects
// of 8,000 keys at the rate the server allows: each costs the server's one
// thread its parse, and the operator must still get through.
export async function keyFlood(ctx) {
  const { s } = ctx;
  const body = manyKeys();
  const post = [`POST /api/v1/command HTTP/1.1`, `Host: 127.0.0.1:${s.port}`, `Authorization: Bearer ${s.token}`,
    `Content-Length: ${Buffer.byteLength(body)}`].join("\r\n") + "\r\n\r\n" + body;
  const socks = Array.from({ length: 2 }, () => rawSocket(s, { keep: 1 << 20 }));
  await Promise.all(socks.map((x) => x.connected));
  const t0 = performance.now();
  socks.forEach((x) => x.write(post.repeat(60)));
  try {
    await sleep(300);
    await ctx.probe("beside two connections sending 8,000-key objects");
    await sleep(700);
  } finally {
    socks.forEach((x) => x.destroy());
  }
  const seconds = (performance.now() - t0) / 1000;
  const refused = socks.map((x) => allAnswers(x.answer).filter((a) => a.status === 400).length);
  ctx.note("key_objects_per_s", refused.reduce((a, b) => a + b, 0) / seconds);
  ctx.expect(`key flood: each connection's objects refused (400): ${refused.join(", ")} in ${seconds.toFixed(1)} s`,
             ctx.mixed || refused.every((n) => n > 0));
}

// The files of the path tricks: a programs folder with a program, a link
// out of it, a FIFO, and a secret outside every folder the server may read.
export function pathTrickFiles(out) {
  const programs = path.join(out, "programs"), outside = path.join(out, "outside");
  fs.mkdirSync(programs, { recursive: true });
  fs.mkdirSync(outside, { recursive: true });
  fs.writeFileSync(path.join(outside, "secret.nc"), "SECRET_WORD_4711\nM30\n");
  fs.writeFileSync(path.join(programs, "victim.nc"), "G0 X1\nM30\n");
  fs.symlinkSync(path.join(outside, "secret.nc"), path.join(programs, "link-out.nc"));
  fs.symlinkSync(outside, path.join(programs, "dir-out"));
  execFileSync("mkfifo", [path.join(programs, "fifo.nc")]);
  return { programs, outside };
}

const leaks = (text) => /SECRET_WORD_4711|root:x:0:0/.test(text);

// Program names that lead out of the folders (.., %2e%2e, absolute paths,
// links, NUL bytes, devices, a FIFO) for load; upload names that are no
// plain name; odd channel and line numbers for the program text; paths of
// the page that lead out. Every one refused, none quotes a secret.
export async function pathTricks(ctx) {
  const { s } = ctx;
  const { programs, outside } = ctx.files;
  await command(s, { command: "reset" });
  await sleep(100);
  const names = ["../outside/secret.nc", "%2e%2e/outside/secret.nc", "..%2foutside%2fsecret.nc", "/etc/passwd",
    path.join(outside, "secret.nc"), path.join(programs, "..", "outside", "secret.nc"), `${programs}/./../outside/secret.nc`,
    "link-out.nc", "dir-out/secret.nc", "victim.nc\u0000.txt", "/proc/self/environ", "/dev/zero", "fifo.nc", "sub/../../outside/secret.nc",
    "victim.nc/", ".", "/", "x".repeat(1024), "C:\\Windows\\win.ini", "\\\\host\\share\\x.nc"];
  let wrong = [];
  for (const program of names) {
    const r = await command(s, { command: "load", program }, { timeout: 3000 });
    if (!(r.status === 400 && errorId(r) === 940309) || leaks(r.body)) wrong.push(`${program.slice(0, 40)}: ${r.status}/${errorId(r)}`);
  }
  ctx.expect(`path tricks: ${names.length} program names out of the folders -> 400 (940309)`, wrong.length === 0, wrong.join("; "));
  const uploads = ["../x.nc", "%2e%2e%2fx.nc", "..", "/tmp/x.nc", "a/b.nc", ".hidden", "x%00y.nc", "", "y".repeat(65),
    "link-out.nc/../../x.nc", "con:x"];
  wrong = [];
  for (const name of uploads) {
    const r = await request(s, "POST", `/api/v1/upload?name=${name}`, { body: "M30\n", timeout: 3000 });
    if (r.status !== 400 || errorId(r) !== 940309) wrong.push(`${JSON.stringify(name).slice(0, 30)}: ${r.status}/${errorId(r)}`);
  }
  ctx.expect(`path tricks: ${uploads.length} upload names that are no plain name -> 400 (940309)`, wrong.length === 0, wrong.join("; "));
  ctx.expect("path tricks: no upload landed outside the uploads folder",
             !fs.existsSync(path.join(ctx.out, "x.nc")) && !fs.existsSync("/tmp/x.nc") && !fs.existsSync(path.join(programs, "x.nc")));
  const queries = ["channel=0", "channel=-1", "channel=2", "channel=99999999999999999999", "channel=1;2", "channel=1&from=0",
    "channel=1&from=-1", "channel=1&from=abc", "channel=1&from=1e99", "channel=1&from=99999999999999999999", "channel=../1"];
  wrong = [];
  for (const q of queries) {
    const r = await request(s, "GET", `/api/v1/program?${q}`, { timeout: 3000 });
    if (r.status === 0 || r.status >= 500 || leaks(r.body)) wrong.push(`${q}: ${r.status}`);
  }
  ctx.expect(`path tricks: ${queries.length} odd program queries answered without a leak`, wrong.length === 0, wrong.join("; "));
  const targets = ["/../../etc/passwd", "/%2e%2e/%2e%2e/etc/passwd", "//etc/passwd", "/api/v1/../../etc/passwd",
    "/hmi.js/../../../etc/passwd", "/hmi.js%00.html", "/api/v1/program/../../../etc/passwd", "/?token=../../etc/passwd"];
  wrong = [];
  for (const t of targets) {
    const r = await request(s, "GET", t, { timeout: 3000 });
    if (![401, 404].includes(r.status) || leaks(r.body)) wrong.push(`${t}: ${r.status}`);
  }
  ctx.expect(`path tricks: ${targets.length} page paths out of the page -> 401/404`, wrong.length === 0, wrong.join("; "));
  await swappedProgram(ctx);
}

// A loaded program replaced by a link out of the folders, then by a FIFO:
// the program's text must not follow the link nor wait on the FIFO (the
// server's one thread would hang in open()).
async function swappedProgram(ctx) {
  const { s } = ctx;
  const { programs, outside } = ctx.files;
  const victim = path.join(programs, "victim.nc");
  const load = await command(s, { command: "load", program: "victim.nc" }, { timeout: 3000 });
  ctx.expect("path tricks: a program of the programs folder loads", load.status === 200, load.body);
  try {
    fs.rmSync(victim);
    fs.symlinkSync(path.join(outside, "secret.nc"), victim);
    const linked = await request(s, "GET", "/api/v1/program?channel=1", { timeout: 3000 });
    ctx.expect("path tricks: the loaded program swapped for a link out: its text is not served", !leaks(linked.body),
               `${linked.status} ${linked.body.slice(0, 160)}`);
    fs.rmSync(victim);
    execFileSync("mkfifo", [victim]);
    const fifo = await request(s, "GET", "/api/v1/program?channel=1", { timeout: 2000 });
    ctx.expect("path tricks: the loaded program swapped for a FIFO: answered at once", fifo.status !== 0, `${fifo.status} ${fifo.body}`);
  } finally {
    // a writer releases a server stuck in open() on the FIFO, so that the rest of the test runs
    try { fs.writeFileSync(victim, "", { flag: fs.constants.O_WRONLY | fs.constants.O_NONBLOCK }); } catch { /* no reader */ }
    fs.rmSync(victim, { force: true });
    fs.writeFileSync(victim, "G0 X1\nM30\n");
  }
  await ctx.restartProgram();
}

// Bytes that are no HTTP: each connection is answered 4xx or closed, and
// the server lives on.
export async function badHttp(ctx) {
  const { s } = ctx;
  const random = Buffer.from(Array.from({ length: 4096 }, () => Math.floor(ctx.random() * 256))).toString("latin1");
  const texts = [random, "\r\n".repeat(5000), "GET\r\n\r\n", "GET / HTTP/0.9\r\n\r\n", "GET / HTTP/9.9\r\n\r\n",
    `BREW /api/v1/state HTTP/1.1\r\nHost: 127.0.0.1:${s.port}\r\n\r\n`, `GET /\0 HTTP/1.1\r\nHost: 127.0.0.1:${s.port}\r\n\r\n`,
    `POST /api/v1/command HTTP/1.1\r\nHost: 127.0.0.1:${s.port}\r\nContent-Length: 5\r\nTransfer-Encoding: chunked\r\n\r\n0\r\n\r\n`,
    `POST /api/v1/command HTTP/1.1\r\nHost: 127.0.0.1:${s.port}\r\nTransfer-Encoding: chunked\r\n\r\nffffffffffffffff\r\n`,
    `POST /api/v1/command HTTP/1.1\r\nHost: 127.0.0.1:${s.port}\r\nContent-Length: 2\r\nContent-Length: 3\r\n\r\nabc`,
    `GET /api/v1/state HTTP/1.1\r\nHost: 127.0.0.1:${s.port}\r\nHost: evil.example\r\n\r\n`,
    `GET /api/v1/state HTTP/1.1\r\nHost: 127.0.0.1:${s.port}\r\n X-Folded: y\r\n\r\n`];
  const wrong = [];
  for (const text of texts) {
    const a = await exchange(s, text, 1500);
    if (a.status !== 0 && (a.status < 400 || a.status >= 500) && a.status !== 503) wrong.push(`${JSON.stringify(text.slice(0, 30))}: ${a.status}`);
  }
  ctx.expect(`bad HTTP: ${texts.length} byte sequences -> 4xx or closed`, wrong.length === 0, wrong.join("; "));
}

export const attacks = { slowloris, slowBody, idleFill, connectionFlood, oneByteFlood, requestFlood, frozenStreams, oversized, malformed, keyFlood, pathTricks,
                         badHttp };
