// The time cursor (issue 31 item 4): a slider with play/pause and speed
// moves a tool marker along each backplot, highlights the NC line in the
// program panel and shows the DRO (MCS and PCS), the modal state, the
// spindles and the cause at that time. Clicking a line of the program
// panel or a point of a path moves the cursor there.
(function () {
  "use strict";
  const esc = (s) => String(s == null ? "" : s).replace(/[&<>"]/g, (c) => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;" }[c]));
  const fmt = (v, d) => (v == null || !isFinite(v) ? "-" : v.toFixed(d));
  const SPEEDS = [0.1, 0.25, 0.5, 1, 2, 5, 10, 50];
  const PANEL_LINES = 12;  // program lines shown on either side of the current one

  // The last index i with a[i] <= x (0 when none).
  function floorIndex(a, x) {
    let lo = 0, hi = a.length - 1;
    if (!a.length || x < a[0]) return 0;
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if (a[mid] <= x) lo = mid; else hi = mid - 1;
    }
    return lo;
  }

  class Player {
    // backplots: the views that show the tool (backplot.js, view3d.js):
    // anything with the channel's data as `ch` and a setMarker(point).
    constructor(parent, data, backplots, inverse) {
      this.D = data;
      this.bps = backplots;
      this.inverse = inverse;
      this.t = 0;
      this.end = data.meta.end_s;
      this.playing = false;
      this.ch = data.channels[0];
      parent.innerHTML =
        '<div class="player-bar"><button id="play" type="button">▶ play</button>' +
        '<input id="cursor" type="range" min="0" max="1000000" value="0" aria-label="time cursor">' +
        '<span id="cursor-t" class="mono"></span> <label>speed <select id="speed">' +
        SPEEDS.map((s) => "<option" + (s === 1 ? " selected" : "") + ' value="' + s + '">' + s + "×</option>").join("") +
        "</select></label>" +
        (data.channels.length > 1 ? ' <label>channel <select id="player-ch">' +
          data.channels.map((c) => "<option>" + c.n + "</option>").join("") + "</select></label>" : "") +
        '</div><div class="player-panes"><div id="program" class="program mono" aria-label="program text"></div>' +
        '<div id="dro" class="dro"></div></div>';
      this.slider = document.getElementById("cursor");
      this.slider.addEventListener("input", () => this.seek((this.slider.value / 1e6) * this.end));
      document.getElementById("play").addEventListener("click", () => this.toggle());
      this.speed = document.getElementById("speed");
      const chSel = document.getElementById("player-ch");
      if (chSel) chSel.addEventListener("change", () => { this.ch = data.channels[chSel.value - 1]; this.seek(this.t); });
      document.getElementById("program").addEventListener("click", (e) => {
        const row = e.target.closest("[data-line]");
        if (row) this.seekLine(+row.dataset.file, +row.dataset.line);
      });
      document.addEventListener("nck-seek", (e) => {
        this.ch = data.channels[e.detail.ch - 1] || this.ch;
        this.seek(e.detail.t);
      });
      this.seek(0);
    }

    toggle() {
      this.playing = !this.playing;
      document.getElementById("play").textContent = this.playing ? "❚❚ pause" : "▶ play";
      if (!this.playing) return;
      if (this.t >= this.end) this.seek(0);
      let last = performance.now();
      const step = (now) => {
        if (!this.playing) return;
        this.seek(Math.min(this.end, this.t + ((now - last) / 1000) * +this.speed.value));
        last = now;
        if (this.t >= this.end) return this.toggle();
        requestAnimationFrame(step);
      };
      requestAnimationFrame(step);
    }

    // The tool of channel ch at time t: between the path points around t,
    // in the block of the later one. The path is timed (the report's
    // TimedPath): its points are within path_error_mm of every cycle's
    // set point, and the stretch up to each point lies in that point's block.
    toolAt(ch, t) {
      if (!ch.t || !ch.t.length) return null;
      const i = floorIndex(ch.t, t), j = Math.min(i + 1, ch.t.length - 1);
      const span = ch.t[j] - ch.t[i];
      const f = span > 0 && t > ch.t[i] ? Math.min(1, (t - ch.t[i]) / span) : 0;
      const lerp = (a) => a[i] + f * (a[j] - a[i]);
      return { i: f > 0 ? j : i, pos: [lerp(ch.x), lerp(ch.y), lerp(ch.z)] };
    }

    causeAt(ch, t) {
      if (!ch.cause_t || !ch.cause_t.length || t < ch.cause_t[0]) return "-";
      return ch.cause[floorIndex(ch.cause_t, t)];
    }

    // The first cycle of the line's first run: the point before is the
    // last cycle of the block before it.
    seekLine(file, line) {
      const ch = this.ch;
      for (let i = 0; i < ch.line.length; i++)
        if (ch.line[i] === line && ch.file[i] === file) {
          const t0 = i > 0 ? ch.t[i - 1] : ch.t[i];
          return this.seek(Math.min(ch.t[i], t0 + this.D.meta.cycle_s));
        }
    }

    seek(t) {
      this.t = Math.max(0, Math.min(this.end, t));
      this.slider.value = this.end > 0 ? Math.round((this.t / this.end) * 1e6) : 0;
      document.getElementById("cursor-t").textContent = this.t.toFixed(3) + " s of " + this.end.toFixed(3) + " s";
      for (const b of this.bps) {
        const at = this.toolAt(b.ch, this.t);
        b.setMarker(at ? at.pos : null);
      }
      const at = this.toolAt(this.ch, this.t);
      this.at = at;  // for the browser test and for scripting
      this.showProgram(at);
      this.showDro(at);
    }

    showProgram(at) {
      const ch = this.ch, el = document.getElementById("program");
      if (!at) { el.textContent = "No path recorded."; return; }
      const file = ch.file[at.i], line = ch.line[at.i];
      const name = String(this.D.files[file] || "").split("/").pop();
      let h = '<div class="program-file">' + esc(name) + "</div>";
      let gap = false;
      for (let k = Math.max(1, line - PANEL_LINES); k <= line + PANEL_LINES; k++) {
        const text = this.D.lines[file + ":" + k];
        if (text == null && k !== line) { gap = true; continue; }
        if (gap) h += '<div class="gap">…</div>';
        gap = false;
        h += '<div data-file="' + file + '" data-line="' + k + '"' + (k === line ? ' class="now"' : "") + "><span>" + k +
          "</span>" + (text == null ? "<i>line " + k + ", text not embedded</i>" : esc(text)) + "</div>";
      }
      el.innerHTML = h;
      const now = el.querySelector(".now");
      if (now) el.scrollTop = now.offsetTop - el.clientHeight / 2;
    }

    // The DRO: MCS and PCS of the backplot axes, the modal state, the
    // spindles (from the time plots' series) and the cause.
    showDro(at) {
      const ch = this.ch, D = this.D;
      const rows = [];
      if (at) {
        const frame = ch.frame ? ch.frame[at.i] : 0, map = ch.frames && ch.frames[frame];
        const f = map ? this.inverse(map) : (p) => p;
        const pcs = f(at.pos);
        // a face-turning axis under G51 with display_diameter_pos: PCS as a diameter
        const dia = map && map.diameter != null ? map.diameter : -1;
        for (let a = 0; a < 3; a++)
          if (ch.has[a]) rows.push([(a === dia ? "\u2300" : "") + esc(ch.axes[a]), fmt(at.pos[a], 3), fmt(a === dia ? 2 * pcs[a] : pcs[a], 3)]);
      }
      let h = '<table class="dro-axes"><tr><th>axis</th><th class="num">MCS (mm)</th><th class="num">PCS (mm)</th></tr>' +
        rows.map((r) => "<tr><td>" + r[0] + '</td><td class="num">' + r[1] + '</td><td class="num">' + r[2] + "</td></tr>").join("") + "</table>";
      const modal = at ? (ch.rapid[at.i] ? "G0" : "G1/G2/G3 (feed)") + ", plane " + ch.plane : "-";
      const line = at ? ch.line[at.i] : 0;
      const n = line ? /^\s*N(\d+)/i.exec(D.lines[ch.file[at.i] + ":" + line] || "") : null;
      h += '<div class="kv"><b>block</b><span class="block-now">' + (line ? "line " + line + (n ? " (N" + n[1] + ")" : "") : "-") +
        "</span><b>motion</b><span>" + modal +
        "</span><b>cause</b><span class=\"cause-now\">" + esc(this.causeAt(ch, this.t)) + "</span>";
      const ts = D.ts, k = floorIndex(ts.t, this.t);
      D.series.forEach((s, i) => {
        if (s.kind === "velocity" && s.ch === ch.n) h += "<b>path velocity</b><span>" + fmt(ts.v[i][k], 1) + " mm/min</span>";
        if (s.kind === "path_a" && s.ch === ch.n) h += "<b>path acceleration</b><span>" + fmt(ts.v[i][k], 1) + " mm/s²</span>";
        if (s.unit === "rpm") h += "<b>" + esc(s.name) + "</b><span>" + fmt(ts.v[i][k], 1) + " rpm</span>";
      });
      document.getElementById("dro").innerHTML = h + "</div>";
    }
  }

  window.NckPlayer = Player;
})();
