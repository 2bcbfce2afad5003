// What the serve tests share (tests/serve/*.mjs): their arguments, checks,
// a server started on a free port of 127.0.0.1 and requests to it
// (node's http module only).
import { spawn } from "node:child_process";
import fs from "node:fs";
import http from "node:http";
import path from "node:path";

// --nck BIN --source DIR --out DIR (the out folder starts empty).
export function testArgs(defaultOut) {
  const args = Object.fromEntries(process.argv.slice(2).reduce((acc, a, i, all) => {
    if (a.startsWith("--")) acc.push([a.slice(2), all[i + 1] ?? "1"]);
    return acc;
  }, []));
  const out = path.resolve(args.out || defaultOut);
  fs.rmSync(out, { recursive: true, force: true });
  fs.mkdirSync(out, { recursive: true });
  return { nck: path.resolve(args.nck), src: path.resolve(args.source || "."), out };
}

let failures = 0;
export const check = (name, cond, detail = "") => {
  if (cond) console.log(`ok   ${name}`);
  else { failures++; console.error(`FAIL ${name} ${detail}`); }
};
// Prints the summary and exits 1 when a check failed.
export function finish() {
  console.log(failures ? `${failures} check(s) failed` : "all checks passed");
  process.exit(failures ? 1 : 0);
}
export const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

// `nck serve MACHINE --port 0 --no-realtime ...extra` in `cwd`; resolves with
// {port, token, proc, exited, stderr()} once it printed its URL. exited:
// a promise of {code, signal}.
export function startServer(nck, cwd, extra, machine = "examples/mill") {
  return new Promise((resolve, reject) => {
    const proc = spawn(nck, ["serve", machine, "--port", "0", "--no-realtime", ...extra], { cwd });
    let text = "", err = "";
    const exited = new Promise((done) => proc.on("exit", (code, signal) => done({ code, signal })));
    proc.stderr.on("data", (d) => { err += d; process.stderr.write(d); });
    proc.stdout.on("data", (d) => {
      text += d;
      const m = text.match(/http:\/\/127\.0\.0\.1:(\d+)\/\?token=([0-9a-f]+)/);
      if (m) resolve({ port: Number(m[1]), token: m[2], proc, exited, stderr: () => err });
    });
    proc.on("exit", (code) => reject(new Error(`nck serve exited ${code} before its URL: ${err}`)));
  });
}

// `nck serve ...args` that is expected to end by itself: {code, signal, stdout, stderr}
// (killed after `ms`).
export function runServe(nck, cwd, args, ms = 10000) {
  return new Promise((resolve) => {
    const proc = spawn(nck, ["serve", ...args], { cwd });
    let stdout = "", stderr = "";
    proc.stdout.on("data", (d) => (stdout += d));
    proc.stderr.on("data", (d) => (stderr += d));
    const timer = setTimeout(() => proc.kill("SIGKILL"), ms);
    proc.on("exit", (code, signal) => { clearTimeout(timer); resolve({ code, signal, stdout, stderr }); });
  });
}

// NCK_API_RECORD=FILE: every answered request is appended to FILE as one
// JSON line, for tests/serve/openapi_check.py (ctest serve.openapi).
function record(method, target, body, res, data) {
  if (!process.env.NCK_API_RECORD) return;
  const line = { method, target, status: res.statusCode, type: res.headers["content-type"] || "", request: body ?? null,
                 answer: data.length <= 1 << 20 ? data : null };
  fs.appendFileSync(process.env.NCK_API_RECORD, JSON.stringify(line) + "\n");
}

// One request; resolves with {status, headers, body} (status 0 and the
// error as body on a reset connection). agent: an http.Agent for
// keep-alive, else a connection of its own. timeout: ms until the request
// is given up (status 0), so that a server that hangs fails a check.
export function request(s, method, target, { body, headers = {}, token = true, host, agent = false, timeout } = {}) {
  return new Promise((resolve) => {
    const h = host === "" ? { ...headers } : { Host: host ?? `127.0.0.1:${s.port}`, ...headers };
    if (token && !h.Authorization) h.Authorization = `Bearer ${s.token}`;
    if (body !== undefined) h["Content-Length"] = Buffer.byteLength(body);
    const req = http.request({ host: "127.0.0.1", port: s.port, method, path: target, headers: h,
                               setHost: false, agent }, (res) => {
      let data = "";
      res.on("data", (c) => (data += c));
      res.on("end", () => {
        record(method, target, body, res, data);
        resolve({ status: res.statusCode, headers: res.headers, body: data });
      });
      res.on("error", () => resolve({ status: res.statusCode, headers: res.headers, body: data }));
    });
    req.on("error", (e) => resolve({ status: 0, headers: {}, body: String(e) }));
    if (timeout) req.setTimeout(timeout, () => req.destroy(new Error(`no answer within ${timeout} ms`)));
    if (body !== undefined) req.write(body);
    req.end();
  });
}
export const command = (s, obj, opts = {}) => request(s, "POST", "/api/v1/command", { body: JSON.stringify(obj), ...opts });
export const state = async (s) => JSON.parse((await request(s, "GET", "/api/v1/state")).body);
export const errorId = (r) => { try { return JSON.parse(r.body).error.id; } catch { return null; } };

// Reads a stream for `ms`; resolves with {status, text}.
export function readStream(s, ms, headers = {}) {
  return new Promise((resolve) => {
    let text = "";
    const req = http.get({ host: "127.0.0.1", port: s.port, path: "/api/v1/stream", agent: false,
                           headers: { Host: `127.0.0.1:${s.port}`, Authorization: `Bearer ${s.token}`, ...headers } }, (res) => {
      res.on("data", (c) => (text += c));
      setTimeout(() => { req.destroy(); resolve({ status: res.statusCode, text }); }, ms);
    });
    req.on("error", () => resolve({ status: 0, text }));
  });
}

// Stops a server with `signal` and resolves with its exit {code, signal}, or null when it
// did not end within `ms` (then it is killed).
export async function stopServer(s, signal = "SIGTERM", ms = 5000) {
  s.proc.kill(signal);
  const ended = await Promise.race([s.exited, sleep(ms).then(() => null)]);
  if (!ended) s.proc.kill("SIGKILL");
  return ended;
}
