// The HMI's link to `nck serve` (docs/api.md): JSON requests, commands, the
// server-sent-events stream, and a throttle so that a dragged slider stays
// well under the server's 50 requests/s per connection.
(function () {
  "use strict";

  // An answer with {"error": DIAGNOSTIC} (docs/api.md) becomes this.
  class ApiError extends Error {
    constructor(status, body) {
      const e = (body && body.error) || {};
      super(e.message || "HTTP " + status);
      this.status = status;
      this.id = e.id;
      this.remedy = e.remedy || "";
      this.diagnostic = e;
    }
  }

  async function request(method, path, body) {
    const init = { method, credentials: "same-origin", headers: {} };
    if (body !== undefined) {
      init.body = typeof body === "string" ? body : JSON.stringify(body);
      init.headers["Content-Type"] = typeof body === "string" ? "text/plain" : "application/json";
    }
    const r = await fetch(path, init);
    let j = null;
    try { j = await r.json(); } catch (_) { /* an empty or non-JSON answer */ }
    if (!r.ok) throw new ApiError(r.status, j);
    return j;
  }

  const get = (path) => request("GET", path);
  const command = (name, channel, fields) => request("POST", "/api/v1/command", { command: name, channel, ...fields });
  // The machine's inputs: POST /api/v1/estop or /api/v1/machine_on with {on}.
  const machineInput = (name, on) => request("POST", "/api/v1/" + name, { on });
  // Homing (G74 through MDI): POST /api/v1/home; axes omitted = all path axes.
  const home = (channel, axes) => request("POST", "/api/v1/home", axes ? { channel, axes } : { channel });
  const upload = (name, text) => request("POST", "/api/v1/upload?name=" + encodeURIComponent(name), text);

  // Calls fn at most once per `ms` with the latest arguments; the last call
  // always goes out (the slider's final value is the one that counts).
  function throttle(fn, ms) {
    let last = 0, timer = null, args = null;
    return (...a) => {
      args = a;
      const wait = last + ms - Date.now();
      if (wait <= 0 && !timer) {
        last = Date.now();
        fn(...args);
        return;
      }
      if (timer) return;
      timer = setTimeout(() => { timer = null; last = Date.now(); fn(...args); }, Math.max(0, wait));
    };
  }

  // The stream: `machine` once, then `state` snapshots and `events` batches;
  // `run` before the first event of a new run.
  // Counts snapshots so the page (and its test) can tell the rate it gets.
  function stream(handlers) {
    const stats = { snapshots: 0, since: performance.now(), rate: 0, connected: false };
    const es = new EventSource("/api/v1/stream");
    es.addEventListener("machine", (m) => handlers.machine && handlers.machine(JSON.parse(m.data)));
    es.addEventListener("state", (m) => {
      stats.snapshots++;
      handlers.state(JSON.parse(m.data));
    });
    es.addEventListener("events", (m) => handlers.events(JSON.parse(m.data)));
    es.addEventListener("run", (m) => handlers.run && handlers.run(JSON.parse(m.data)));
    es.onopen = () => { stats.connected = true; handlers.connection && handlers.connection(true); };
    es.onerror = () => { stats.connected = false; handlers.connection && handlers.connection(false); };
    // the rate over the last second, once a second
    let count = 0, at = performance.now();
    setInterval(() => {
      const now = performance.now();
      stats.rate = ((stats.snapshots - count) * 1000) / (now - at);
      count = stats.snapshots; at = now;
    }, 1000);
    return { source: es, stats };
  }

  window.NckApi = { ApiError, request, get, command, machineInput, home, upload, throttle, stream };
})();
