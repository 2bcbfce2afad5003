// The operator's controls of one channel, each a small panel: cycle buttons
// and switches, overrides, skip levels, jog, MDI and spindles. Each takes
// `send(command, fields)` (the channel is added by the caller) and returns
// {el, update(channelState, state)}.
(function () {
  "use strict";
  const { el, button, check, slider, fixed } = window.NckUi;
  const { throttle } = window.NckApi;

  // Cycle start, feedhold, stop, reset; single step, optional stop; mode.
  function cyclePanel(send) {
    const hold = button("Feedhold", "hold the path (press again to release)", () => send("feedhold", { on: !held }), "hold");
    let held = false;
    const step = check("single step", "hold at the end of every block", (on) => send("single_step", { on }));
    const opt = check("optional stop (M1)", "M1 holds the program", (on) => send("optional_stop", { on }));
    const mode = el("select", { "aria-label": "mode", onchange: () => send("mode", { mode: mode.value }) },
      el("option", { value: "automatic" }, "automatic"), el("option", { value: "manual" }, "manual"));
    const panel = el("div", { class: "panel cycle" },
      el("div", { class: "buttons" },
        button("Cycle start", "start the loaded program, or release a hold", () => send("cycle_start"), "start"),
        hold,
        button("Stop", "NC stop: hold the program where it is (cycle start goes on, reset ends it)", () => send("stop"), "stop"),
        button("Reset", "reset the channel: the program ends, errors clear", () => send("reset"), "reset")),
      el("div", { class: "switches" }, step.el, opt.el, el("label", { class: "check mode-choice" }, "mode ", mode)));
    return {
      el: panel,
      update(c) {
        held = !!c.feedhold;
        hold.classList.toggle("on", held);
        hold.setAttribute("aria-pressed", held);
        step.set(c.single_step);
        opt.set(c.optional_stop);
        if (document.activeElement !== mode) mode.value = c.manual_mode ? "manual" : "automatic";
      },
    };
  }

  // Feed and rapid override 0..200 %: throttled, the server allows 50 requests/s.
  function overridePanel(send) {
    const feed = slider("feed override", 0, 200, 1, " %", throttle((percent) => send("feed_override", { percent }), 100));
    const rapid = slider("rapid override", 0, 200, 1, " %", throttle((percent) => send("rapid_override", { percent }), 100));
    return {
      el: el("div", { class: "panel override" }, feed.el, rapid.el),
      update: (c) => {
        feed.set(c.feed_override_pct);
        rapid.set(c.rapid_override_pct);
      },
    };
  }

  // Skip levels /1../10 as the bits 0..9 of the channel's skip mask.
  function skipPanel(send) {
    const boxes = [];
    const sendMask = () => send("skip_mask", { mask: boxes.reduce((m, b, i) => m | (b.box.checked ? 1 << i : 0), 0) });
    for (let i = 0; i < 10; i++) boxes.push(check("/" + (i + 1), `skip blocks marked /${i + 1}${i ? "" : " or /"}`, sendMask));
    return {
      el: el("div", { class: "panel skip" }, el("span", { class: "name" }, "skip"), ...boxes.map((b) => b.el)),
      update: (c) => boxes.forEach((b, i) => b.set((c.skip_mask >> i) & 1)),
    };
  }

  // Jog keys per axis: held down for a continuous jog, or one step per click.
  function jogPanel(send, axes) {
    const step = el("select", { "aria-label": "jog increment" },
      ...["continuous", "0.001", "0.01", "0.1", "1", "10"].map((v) => el("option", { value: v }, v === "continuous" ? v : v + " mm")));
    const key = (axis, direction) => {
      const b = button(axis + direction.replace("-", "−"), `jog ${axis} ${direction}`, null, "jog");
      b.dataset.axis = axis; b.dataset.direction = direction;
      b.addEventListener("pointerdown", () => {
        if (step.value === "continuous") send("jog", { axis, direction });
        else send("jog_increment", { axis, direction, step_mm: Number(step.value) });
      });
      const release = () => { if (step.value === "continuous") send("jog", { axis, direction: "stop" }); };
      b.addEventListener("pointerup", release);
      b.addEventListener("pointerleave", (e) => { if (e.buttons) release(); });
      return b;
    };
    const keys = el("div", { class: "jog-keys" }, ...axes.map((a) => el("span", { class: "jog-axis" }, key(a, "-"), key(a, "+"))));
    return { el: el("div", { class: "panel jog" }, el("span", { class: "name" }, "jog"), step, keys), update() {} };
  }

  // One NC block typed by the operator (runs when the channel is idle or
  // ended). The blocks run are kept (the newest first, at most 20, across a
  // reload of the page): ↑ and ↓ in the box step through them, a click on
  // one in the list puts it back in the box.
  function mdiPanel(send, channel) {
    const key = "nck.mdi." + channel, kept = 20;
    const input = el("input", { type: "text", placeholder: "MDI: e.g. G0 X10", "aria-label": "MDI block", maxlength: 256 });
    const list = el("ol", { class: "mdi-history", "aria-label": "MDI history" });
    let history = [];
    try { history = JSON.parse(sessionStorage.getItem(key) || "[]"); } catch { history = []; }
    let at = -1;  // where ↑/↓ stand in the history (-1: the box as typed)
    const show = () => list.replaceChildren(...history.slice(0, 5).map((text) =>
      el("li", { title: "put this block back in the box", onclick: () => { input.value = text; input.focus(); } }, text)));
    const remember = (text) => {
      history = [text, ...history.filter((h) => h !== text)].slice(0, kept);
      try { sessionStorage.setItem(key, JSON.stringify(history)); } catch { /* storage full or off: memory only */ }
      show();
    };
    const go = () => {
      const text = input.value.trim();
      if (!text) return;
      send("mdi", { text: input.value }).then((ok) => { if (ok) { remember(text); input.value = ""; at = -1; } });
    };
    input.addEventListener("keydown", (e) => {
      if (e.key === "Enter") go();
      else if ((e.key === "ArrowUp" || e.key === "ArrowDown") && history.length) {
        at = Math.max(-1, Math.min(history.length - 1, at + (e.key === "ArrowUp" ? 1 : -1)));
        input.value = at < 0 ? "" : history[at];
        e.preventDefault();
      }
    });
    show();
    return { el: el("div", { class: "panel mdi" }, input, button("Run MDI", "run the typed block", go), list), update() {} };
  }

  // The channel's spindles: set and actual speed, gear, speed reached; override.
  function spindlePanel(send, names) {
    const rows = names.map((name) => {
      const cells = { set: el("td", { class: "num" }), act: el("td", { class: "num" }), gear: el("td", { class: "num" }), reached: el("td") };
      const ovr = slider(name + " override", 0, 200, 1, " %", throttle((percent) => send("spindle_override", { spindle: name, percent }), 100));
      ovr.set(100);
      const tr = el("tr", { "data-spindle": name }, el("th", {}, name), cells.set, cells.act, cells.gear, cells.reached, el("td", {}, ovr.el));
      return { name, cells, tr };
    });
    const table = el("table", { class: "spindles" },
      el("tr", {}, el("th", {}, "spindle"), el("th", { class: "num" }, "set rpm"), el("th", { class: "num" }, "act rpm"),
        el("th", { class: "num" }, "gear"), el("th", {}, "reached"), el("th", {}, "override")), ...rows.map((r) => r.tr));
    return {
      el: names.length ? el("div", { class: "panel" }, table) : el("div"),
      update(c, state) {
        for (const r of rows) {
          const s = (state.spindles || []).find((x) => x.name === r.name);
          if (!s) continue;
          r.cells.set.textContent = fixed(s.set_rpm, 0);
          r.cells.act.textContent = fixed(s.act_rpm, 0);
          r.cells.gear.textContent = s.gear;
          r.cells.reached.textContent = s.stopped ? "stopped" : s.speed_reached ? "yes" : "no";
          r.cells.reached.className = s.stopped || s.speed_reached ? "" : "warn";
        }
      },
    };
  }

  // The machine's E-stop (a latching button: press to stop, press again to
  // release) and machine-on switch, with what they leave: E-stop active,
  // reset needed, drives off. Not a safety function (docs/operating.md).
  // input(name, on) posts the input; its refusal is the caller's to show.
  function machinePanel(input) {
    let estop = false;
    const stop = button("E-stop", "emergency stop: the axes brake and are disabled; release it, then reset", () => input("estop", !estop), "estop");
    stop.id = "estop";
    const on = check("machine on", "the machine's drives may be powered", (v) => input("machine_on", v));
    on.box.id = "machine-on";
    const status = el("span", { id: "machine-status", role: "status" });
    return {
      el: el("span", { class: "machine" }, stop, on.el, status),
      update(s) {
        estop = !!s.estop;
        stop.classList.toggle("on", estop);
        stop.setAttribute("aria-pressed", estop);
        stop.textContent = estop ? "Release E-stop" : "E-stop";
        on.set(s.machine_on !== false);
        const said = [estop ? "E-stop active" : "", !estop && s.reset_needed ? "reset needed" : "",
          s.machine_on === false ? "machine off" : "", s.drives_enabled === false ? "drives off" : ""].filter(Boolean);
        status.textContent = said.join(" · ");
        status.className = said.length ? "warn" : "";
      },
    };
  }

  window.NckControls = { machinePanel, cyclePanel, overridePanel, skipPanel, jogPanel, mdiPanel, spindlePanel };
})();
