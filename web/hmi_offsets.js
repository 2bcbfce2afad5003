// The HMI's offsets and tools panel (issue 48 item 8; docs/operating.md):
// the zero offsets G54..G59, the clamp offsets and the tool table of the
// server's machine, an edit box per value, a touch-off per axis and a save
// that writes the list files back. Every refusal is shown with its ID.
// window.nckOffsets tells the browser test what the panel shows.
(function () {
  "use strict";
  const { el, button } = window.NckUi;
  const api = window.NckApi;
  const TOOL_FIELDS = [["length_mm", "Length mm"], ["radius_mm", "Radius mm"], ["vb_min_rpm", "min rpm"],
    ["vb_max_rpm", "max rpm"], ["a_max_deg_s2", "a max °/s²"]];
  const view = { tables: null, message: null, refusals: 0 };
  window.nckOffsets = view;
  const root = () => document.getElementById("offsets");

  // The answer of a request in the message line: a refusal with its ID and remedy.
  function say(text, error) {
    const box = document.getElementById("offsets-message");
    view.message = error ? { id: error.id, text: error.message, remedy: error.remedy } : { text };
    if (error) view.refusals++;
    box.className = error ? "message refused" : "message";
    box.textContent = error ? `refused ${error.id || ""}: ${error.message}` + (error.remedy ? ` — ${error.remedy}` : "") : text;
  }

  async function send(path, body, done) {
    try {
      const answer = await api.request("POST", path, body);
      say(done(answer));
    } catch (e) {
      say("", e);
    }
    await load();
  }

  // A number box of one value; a change sends it.
  function valueBox(value, label, onchange) {
    const input = el("input", { type: "number", step: "any", value: String(value), "aria-label": label });
    input.addEventListener("change", () => {
      const v = Number(input.value);
      if (input.value.trim() === "" || !Number.isFinite(v)) return say("", { id: "", message: `${label}: not a number` });
      onchange(v);
    });
    return el("td", {}, input);
  }

  function zeroTable(c) {
    const head = el("tr", {}, el("th", {}, "Offset"), ...c.axes.map((a) => el("th", {}, a)));
    const rows = c.zero.map((z) => el("tr", { class: z.offset === c.active_zero ? "active" : null, "data-offset": z.offset },
      el("th", {}, z.offset + (z.offset === c.active_zero ? " ●" : "")),
      ...c.axes.map((a) => valueBox(z.values_mm[a] ?? 0, `${z.offset} ${a}`, (v) =>
        send("/api/v1/offsets/zero", { channel: c.channel, offset: z.offset, axis: a, value_mm: v },
          () => `${z.offset} ${a} = ${v} mm (takes effect at its next selection)`)))));
    return el("table", { class: "offsets-table zero" }, el("thead", {}, head), el("tbody", {}, ...rows));
  }

  // Touch off: the chosen offset's value that makes the axis read `reads`.
  function touchOff(c) {
    const target = el("select", { "aria-label": "offset to touch off" },
      ...c.zero.map((z) => el("option", { value: z.offset }, z.offset)));
    target.value = c.zero.some((z) => z.offset === c.active_zero) ? c.active_zero : "G54";
    const reads = el("input", { type: "number", step: "any", value: "0", "aria-label": "reads mm", class: "reads" });
    const buttons = c.axes.map((a) => button(`Touch off ${a}`, `set ${a} of the offset so that the current position reads the value`,
      () => send("/api/v1/offsets/touch_off", { channel: c.channel, offset: target.value, axis: a, reads_mm: Number(reads.value) },
        (r) => `${target.value} ${a} = ${r.value_mm} mm: ${a} reads ${reads.value} once ${target.value} is selected`), "touch-off"));
    return el("div", { class: "touch-off" }, "Touch off ", target, " so that the axis reads ", reads, " mm: ", ...buttons);
  }

  function clampTable(c) {
    const head = el("tr", {}, el("th", {}, "Clamp group"), ...c.axes.map((a) => el("th", {}, a)));
    const rows = c.clamp.map((g) => el("tr", {}, el("th", {}, String(g.group)),
      ...c.axes.map((a) => valueBox(g.values_mm[a] ?? 0, `clamp ${g.group} ${a}`, (v) =>
        send("/api/v1/offsets/clamp", { channel: c.channel, group: g.group, axis: a, value_mm: v },
          () => `clamp group ${g.group} ${a} = ${v} mm (takes effect at the next program start)`)))));
    return el("table", { class: "offsets-table clamp" }, el("thead", {}, head), el("tbody", {}, ...rows));
  }

  function toolTable(c) {
    const head = el("tr", {}, el("th", {}, "Tool"), ...TOOL_FIELDS.map(([, t]) => el("th", {}, t)));
    const rows = c.tools.map((t) => el("tr", { "data-tool": String(t.tool) },
      el("th", {}, `D${t.tool}` + (t.tool === c.active_tool ? " ●" : "")),
      ...TOOL_FIELDS.map(([f, label]) => valueBox(t[f], `D${t.tool} ${label}`, (v) =>
        send(`/api/v1/tools/${t.tool}`, { channel: c.channel, [f]: v }, () => `D${t.tool} ${label} = ${v}`)))));
    return el("table", { class: "offsets-table tools" }, el("thead", {}, head), el("tbody", {}, ...rows));
  }

  // The #ACS / #CS the running program set: programmed, so shown, not edited.
  function coordinateSystems(c) {
    const systems = c.coordinate_systems || [];
    if (!systems.length) return el("p", { class: "cs-none" }, "none set by the program (#ACS, #CS)");
    const rows = systems.map((cs) => el("tr", { "data-cs": cs.kind },
      el("th", {}, "#" + cs.kind.toUpperCase()),
      el("td", { class: "cs-values" }, Object.entries(cs.values).map(([k, v]) => `${k} ${v}`).join("  "))));
    return el("table", { class: "offsets-table cs" }, el("tbody", {}, ...rows));
  }

  function draw(tables) {
    const parts = [];
    for (const c of tables.channels) {
      const files = Object.entries(c.files).filter(([, f]) => f).map(([k, f]) => `${k}: ${f}`).join(", ");
      parts.push(el("div", { class: "offsets-channel", "data-channel": String(c.channel) },
        el("h3", {}, `Channel ${c.channel}` + (files ? ` (${files})` : "")),
        el("h4", {}, `Zero offsets (active: ${c.active_zero})`), zeroTable(c), touchOff(c),
        el("h4", {}, "Coordinate systems (programmed)"), coordinateSystems(c),
        el("h4", {}, "Clamp offsets"), clampTable(c),
        el("h4", {}, "Tools"), c.tools.length ? toolTable(c) : el("p", {}, "no tool list")));
    }
    root().replaceChildren(...parts);
    document.getElementById("offsets-unsaved").hidden = !tables.unsaved;
  }

  async function load() {
    try {
      view.tables = await api.get("/api/v1/offsets");
      draw(view.tables);
    } catch (e) {
      say("", e);
    }
  }

  function start() {
    document.getElementById("offsets-save").addEventListener("click", () =>
      send("/api/v1/offsets/save", {}, (r) => r.written.length ? `saved ${r.written.join(", ")} (old files kept as .bak)` : "nothing to save"));
    document.getElementById("offsets-reload").addEventListener("click", () =>
      send("/api/v1/offsets/reload", {}, () => "lists read again from the machine folder (unsaved edits dropped)"));
    document.getElementById("offsets-section").addEventListener("toggle", (e) => { if (e.target.open) load(); });
    load();
  }
  view.reload = load;
  // An #ACS / #CS of the program ran: the open panel shows it.
  view.refresh = () => { if (document.getElementById("offsets-section").open) load(); };
  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})();
