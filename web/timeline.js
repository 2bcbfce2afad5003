// Who waits for whom, over time: one row per waiter (a channel, or a
// spindle held on its own), one bar per wait, coloured by whom it waits for
// (a spindle, the PLC, the clock, the operator, the drives; nck
// has no channel-to-channel synchronisation: #WAIT/#SIGNAL are refused). The report
// draws the run's waits with it, the HMI the waits of the live stream; both
// name the reasons with the words below.
(function () {
  "use strict";
  const REASONS = {
    plc_ack: "the PLC's acknowledgement", speed_reached: "speed reached", in_position: "in position",
    standstill: "standstill", homing: "homing", gear_change: "gear change", expl_syn: "explicit synchronisation",
    dwell: "dwell", feedhold: "feed hold", coupling: "a spindle coupling", zero_mark: "the spindle's zero mark (G33)",
    drive_enable: "the drives' power-up (CiA 402)",
  };
  // Whom a wait is for, and its colour.
  const PARTIES = {
    spindle: { label: "a spindle", colour: "#ff7f0e" },
    plc: { label: "the PLC", colour: "#1f6feb" },
    clock: { label: "the clock (dwell)", colour: "#8c8c8c" },
    operator: { label: "a feed hold (operator or PLC)", colour: "#d62728" },
    drives: { label: "the drives", colour: "#9467bd" },
  };
  function party(w) {
    if (w.reason === "plc_ack" || w.reason === "expl_syn") return "plc";  // #EXPL SYN: the late acknowledgements
    if (w.reason === "dwell") return "clock";
    if (w.reason === "feedhold") return "operator";
    if (w.reason === "drive_enable") return "drives";
    return "spindle";
  }
  // "S1 speed reached (M3)", "the PLC's acknowledgement of M8", "the PLC's
  // acknowledgement of M3 for S2" (a linked spindle's M3 waits once per spindle), "dwell".
  function whom(w) {
    const what = REASONS[w.reason] || w.reason;
    if (w.reason === "plc_ack") return what + (w.fn ? " of " + w.fn : "") + (w.spindle ? " for " + w.spindle : "");
    return (w.spindle ? w.spindle + " " : "") + what + (w.fn ? " (" + w.fn + ")" : "");
  }
  const rowOf = (w) => (w.ch ? "channel " + w.ch : "spindle " + (w.spindle || "?"));

  const SVG = "http://www.w3.org/2000/svg";
  function node(name, attrs, text) {
    const n = document.createElementNS(SVG, name);
    for (const [k, v] of Object.entries(attrs)) n.setAttribute(k, v);
    if (text != null) n.textContent = text;
    return n;
  }

  // Draws `waits` ({ch, spindle, reason, fn, t0, t1, where}; t1 < 0 or null: still
  // waiting at tEnd) from tStart (default 0) to tEnd into host, replacing
  // what it held, with a row for each of extraRows even without waits.
  // Returns the bars drawn, for tests and scripts.
  function draw(host, waits, tEnd, extraRows, tStart = 0) {
    const rows = [...new Set((extraRows || []).concat(waits.map(rowOf)))].sort();
    const labelW = 90, width = 900, rowH = 22, axisH = 18, plotW = width - labelW - 10;
    const span = Math.max(tEnd - tStart, 1e-3), x = (t) => labelW + (plotW * Math.min(Math.max(t - tStart, 0), span)) / span;
    const svg = node("svg", { viewBox: `0 0 ${width} ${rows.length * rowH + axisH}`, class: "timeline", role: "img",
      "aria-label": "who waits for whom over time" });
    rows.forEach((r, i) => {
      svg.append(node("text", { x: 4, y: i * rowH + 15, class: "tl-row" }, r));
      svg.append(node("line", { x1: labelW, x2: labelW + plotW, y1: (i + 1) * rowH - 0.5, y2: (i + 1) * rowH - 0.5, class: "tl-grid" }));
    });
    const bars = [];
    for (const w of waits) {
      const t1 = w.t1 == null || w.t1 < 0 ? tEnd : w.t1, i = rows.indexOf(rowOf(w)), p = party(w);
      const x0 = x(w.t0), bw = Math.max(x(t1) - x0, 1.5);
      const text = rowOf(w) + (w.where ? " (" + w.where + ")" : "") + " waits " + (t1 - w.t0).toFixed(3) + " s for " + whom(w) + " (" + w.t0.toFixed(3) + "–" + t1.toFixed(3) + " s)";
      const bar = node("rect", { x: x0, y: i * rowH + 3, width: bw, height: rowH - 7, fill: PARTIES[p].colour,
        "data-party": p, "data-reason": w.reason, class: "tl-bar" });
      bar.append(node("title", {}, text));
      svg.append(bar);
      if (bw > 6.2 * whom(w).length + 6) svg.append(node("text", { x: x0 + 3, y: i * rowH + 15, class: "tl-label" }, whom(w)));
      bars.push({ row: rowOf(w), party: p, t0: w.t0, t1, text });
    }
    for (let k = 0; k <= 4; k++) {
      const t = tStart + (span * k) / 4;
      svg.append(node("text", { x: x(t), y: rows.length * rowH + 13, class: "tl-axis", "text-anchor": k ? (k === 4 ? "end" : "middle") : "start" }, t.toFixed(1) + " s"));
    }
    const used = [...new Set(bars.map((b) => b.party))];
    const legend = document.createElement("div");
    legend.className = "tl-legend";
    legend.innerHTML = used.length ? used.map((p) => `<span><i style="background:${PARTIES[p].colour}"></i>${PARTIES[p].label}</span>`).join(" ")
      : "no waits";
    host.replaceChildren(svg, legend);
    return bars;
  }

  window.NckTimeline = { REASONS, whom, draw };
})();
