// The report page: reads the run's data (the JSON in #nck-data) and builds
// the summary, tables, backplots (backplot.js, view3d.js), the time
// cursor (player.js) and time plots (uPlot).
(function () {
  "use strict";
  const t0 = performance.now();
  const D = JSON.parse(document.getElementById("nck-data").textContent);
  const $ = (id) => document.getElementById(id);
  const esc = (s) => String(s == null ? "" : s).replace(/[&<>"]/g, (c) => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;" }[c]));
  const base = (p) => String(p || "").split("/").pop();
  const COLOURS = ["#1f6feb", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#17becf", "#e377c2"];
  const REASONS = NckTimeline.REASONS;

  function hms(s) {
    const h = Math.floor(s / 3600), m = Math.floor((s % 3600) / 60), sec = s - 3600 * h - 60 * m;
    return h + ":" + String(m).padStart(2, "0") + ":" + sec.toFixed(3).padStart(6, "0");
  }
  function lineText(file, line) { return D.lines[file + ":" + line] || ""; }
  function nLabel(file, line) {
    const m = /^\s*N(\d+)/i.exec(lineText(file, line));
    return m ? "N" + m[1] : "line " + line;
  }
  function table(headers, rows, numeric) {
    let h = "<table><tr>" + headers.map((x, i) => "<th" + (numeric && numeric[i] ? ' class="num"' : "") + ">" + esc(x) + "</th>").join("") + "</tr>";
    for (const r of rows) h += "<tr>" + r.map((x, i) => "<td" + (numeric && numeric[i] ? ' class="num"' : "") + ">" + x + "</td>").join("") + "</tr>";
    return h + "</table>";
  }

  // --- what a wait means, in words ---------------------------------------
  function waitText(w) {
    if (w.reason === "feedhold")  // from the PLC (HLI), not the program
      return (w.ch ? nLabel(w.file, w.line) : w.spindle) + " held " + (w.t1 - w.t0).toFixed(3) + " s by the PLC's " +
        (w.ch ? "feedhold" : "spindle feedhold of " + w.spindle) + " (HLI)";
    const what = (w.spindle ? w.spindle + " " : "") + (REASONS[w.reason] || w.reason);
    return nLabel(w.file, w.line) + " waits " + (w.t1 - w.t0).toFixed(3) + " s for " + what +
      (w.fn ? " (" + w.fn + ")" : "") + (w.sync ? ", " + w.sync : "");
  }

  // Seconds waited per reason: a channel waiting for two spindles at once
  // waits once (the union of its intervals per channel and reason).
  function waitSecondsByReason(waits) {
    const groups = {};
    for (const w of waits) (groups[w.ch + " " + w.reason] ||= { reason: w.reason, spans: [] }).spans.push([w.t0, w.t1]);
    const by = {};
    for (const g of Object.values(groups)) {
      g.spans.sort((a, b) => a[0] - b[0]);
      let total = 0, [from, to] = g.spans[0];
      for (const [t0, t1] of g.spans) {
        if (t0 > to) { total += to - from; from = t0; to = t1; } else to = Math.max(to, t1);
      }
      total += to - from;
      by[g.reason] = (by[g.reason] || 0) + total;
    }
    return by;
  }

  // --- summary ---------------------------------------------------------
  function summary() {
    const m = D.meta;
    const waitsBy = waitSecondsByReason(D.waits);
    const waits = Object.entries(waitsBy).map(([r, s]) => esc(REASONS[r] || r) + " " + s.toFixed(3) + " s").join(", ") || "none";
    const rows = [
      ["machine", "<code>" + esc(m.machine) + "</code>"],
      ["program(s)", m.programs.map((p, i) => "channel " + (i + 1) + ": <code>" + esc(p) + "</code>").join("<br>")],
      ["PLC scenario", m.plc ? "<code>" + esc(m.plc) + "</code>" : "none (the PLC acknowledges at once)"],
      ["end", esc(m.end || (m.exit_code === 0 ? "program end" : "")) + " (exit code " + m.exit_code + ")"],
      ["cycle time", hms(m.end_s) + " (" + m.end_s.toFixed(3) + " s simulated, NC cycle " + (m.cycle_s * 1000).toFixed(3) + " ms)"],
      ["errors / warnings", '<span class="' + (m.errors ? "err" : "") + '">' + m.errors + "</span> / <span class=\"" + (m.warnings ? "warn" : "") + '">' + m.warnings + "</span>"],
      ["waits", waits],
      ["written by", "nck " + esc(m.nck || "")],
    ];
    $("summary").innerHTML = '<div class="kv">' + rows.map(([k, v]) => "<b>" + k + "</b><span>" + v + "</span>").join("") + "</div>";
  }

  // --- errors and warnings ---------------------------------------------
  function diagnostics() {
    if (!D.diagnostics.length) return;
    $("diagnostics-section").hidden = false;
    const fileId = (name) => D.files.indexOf(name);
    const rows = D.diagnostics.map((d) => [
      '<span class="' + (d.ev === "error" ? "err" : "warn") + '">' + d.ev + "</span>", d.id, d.ch || "",
      esc(base(d.file)) + ":" + (d.line || ""), '<span class="nc">' + esc(lineText(fileId(d.file), d.line)) + "</span>",
      esc(d.msg), d.t.toFixed(3)]);
    $("diagnostics").innerHTML = table(["", "id", "ch", "where", "NC line", "message", "t (s)"], rows, [0, 0, 0, 0, 0, 0, 1]);
  }

  // --- time plots -------------------------------------------------------
  const plots = [];
  let tip = null;
  function showTip(text, x, y) {
    if (!tip) { tip = document.createElement("div"); tip.className = "tip"; document.body.appendChild(tip); }
    tip.textContent = text; tip.style.left = x + 14 + "px"; tip.style.top = y + 14 + "px"; tip.hidden = false;
  }
  function hideTip() { if (tip) tip.hidden = true; }

  function waitsFor(meta) {
    if (meta.ch) return D.waits.filter((w) => w.ch === meta.ch);
    const name = D.spindles[meta.spindle];
    return D.waits.filter((w) => w.spindle === name);
  }

  // Shades the waits and draws the spindle marks under the lines.
  function shadesPlugin(waits, marks) {
    return {
      hooks: {
        drawClear: (u) => {
          const ctx = u.ctx, top = u.bbox.top, h = u.bbox.height;
          ctx.save();
          for (const w of waits) {
            const x0 = u.valToPos(w.t0, "x", true), x1 = u.valToPos(w.t1, "x", true);
            if (x1 < u.bbox.left || x0 > u.bbox.left + u.bbox.width) continue;
            ctx.fillStyle = w.reason === "feedhold" ? "rgba(214,39,40,0.16)" : "rgba(255,170,0,0.22)";
            ctx.fillRect(Math.max(x0, u.bbox.left), top, Math.max(1, Math.min(x1, u.bbox.left + u.bbox.width) - Math.max(x0, u.bbox.left)), h);
          }
          ctx.restore();
        },
        draw: (u) => {
          const ctx = u.ctx;
          ctx.save();
          ctx.font = 11 * devicePixelRatio + "px system-ui, sans-serif";
          for (const m of marks) {
            const x = u.valToPos(m.t, "x", true);
            if (x < u.bbox.left || x > u.bbox.left + u.bbox.width) continue;
            ctx.strokeStyle = m.kind === "gear" ? "#9467bd" : m.kind === "speed_reached" ? "#2ca02c" : m.kind === "override" ? "#e8590c" : "#667085";
            ctx.setLineDash(m.kind === "s" ? [3, 3] : []);
            ctx.beginPath(); ctx.moveTo(x, u.bbox.top); ctx.lineTo(x, u.bbox.top + u.bbox.height); ctx.stroke();
            ctx.fillStyle = ctx.strokeStyle;
            const label = m.kind === "gear" ? m.text.split(" ")[0] : m.kind === "speed_reached" ? "✓" :
              m.kind === "override" ? m.text.replace(/^.*override /, "") : "S";
            ctx.fillText(label, x + 3, u.bbox.top + (m.kind === "override" ? 26 : 12) * devicePixelRatio);
          }
          ctx.restore();
        },
      },
    };
  }

  function syncX(src) {
    const { min, max } = src.scales.x;
    for (const p of plots) if (p.u !== src && (p.u.scales.x.min !== min || p.u.scales.x.max !== max)) p.u.setScale("x", { min, max });
  }

  // What the shades and vertical marks of a panel mean (only those it shows).
  function marksLegend(marks, waits) {
    const kinds = new Set(marks.map((m) => m.kind)), items = [];
    if (waits.some((w) => w.reason !== "feedhold")) items.push('<span class="shade wait"></span>waiting');
    if (waits.some((w) => w.reason === "feedhold")) items.push('<span class="shade hold"></span>feedhold');
    if (kinds.has("speed_reached")) items.push('<span class="mark reached"></span>✓ speed reached');
    if (kinds.has("gear")) items.push('<span class="mark gear"></span>gear change');
    if (kinds.has("override")) items.push('<span class="mark override"></span>override changed');
    if (kinds.has("s")) items.push('<span class="mark speed"></span>S speed command');
    return items.join(" ");
  }

  // A series that never changes gets a range of its own (not ticks of 0 0 0).
  const yRange = (u, lo, hi) => (hi - lo < 1e-9 ? [lo - 1, hi + 1] : uPlot.rangeNum(lo, hi, 0.1, true));

  function timeplots() {
    const panels = new Map();
    D.series.forEach((s, i) => {
      if (s.kind === "c_axis" && !D.meta.c_axis) return;  // follows the turning spindle: not an axis motion
      const v = D.ts.v[i];
      let lo = Infinity, hi = -Infinity;
      for (const x of v) { if (x < lo) lo = x; if (x > hi) hi = x; }
      if (!(hi > lo) && !(s.kind === "act_rpm" || s.kind === "set_rpm") && !(s.kind === "velocity" && hi > 0)) return; // nothing happens
      if ((s.kind === "set_rpm" || s.kind === "act_rpm") && lo === 0 && hi === 0) return;
      if (!panels.has(s.panel)) panels.set(s.panel, { meta: s, idx: [] });
      panels.get(s.panel).idx.push(i);
    });
    const width = Math.min($("timeplots").clientWidth - 10, 1220);
    for (const [title, p] of panels) {
      const box = document.createElement("div");
      box.className = "timeplot";
      box.dataset.panel = title;
      box.innerHTML = "<h3>" + esc(title) + "</h3>";
      $("timeplots").appendChild(box);
      // a scale and an axis per unit (path.a in mm/s² left, path.j in mm/s³ right)
      const units = [...new Set(p.idx.map((i) => D.series[i].unit))];
      const marks = p.meta.spindle != null ? D.marks.filter((m) => m.spindle === p.meta.spindle)
        : p.meta.kind === "velocity" ? D.marks.filter((m) => m.ch === p.meta.ch) : [];
      const waits = waitsFor(p.meta);
      const legend = marksLegend(marks, waits);
      if (legend) box.insertAdjacentHTML("beforeend", '<div class="marks-legend">' + legend + "</div>");
      const opts = {
        width, height: 230,
        cursor: { sync: { key: "nck", setSeries: false }, drag: { x: true, y: false } },
        scales: Object.fromEntries([["x", { time: false }]].concat(units.map((unit) => [unit, { range: yRange }]))),
        axes: [{ label: "time (s)", grid: { stroke: "#eef0f4" }, ticks: { stroke: "#c9ced8" } }].concat(units.map((unit, k) => Object.assign({
          scale: unit, label: unit, size: 70, side: k ? 1 : 3,
          grid: { show: k === 0, stroke: "#eef0f4" }, ticks: { stroke: "#c9ced8" },
        }, units.length > 1 ? { stroke: COLOURS[k % COLOURS.length] } : {}))),  // two scales: each in its series' colour
        series: [{ label: "t (s)", value: (u, v) => (v == null ? "-" : v.toFixed(4)) }].concat(p.idx.map((i, k) => ({
          label: D.series[i].name + " (" + D.series[i].unit + ")",
          scale: D.series[i].unit,
          stroke: D.series[i].kind === "act_rpm" ? "#d62728" : D.series[i].kind === "set_rpm" ? "#1f6feb" : COLOURS[k % COLOURS.length],
          width: 1.5,
          dash: D.series[i].kind === "set_rpm" ? [6, 3] : undefined,
          value: (u, v) => (v == null ? "-" : (+v.toFixed(3)).toString()),
        }))),
        plugins: [shadesPlugin(waits, marks)],
        hooks: { setScale: [(u, key) => { if (key === "x") syncX(u); }] },
      };
      const u = new uPlot(opts, [D.ts.t].concat(p.idx.map((i) => D.ts.v[i])), box);
      plots.push({ title, u, waits, marks, series: p.idx.map((i) => D.series[i].name), points: D.ts.t.length });
      u.over.addEventListener("mousemove", (e) => {
        const t = u.posToVal(e.offsetX, "x");
        const w = waits.find((w) => t >= w.t0 && t <= w.t1);
        const px = u.bbox.width / devicePixelRatio / Math.max(1e-9, u.scales.x.max - u.scales.x.min);
        const mk = marks.find((m) => Math.abs(m.t - t) * px < 4);
        const text = [w ? waitText(w) : "", mk ? mk.t.toFixed(3) + " s: " + (D.spindles[mk.spindle] ? D.spindles[mk.spindle] + " " : "") + mk.text : ""].filter(Boolean).join(" · ");
        if (text) showTip(text, e.clientX, e.clientY); else hideTip();
      });
      u.over.addEventListener("mouseleave", hideTip);
    }
    if (!panels.size) $("timeplots").insertAdjacentHTML("beforeend", '<p class="hint">Nothing moved and no spindle turned.</p>');
  }

  // --- cycle time per tool and per block --------------------------------
  function cycletime() {
    const total = Math.max(D.meta.end_s, 1e-9);
    const tools = D.summary.tools.filter((t) => t.time_s > 0).map((t) => [t.ch, esc(t.tool === "-" ? "(none)" : t.tool), t.time_s.toFixed(3), hms(t.time_s), (100 * t.time_s / total).toFixed(1) + " %"]);
    const blocks = D.summary.blocks.filter((b) => b.time_s > 0).slice(0, 40).map((b) => [b.ch, esc(base(D.files[b.file])) + ":" + b.line, '<span class="nc">' + esc(lineText(b.file, b.line)) + "</span>", b.count, b.time_s.toFixed(3), (100 * b.time_s / total).toFixed(1) + " %"]);
    $("cycletime").innerHTML =
      "<div><h3>Per tool</h3>" + table(["ch", "tool", "time (s)", "h:mm:ss", "share"], tools, [0, 0, 1, 1, 1]) + "</div>" +
      "<div><h3>Longest blocks (" + blocks.length + " of " + D.summary.blocks_total + ")</h3>" +
      table(["ch", "line", "NC text", "runs", "time (s)", "share"], blocks, [0, 0, 0, 1, 1, 1]) + "</div>";
  }

  // --- time by cause: a stacked bar, the causes, the blocks losing most ---
  // A table whose column heads sort it (numbers descending first).
  function sortableTable(el, headers, rows, numeric) {
    let col = -1, desc = true;
    const render = () => {
      const sorted = col < 0 ? rows : rows.slice().sort((a, b) => {
        const x = a[col].sort, y = b[col].sort;
        return (x < y ? -1 : x > y ? 1 : 0) * (desc ? -1 : 1);
      });
      el.innerHTML = table(headers, sorted.map((r) => r.map((c) => c.html)), numeric);
      el.querySelectorAll("th").forEach((th, i) => {
        th.classList.add("sortable");
        th.addEventListener("click", () => { desc = col === i ? !desc : true; col = i; render(); });
      });
    };
    render();
  }
  // The k-th of as many distinct colours as there are causes: the palette,
  // then hues a golden angle apart in two lightnesses (not the palette again).
  function distinctColour(k) {
    if (k < COLOURS.length) return COLOURS[k];
    return "hsl(" + Math.round((k * 137.508) % 360) + ", 60%, " + (k % 2 ? 38 : 62) + "%)";
  }
  const cell = (html, sort) => ({ html: String(html), sort: sort === undefined ? String(html) : sort });

  function causes() {
    const C = D.causes;
    if (!C || !C.channels) { $("causes-section").hidden = true; return; }
    const parent = $("causes");
    const colour = {};
    C.channels.forEach((ch) => ch.causes.forEach((c) => {
      if (!(c.name in colour)) colour[c.name] = distinctColour(Object.keys(colour).length);
    }));
    for (const ch of C.channels) {
      if (!ch.time_s) continue;
      const div = document.createElement("div");
      div.className = "cause-channel";
      div.innerHTML = "<h3>Channel " + ch.ch + ": " + ch.time_s.toFixed(3) + " s</h3>" +
        '<div class="cause-bar">' + ch.causes.map((c) => '<span style="width:' + (100 * c.share).toFixed(3) + "%;background:" +
          colour[c.name] + '" title="' + esc(c.name + " " + c.time_s.toFixed(3) + " s") + '"></span>').join("") + "</div>" +
        '<div class="tables"><div class="cause-table"></div><div><h3>Per tool</h3><div class="cause-tools"></div></div>' +
        '<div><h3>Per subroutine / cycle file</h3><div class="cause-files"></div></div></div>' +
        '<h3>The blocks where the most time is lost against length ÷ feed (' +
        Math.min(ch.blocks.length, 2000) + ")</h3>" + '<div class="blocks"></div>';
      parent.appendChild(div);
      sortableTable(div.querySelector(".cause-table"), ["cause", "time (s)", "share"], ch.causes.map((c) => [
        cell('<span class="cause-key" style="background:' + colour[c.name] + '"></span>' + esc(c.name), c.name),
        cell(c.time_s.toFixed(3), c.time_s), cell((100 * c.share).toFixed(1) + " %", c.share)]), [0, 1, 1]);
      // per tool and per file: the time and its largest cause
      const top = (list) => list.length ? list[0].name + " " + (100 * list[0].share).toFixed(1) + " %" : "";
      sortableTable(div.querySelector(".cause-tools"), ["tool", "time (s)", "largest cause"], ch.tools.map((t) => [
        cell(esc(t.tool === "-" ? "(none)" : t.tool)), cell(t.time_s.toFixed(3), t.time_s), cell(esc(top(t.causes)))]), [0, 1, 0]);
      sortableTable(div.querySelector(".cause-files"), ["file", "time (s)", "largest cause"], ch.subroutines.map((f) => [
        cell(esc(base(f.file)) + (f.main ? " (main)" : "")), cell(f.time_s.toFixed(3), f.time_s), cell(esc(top(f.causes)))]), [0, 1, 0]);
      sortableTable(div.querySelector(".blocks"), ["line", "NC text", "runs", "time (s)", "length ÷ feed (s)", "lost (s)", "main cause"],
        ch.blocks.slice(0, 2000).map((b) => [
          cell(esc(base(D.files[b.fid])) + ":" + b.line, b.fid + ":" + String(b.line).padStart(9, "0")),
          cell('<span class="nc">' + esc(lineText(b.fid, b.line) || "line " + b.line + ", text not embedded") + "</span>"),
          cell(b.runs, b.runs), cell(b.time_s.toFixed(3), b.time_s), cell(b.ideal_s.toFixed(3), b.ideal_s),
          cell((Math.abs(b.lost_s) < 5e-4 ? 0 : b.lost_s).toFixed(3), b.lost_s), cell(esc(b.cause))]), [0, 0, 1, 1, 1, 1, 0]);
    }
  }

  // --- the filterable event table ----------------------------------------
  // A field as a reader wants it: numbers to 4 decimals at most, a link's
  // pairs as "slave <- master", other objects as "key value" lists.
  function fieldText(v) {
    if (typeof v === "number") return Number.isInteger(v) ? String(v) : String(+v.toFixed(4));
    if (Array.isArray(v)) return v.map(fieldText).join("; ");
    if (v && typeof v === "object") {
      if ("slave" in v && "master" in v) return v.slave + " ← " + v.master + ("ratio" in v && v.ratio !== 1 ? " × " + fieldText(v.ratio) : "");
      return Object.entries(v).filter(([, x]) => x != null).map(([k, x]) => k + " " + fieldText(x)).join(", ");
    }
    return String(v);
  }

  function events() {
    const kinds = [...new Set(D.events.map((e) => e.ev))];
    for (const k of kinds) $("event-kind").insertAdjacentHTML("beforeend", "<option>" + esc(k) + "</option>");
    const texts = D.events.map((e) => JSON.stringify(e).toLowerCase());
    const render = () => {
      const q = $("event-filter").value.trim().toLowerCase(), kind = $("event-kind").value;
      const rows = [];
      let matches = 0;
      D.events.forEach((e, i) => {
        if ((kind && e.ev !== kind) || (q && !texts[i].includes(q))) return;
        if (++matches > 500) return;
        const rest = Object.entries(e).filter(([k, v]) => k !== "t" && k !== "ch" && k !== "ev" && v != null)
          .map(([k, v]) => "<b>" + esc(k) + "</b> " + esc(fieldText(v))).join(" &nbsp; ");
        rows.push([e.t.toFixed(4), e.ch || "", esc(e.ev), rest]);
      });
      $("events").innerHTML = table(["t (s)", "ch", "event", "fields"], rows, [1, 0, 0, 0]) +
        (matches > 500 ? '<div class="more">' + (matches - 500) + " more rows: narrow the filter</div>" : "") +
        (D.events_dropped ? '<div class="more">' + D.events_dropped + " events are not in this table (see --events)</div>" : "");
      $("event-count").textContent = matches + " of " + D.events.length + " events";
    };
    $("event-filter").addEventListener("input", render);
    $("event-kind").addEventListener("change", render);
    render();
  }

  // A plane view per channel and, beside it, a 3D view where the channel
  // has three linear axes (view3d.js; both halves of the row then).
  function backplots() {
    const parent = $("backplots");
    const list = [], views = [];
    const with3d = (ch) => ch.has.every(Boolean) && window.NckView3d;
    const half = D.channels.some(with3d) ? { width: Math.max(360, Math.floor((parent.clientWidth - 60) / 2)) } : {};
    for (const ch of D.channels) {
      list.push(new NckBackplot(parent, ch, D, half));
      if (with3d(ch)) views.push(new NckView3d(parent, ch, { width: half.width, height: 460 }));
    }
    return { list, views };
  }

  // nck diff --run --report: run B's cycle time and causes beside this run's.
  function ghost() {
    const g = D.ghost;
    if (!g) return;
    $("ghost-section").hidden = false;
    let h = "<p>" + esc(g.label) + " — drawn grey and dashed on channel 1's backplot. Cycle time: this run " +
      D.meta.end_s.toFixed(3) + " s, B " + g.time_s.toFixed(3) + " s (B − A " + (g.time_s - D.meta.end_s).toFixed(3) + " s).</p>";
    (D.causes ? D.causes.channels : []).forEach((ch, c) => {
      const a = {}, b = {};
      for (const r of ch.causes) a[r.name] = r.time_s;
      for (const r of g.causes[c] || []) b[r.name] = r.time_s;
      const names = [...new Set(Object.keys(a).concat(Object.keys(b)))];
      names.sort((x, y) => Math.abs((b[y] || 0) - (a[y] || 0)) - Math.abs((b[x] || 0) - (a[x] || 0)));
      const fmt = (v) => (v == null ? "-" : v.toFixed(3));
      h += "<h3>channel " + ch.ch + "</h3>" + table(["cause", "A (s)", "B (s)", "B − A (s)"],
        names.map((n) => [esc(n), fmt(a[n]), fmt(b[n]), ((b[n] || 0) - (a[n] || 0)).toFixed(3)]), [0, 1, 1, 1]);
    });
    $("ghost").innerHTML = h;
  }

  // --- who waits for whom --------------------------------------------------
  function timeline() {
    if (!D.waits.length) { $("timeline-section").hidden = true; return []; }
    const rows = D.meta.programs.map((p, i) => "channel " + (i + 1));
    const waits = D.waits.map((w) => Object.assign({ where: w.ch ? nLabel(w.file, w.line) : "" }, w));
    return NckTimeline.draw($("timeline"), waits, D.meta.end_s, rows);
  }

  summary();
  diagnostics();
  const { list: bps, views } = backplots();
  const player = new NckPlayer($("player"), D, bps.concat(views), NckBackplot.inverse);
  ghost();
  timeplots();
  cycletime();
  causes();
  const timelineBars = timeline();
  events();
  // For the browser test and for scripting: what was drawn.
  window.nckReport = { data: D, plots, backplots: bps, views3d: views, player, waitText, timeline: timelineBars, loadMs: performance.now() - t0, ready: true };
})();
