// nck serve under load (issue 28's performance figures; not part of ctest):
// examples/mill/contour.nc in a loop at real time, 5 stream clients, one of
// them sending 40 commands per second, for --minutes (default 10). Prints
// the kernel's cycle lateness (p50, p99, worst, cycles later than one cycle),
// the scheduling class its thread got, the stream rate each client saw, the
// page load time and the process's peak RSS.
//   node bench/serve_lateness.mjs --nck build/release/nck [--minutes 10]
import { execFileSync, spawn } from "node:child_process";
import fs from "node:fs";
import http from "node:http";
import path from "node:path";

const args = Object.fromEntries(process.argv.slice(2).reduce((acc, a, i, all) => {
  if (a.startsWith("--")) acc.push([a.slice(2), all[i + 1] ?? "1"]);
  return acc;
}, []));
const nck = path.resolve(args.nck || "build/release/nck");
const minutes = Number(args.minutes || 10);
const root = path.resolve(path.dirname(new URL(import.meta.url).pathname), "..");

const server = spawn(nck, ["serve", "examples/mill", "examples/mill/contour.nc", "--port", "0"], { cwd: root });
server.stderr.on("data", (d) => process.stderr.write(d));
const { port, token } = await new Promise((resolve) => {
  let text = "";
  server.stdout.on("data", (d) => {
    text += d;
    const m = text.match(/:(\d+)\/\?token=([0-9a-f]+)/);
    if (m) resolve({ port: Number(m[1]), token: m[2] });
  });
});
const headers = { Host: `127.0.0.1:${port}`, Authorization: `Bearer ${token}` };
const agent = new http.Agent({ keepAlive: true, maxSockets: 1 });
const call = (method, p, body) => new Promise((resolve) => {
  const req = http.request({ host: "127.0.0.1", port, method, path: p, agent, headers: { ...headers, "Content-Length": body ? Buffer.byteLength(body) : 0 } }, (res) => {
    let data = "";
    res.on("data", (c) => (data += c));
    res.on("end", () => resolve({ status: res.statusCode, body: data }));
  });
  req.on("error", () => resolve({ status: 0, body: "" }));
  if (body) req.write(body);
  req.end();
});
const command = (obj) => call("POST", "/api/v1/command", JSON.stringify(obj));

// Five stream clients counting states.
const counts = [0, 0, 0, 0, 0];
const streams = counts.map((_, i) => http.get({ host: "127.0.0.1", port, path: "/api/v1/stream", agent: false, headers }, (res) => {
  res.on("data", (c) => { counts[i] += (String(c).match(/event: state/g) || []).length; });
}));

const pageStart = Date.now();
await new Promise((resolve) => http.get({ host: "127.0.0.1", port, path: "/", agent: false, headers: { Host: headers.Host } }, (res) => { res.resume(); res.on("end", resolve); }));
const pageMs = Date.now() - pageStart;

// One client: 40 commands per second (overrides), restarting the program whenever it ended.
const t0 = Date.now(), end = t0 + minutes * 60000;
let sent = 0, refused = 0, restarts = 0;
while (Date.now() < end) {
  const r = await command({ command: "feed_override", percent: 50 + (sent % 50) });
  sent++;
  if (r.status !== 200) refused++;
  if (sent % 40 === 0) {
    const s = JSON.parse((await call("GET", "/api/v1/state")).body);
    if (["ended", "idle", "error"].includes(s.channels[0].state)) { await command({ command: "cycle_start" }); restarts++; }
  }
  await new Promise((r2) => setTimeout(r2, 25));
}
const state = JSON.parse((await call("GET", "/api/v1/state")).body);
const seconds = (Date.now() - t0) / 1000;
let sched = "?";
try {
  sched = execFileSync("ps", ["-L", "-o", "cls=,rtprio=", "-p", String(server.pid)]).toString().split("\n")
    .map((l) => l.trim()).filter((l) => l && !l.startsWith("TS")).join(" | ") || "TS only (no real-time thread)";
} catch { /* ps missing */ }
const status = fs.readFileSync(`/proc/${server.pid}/status`, "utf8");
const rss = (status.match(/VmHWM:\s+(\d+) kB/) || [])[1];
streams.forEach((s) => s.destroy());
server.kill("SIGTERM");
agent.destroy();
const l = state.lateness;
console.log(JSON.stringify({
  minutes, wakeups: l.wakeups, p50_us: l.p50_us, p99_us: l.p99_us, worst_us: l.worst_us, late_cycles: l.late_cycles,
  realtime_threads: sched, commands_sent: sent, commands_refused: refused, program_restarts: restarts,
  stream_states_per_s: counts.map((c) => +(c / seconds).toFixed(1)), page_load_ms: pageMs, peak_rss_mib: rss ? +(rss / 1024).toFixed(1) : null,
}, null, 1));
