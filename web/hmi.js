// nck serve's HMI: reads the machine, builds one column per channel
// (hmi_channel.js), and feeds them the stream's snapshots; the run's speed,
// pause and lateness in the top bar, errors and warnings with their remedy
// below. window.nckHmi tells scripts and the browser test what it shows.
(function () {
  "use strict";
  const t0 = performance.now();
  const { el, button, check, fixed } = window.NckUi;
  const api = window.NckApi;
  const $ = (id) => document.getElementById(id);
  const MAX_ERRORS = 100;

  const MAX_WAITS = 500, TIMELINE_MS = 500;
  const hmi = { ready: false, panels: [], errors: [], state: null, stats: null, catalog: new Map(),
    waits: [], timeline: [] };
  window.nckHmi = hmi;

  // One entry of the errors list: what happened, where, and what to do.
  function addError(kind, id, message, where, remedy) {
    const known = hmi.catalog.get(id);
    const fix = remedy || (known && known.remedy) || "";
    hmi.errors.push({ kind, id, message, where, remedy: fix });
    const item = el("li", { class: kind },
      el("span", { class: "kind" }, kind + (id ? " " + id : "")), " ", el("span", { class: "msg" }, message),
      where ? el("span", { class: "where" }, " — " + where) : null,
      fix ? el("div", { class: "remedy" }, "Remedy: " + fix) : null);
    const list = $("errors");
    list.prepend(item);
    while (list.children.length > MAX_ERRORS) list.lastChild.remove();
    $("errors-section").hidden = false;
  }

  // A refused request (status 4xx with {"error": ...}) or a failed fetch.
  function reportRefusal(e, what) {
    const d = e.diagnostic || {};  // an MDI text that does not decode says where in it
    const at = d.line ? ` line ${d.line}${d.column ? ", column " + d.column : ""}` : "";
    addError("refused", e.id, e.message, what + at, e.remedy);
  }

  // The current run's waits from the stream's wait / wait_end events, for
  // the timeline of who waits for whom (timeline.js). The stream's `run`
  // frame comes before a new run's first event: its waits start afresh, and
  // the timeline starts at the run's first state or wait (its clock may
  // start again at 0).
  let runStart = null, timelineDrawn = 0, timelineTimer = null;
  function onRun() {
    hmi.waits.length = 0;
    runStart = null;
  }
  function noteWait(e) {
    const same = (w) => w.t1 == null && w.ch === e.ch && w.spindle === e.spindle && w.reason === e.reason && w.fn === e.fn;
    if (e.ev === "wait" && hmi.waits.length < MAX_WAITS)
      hmi.waits.push({ ch: e.ch, spindle: e.spindle, reason: e.reason, fn: e.fn, t0: e.t, t1: null });
    else if (e.ev === "wait_end") {
      const w = hmi.waits.find(same);
      if (w) w.t1 = e.t;
    }
  }
  function drawTimeline(s) {
    if (runStart == null) runStart = s.t_s;
    const waitMs = TIMELINE_MS - (performance.now() - timelineDrawn);
    if (waitMs > 0) {  // drawn a moment ago: draw the latest snapshot later, so a run's last waits are never left out
      timelineTimer ||= setTimeout(() => { timelineTimer = null; drawTimeline(hmi.state); }, waitMs);
      return;
    }
    timelineDrawn = performance.now();
    $("timeline-section").hidden = !hmi.waits.length;
    if (!hmi.waits.length) return;
    const from = Math.min(runStart, ...hmi.waits.map((w) => w.t0));
    hmi.timeline = window.NckTimeline.draw($("timeline"), hmi.waits, s.t_s, hmi.panels.map((p) => "channel " + p.n), from);
  }

  function onEvents(events) {
    for (const e of events) {
      if (e.ev === "wait" || e.ev === "wait_end") noteWait(e);
      if (e.ev === "link" && hmi.panels[e.ch - 1]) hmi.panels[e.ch - 1].noteLink(e);
      if (e.ev === "offset" && (e.kind === "cs" || e.kind === "acs") && window.nckOffsets) window.nckOffsets.refresh();
      if (e.ev !== "error" && e.ev !== "warning") continue;
      const where = [e.ch ? "channel " + e.ch : "", e.file ? String(e.file).split("/").pop() + ":" + e.line : "",
        e.n != null ? "N" + e.n : "", e.t != null ? "t " + fixed(e.t, 3) + " s" : ""].filter(Boolean).join(" ");
      addError(e.ev, e.id, e.message || e.msg || "", where, e.remedy);  // the diagnostic's one shape (docs/outputs.md)
    }
  }

  // The run's bar: time, speed, pause, lateness of the kernel's cycles, stream rate.
  function runBar() {
    const speed = el("select", { id: "speed", "aria-label": "run speed", onchange: () => send("speed", { speed: Number(speed.value) }) },
      ...[["0.1", "0.1×"], ["0.5", "0.5×"], ["1", "real time"], ["2", "2×"], ["5", "5×"], ["10", "10×"], ["0", "as fast as possible"]]
        .map(([v, t]) => el("option", { value: v }, t)));
    const pause = check("pause", "stop the kernel's clock (the machine freezes)", (on) => send("pause", { on }));
    const step = button("Step cycle", "one kernel cycle while paused", () => send("step_cycle"));
    const machine = window.NckControls.machinePanel((name, on) =>
      api.machineInput(name, on).catch((e) => reportRefusal(e, name)));
    hmi.bar = { speed, pause, machine };
    $("run").append(machine.el, el("span", { class: "run-pace" }, el("label", {}, "speed ", speed), pause.el, step),
      el("span", { id: "clock" }), el("span", { id: "lateness", title: "how late the kernel's cycles woke up" }),
      el("span", { id: "rate" }), el("span", { id: "link" }));
  }

  const send = (command, fields) => api.command(command, 1, fields).catch((e) => reportRefusal(e, command));

  function updateBar(s) {
    hmi.bar.machine.update(s);
    const speed = hmi.bar.speed, value = String(s.speed);
    // a speed set elsewhere (--speed 4, the API) that the list lacks joins it
    if (![...speed.options].some((o) => o.value === value)) speed.append(el("option", { value }, value + "×"));
    if (document.activeElement !== speed) speed.value = value;
    hmi.bar.pause.set(s.paused);
    $("clock").textContent = `t ${fixed(s.t_s, 3)} s · cycle ${s.cycle} · run ${s.run}` + (s.events_lost ? ` · ${s.events_lost} events lost` : "");
    const l = s.lateness;
    $("lateness").textContent = `lateness p50 ${fixed(l.p50_us, 0)} µs · p99 ${fixed(l.p99_us, 0)} µs · worst ${fixed(l.worst_us, 0)} µs · ${l.late_cycles} late of ${l.wakeups}`;
    $("lateness").className = l.late_cycles ? "warn" : "";
  }

  // nck-hal --serve (docs/hal.md, "The HMI"): the kernel runs in a LinuxCNC
  // HAL thread. What the HAL file owns (E-stop and machine on are pins, the
  // thread sets the pace; another program, MDI, jog, homing and offsets
  // would need another kernel) is shown, not offered (hmi.css, body.hal).
  function halMode() {
    document.body.classList.add("hal");
    for (const id of ["estop", "machine-on"]) {
      $(id).disabled = true;
      $(id).title = "HAL pins drive the machine's inputs (nck.estop, nck.machine-on)";
    }
    $("run").prepend(el("span", { class: "hal-badge", title: "nck-hal --serve: the kernel runs in a LinuxCNC HAL thread" }, "HAL"));
  }

  function onState(s) {
    hmi.state = s;
    if (s.hal && !document.body.classList.contains("hal")) halMode();
    updateBar(s);
    for (const p of hmi.panels) p.update(s);
    drawTimeline(s);
    if (!hmi.ready) {
      hmi.ready = true;
      hmi.loadMs = performance.now() - t0;
    }
  }

  async function refreshPrograms() {
    const list = (await api.get("/api/v1/programs")).programs;
    for (const p of hmi.panels) p.programs(list);
  }

  async function start() {
    runBar();
    const [machine, catalog] = await Promise.all([api.get("/api/v1/machine"), api.get("/api/v1/errors")]);
    for (const e of catalog) hmi.catalog.set(e.id, e);
    hmi.machine = machine;
    const parent = $("channels");
    parent.style.setProperty("--channels", machine.channels.length);
    machine.channels.forEach((ch, i) => {
      const p = new window.NckChannelPanel(parent, i + 1, ch, reportRefusal);
      p.onUploaded = refreshPrograms;
      hmi.panels.push(p);
    });
    await refreshPrograms();
    const s = api.stream({
      state: onState,
      events: onEvents,
      run: onRun,
      connection: (up) => { $("link").textContent = up ? "● live" : "● reconnecting…"; $("link").className = up ? "up" : "down"; },
    });
    hmi.stats = s.stats;
    setInterval(() => { $("rate").textContent = `stream ${s.stats.rate.toFixed(0)} snapshots/s`; }, 1000);
  }

  $("clear-errors").addEventListener("click", () => { $("errors").replaceChildren(); hmi.errors.length = 0; $("errors-section").hidden = true; });
  start().catch((e) => reportRefusal(e, "starting the HMI"));
})();
