// One channel's column of the HMI: its state, DRO, program (with block
// search), live backplot and controls (hmi_controls.js).
(function () {
  "use strict";
  const { el, button, fixed } = window.NckUi;
  const api = window.NckApi;
  const C = window.NckControls;

  const WAITS = window.NckTimeline.REASONS;

  class ChannelPanel {
    // machine: this channel's {axes, spindles}; n: its number (1..);
    // report(error, what): shows a refused command in the errors list.
    constructor(parent, n, machine, report) {
      this.n = n;
      this.axes = machine.axes;
      this.plotAxes = machine.plot_axes || ["X", "Y", "Z"];  // the backplot's X, Y, Z (the twin's X, Y1, Z1)
      this.links = new Map();  // coupling group -> [[slave, master], ...] while it is on (the stream's link events)
      this.report = report;
      this.run = null;
      this.programName = undefined;
      this.send = (command, fields) => api.command(command, n, fields).then(() => true,
        (e) => { report(e, `channel ${n}: ${command}`); return false; });
      this.controls = [C.cyclePanel(this.send), C.overridePanel(this.send), C.skipPanel(this.send),
        C.spindlePanel(this.send, machine.spindles), C.jogPanel(this.send, machine.axes), C.mdiPanel(this.send, n)];
      this.program = new window.NckProgramView((nr, line) => this.search(nr, line),
        (from) => api.get(`/api/v1/program?channel=${n}&from=${from}`), (e) => report(e, `channel ${n}: program text`));
      this.el = el("section", { class: "channel", "data-channel": n },
        this.header(), el("div", { class: "channel-body" },
          el("div", { class: "col controls" }, this.dro(), ...this.controls.map((c) => c.el)),
          el("div", { class: "col program-col" }, this.picker(), this.program.el, this.notice = el("div", { class: "notice" })),
          this.plotCol = el("div", { class: "col plot-col" })));
      parent.append(this.el);
      this.makeBackplot();
    }

    header() {
      this.stateEl = el("span", { class: "state" }, "—");
      this.whyEl = el("span", { class: "why" });
      this.blockEl = el("span", { class: "block" });
      return el("header", { class: "channel-head" }, el("h2", {}, "Channel " + this.n), this.stateEl, this.whyEl, this.blockEl);
    }

    // The DRO: program and machine coordinates and the distance to go per
    // axis (a face-turning axis as a diameter when the machine's
    // display_diameter_pos and G51 say so), path velocity against the
    // programmed feed, and the modal state.
    dro() {
      this.droCells = {};
      const rows = this.axes.map((a) => {
        const name = el("th", {}, a), mcs = el("td", { class: "num" }), pcs = el("td", { class: "num" });
        const dtg = el("td", { class: "num dtg" });
        // homing (P-AXIS-00277): a "not homed" mark and the axis's Home button
        const homed = el("span", { class: "not-homed", title: "not homed: a programmed motion of this axis is refused (930740) until it is homed", hidden: true }, "not homed");
        const home = button("Home", `home ${a} (G74 ${a}1)`, () => this.home([a]), "home");
        this.droCells[a] = { name, mcs, pcs, dtg, homed };
        return el("tr", { "data-axis": a }, name, pcs, mcs, dtg, el("td", { class: "homing" }, homed, home));
      });
      this.velEl = el("td", { class: "num", colspan: 3 });
      this.modalEl = el("td", { class: "modal", colspan: 3 });
      return el("table", { class: "dro panel" },
        el("tr", {}, el("th", {}), el("th", { class: "num" }, "PCS"), el("th", { class: "num" }, "MCS"),
          el("th", { class: "num" }, "to go")), ...rows,
        el("tr", { class: "small" }, el("th", { title: "path velocity / programmed feed" }, "F act/prog"), this.velEl),
        el("tr", { class: "small" }, el("th", {}, "modal"), this.modalEl),
        el("tr", { class: "small" }, el("th", {}), el("td", { colspan: 4 },
          button("Home all", "home every path axis of this channel (G74, all together)", () => this.home(null), "home-all"))));
    }

    // Homing through the server (G74 by MDI); a refusal (940340 in automatic
    // mode, 940341 an unknown axis) goes to the errors list with its ID.
    async home(axes) {
      try {
        await api.home(this.n, axes);
        return true;
      } catch (e) { this.report(e, `channel ${this.n}: home ${axes ? axes.join(" ") : "all"}`); return false; }
    }

    // One DRO row: a face-turning axis in diameter display shows ⌀ and twice its radius.
    // A coupling switched on or off (a `link` event): its slave axes show
    // their master in the DRO while it is on.
    noteLink(e) {
      if (e.on) this.links.set(e.group, e.pairs); else this.links.delete(e.group);
    }
    masterOf(a) {
      for (const pairs of this.links.values()) for (const [slave, master] of pairs) if (slave === a) return master;
      return null;
    }

    droRow(a, c) {
      const cells = this.droCells[a], axis = (c.axes || {})[a] || {};
      const diameter = c.diameter_display && axis.pcs_diameter != null, master = this.masterOf(a);
      cells.name.textContent = (diameter ? "\u2300" + a : a) + (master ? " \u2190 " + master : "");
      cells.name.title = diameter ? "diameter (G51, display_diameter_pos)" : master ? `coupled: ${a} follows ${master}` : "";
      cells.pcs.textContent = fixed(diameter ? axis.pcs_diameter : c.pcs[a], 3);
      cells.mcs.textContent = fixed(c.mcs[a], 3);
      cells.dtg.textContent = fixed(diameter ? 2 * c.dtg[a] : c.dtg[a], 3);
      cells.homed.hidden = axis.homed !== false;  // shown only where the server says "not homed"
      cells.homed.parentElement.parentElement.dataset.homed = axis.homed === false ? "no" : "yes";
    }

    // G codes in force, then D (the tool offset).
    modalText(m) {
      if (!m) return "";
      return [m.motion, m.plane, m.distance, m.units, m.zero_offset, m.radius_comp, m.feed_mode, m.speed_mode,
              m.diameter, m.exact_stop, "D" + m.D].filter((x) => x != null).join(" ");
    }

    // Program picker: a program of /api/v1/programs, loaded into this channel; or an upload.
    picker() {
      this.select = el("select", { "aria-label": "program of channel " + this.n });
      const file = el("input", { type: "file", accept: ".nc,.txt", hidden: true, onchange: () => this.uploadFile(file) });
      return el("div", { class: "picker" }, this.select,
        button("Load", "load the chosen program into this channel", () => this.load(this.select.value), "load"),
        button("Upload…", "upload an NC program from this computer", () => file.click(), "upload"), file);
    }

    programs(list) {
      const keep = this.select.value;
      this.select.replaceChildren(...list.filter((p) => /\.(nc|ecy|txt)$/i.test(p)).map((p) => el("option", { value: p }, p)));
      if (keep) this.select.value = keep;
    }

    async uploadFile(input) {
      const f = input.files[0];
      if (!f) return;
      try {
        const r = await api.upload(f.name, await f.text());
        this.say(`uploaded as ${r.program}`);
        this.onUploaded && this.onUploaded(r.program);
      } catch (e) { this.report(e, `upload ${f.name}`); }
      input.value = "";
    }

    async load(program, startAt) {
      if (!program) return false;
      try {
        await api.command("load", this.n, startAt ? { program, start_at: startAt } : { program });
        return true;
      } catch (e) { this.report(e, `channel ${this.n}: load ${program}`); return false; }
    }

    // A click on a line: load the program with that block as the search mark.
    async search(nr, line) {
      const program = this.programName;
      if (await this.load(program, "N" + nr)) {
        this.say(`block search to N${nr} (line ${line}) staged: Cycle start searches, returns to the contour and holds; Cycle start again continues.`);
        this.searchHint = true;
      }
    }

    // The staged-search hint goes once the kernel took the search: nothing
    // staged any more and the channel searching, returning, held or running.
    followSearchHint(state, c) {
      if (!this.searchHint || state.staged || !["searching", "returning", "hold", "running"].includes(c.state)) return;
      this.searchHint = false;
      this.say("");
    }

    say(text) { this.notice.textContent = text; }

    makeBackplot() {
      const has = this.plotAxes.map((a) => a != null);
      this.plotCh = { n: this.n, plane: "XY", axes: this.plotAxes.map((a, k) => a || "XYZ"[k]), has, x: [], y: [], z: [], px: [], py: [], pz: [], rapid: [], file: [], line: [] };
      // the backplot's hover reads d.lines["file:line"]: the loaded program's text
      const lines = new Proxy({}, { get: (_, key) => this.program.text(Number(String(key).split(":")[1])) });
      const data = { channels: [this.plotCh], files: [""], lines };
      const width = Math.max(320, Math.min(640, this.plotCol.clientWidth - 24));  // the box's padding and border
      this.plot = new window.NckBackplot(this.plotCol, this.plotCh, data, { width, height: Math.round(width * 0.8), minSpan: 20 });
    }

    xyz(pos) { return this.plotAxes.map((a) => (pos && a != null && a in pos ? pos[a] : 0)); }

    // A point on the path where the tool moved (not every snapshot of a standstill).
    track(c) {
      const mcs = this.xyz(c.mcs), pcs = this.xyz(c.pcs), ch = this.plotCh, k = ch.x.length - 1;
      this.plot.setTool(mcs, pcs);
      const rapid = c.cause === "rapid";
      if (this.restoring) return;
      if (k >= 0 && Math.abs(ch.x[k] - mcs[0]) + Math.abs(ch.y[k] - mcs[1]) + Math.abs(ch.z[k] - mcs[2]) < 1e-3) return;
      this.plot.append(mcs, pcs, rapid, 0, c.block.file === this.program.path ? c.block.line : 0);
    }

    // A snapshot (/api/v1/state) and this channel's part of it.
    update(state) {
      const c = state.channels[this.n - 1];
      if (!c) return;
      this.followSearchHint(state, c);
      this.state = c;
      this.stateEl.textContent = c.state;
      this.stateEl.dataset.state = c.state;
      this.whyEl.textContent = c.wait ? "waits for " + (WAITS[c.wait] || c.wait) : c.cause && c.state !== "idle" ? c.cause : "";
      const b = c.block;
      this.blockEl.textContent = b.line ? `${String(b.file).split("/").pop()}:${b.line}${b.n != null ? " N" + b.n : ""}` : "";
      for (const a of this.axes) this.droRow(a, c);
      this.velEl.textContent = `${fixed(c.path_velocity_mm_s * 60, 0)} / ${fixed(c.feed_mm_s * 60, 0)} mm/min`;
      this.modalEl.textContent = this.modalText(c.modal);
      for (const p of this.controls) p.update(c, state);
      this.followProgram(state);
      if (this.run !== state.run) { this.run = state.run; this.plot.clear(); this.restorePath(state.run); }
      this.track(c);
      this.program.highlight(b.file, b.line);
    }

    // A page loaded during a run draws what ran before it: the server keeps
    // the path (GET /api/v1/path); the live points wait until it is drawn.
    async restorePath(run) {
      this.restoring = true;
      try {
        const p = await api.get("/api/v1/path?channel=" + this.n);
        if (p.run === run && this.run === run)
          for (let k = 0; k < p.points; k++)
            this.plot.append([p.x[k], p.y[k], p.z[k]], [p.px[k], p.py[k], p.pz[k]], p.rapid[k] === 1, 0, p.line[k]);
      } catch (e) { this.report(e, `channel ${this.n}: the path so far`); }
      this.restoring = false;
    }

    // The program text follows the loaded program (fetched when it changes).
    async followProgram(state) {
      const name = (state.programs || [])[this.n - 1];
      if (name === this.programName) return;
      this.programName = name;
      if (name) this.select.value = name;
      try {
        const p = await api.get("/api/v1/program?channel=" + this.n);
        this.program.show(p);
        this.plot.data.files[0] = p.path;
        this.plot.setPreview(await api.get("/api/v1/preview?channel=" + this.n));
      } catch (e) { this.report(e, `channel ${this.n}: program text`); }
    }
  }

  window.NckChannelPanel = ChannelPanel;
})();
