// Backplot: one channel's tool path on a canvas. Views: the planes and an
// isometric one; G0 dashed red, feed moves solid and coloured from blue to
// orange along the program; wheel zooms, drag pans, double-click fits,
// hovering shows the block (NC line) that moved to the nearest point.
// Machine (MCS) or program coordinates (PCS: each point through the inverse
// of its block's program -> machine map); under G41/G42 the programmed
// contour is drawn thin beside the tool-centre path.
// Live use (nck serve's HMI): `append` grows the path point by point (with
// its program coordinates, ch.px/py/pz, where no frames are known) and
// `setTool` marks where the tool stands now, `setPreview` draws the loaded
// program's path before it runs; `opts.width/height` size it.
(function () {
  "use strict";
  const VIEWS = {
    XY: { h: 0, v: 1, label: "XY (G17)" },
    XZ: { h: 0, v: 2, label: "XZ (G18, front)" },
    ZX: { h: 2, v: 0, label: "ZX (lathe: Z right, X up)" },
    YZ: { h: 1, v: 2, label: "YZ (G19)" },
    ISO: { iso: true, label: "isometric" },
  };
  const C30 = Math.cos(Math.PI / 6), S30 = Math.sin(Math.PI / 6);

  function niceStep(range, count) {
    const raw = range / Math.max(1, count);
    const p = Math.pow(10, Math.floor(Math.log10(raw)));
    const m = raw / p;
    return (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * p;
  }

  // The inverse of MCS = r * PCS + s (r row by row, 3 x 3).
  function inverse(f) {
    const r = f.r;
    const a = r[0], b = r[1], c = r[2], d = r[3], e = r[4], g = r[5], h = r[6], k = r[7], l = r[8];
    const A = e * l - g * k, B = -(d * l - g * h), C = d * k - e * h;
    const det = a * A + b * B + c * C || 1;
    const m = [A, -(b * l - c * k), b * g - c * e, B, a * l - c * h, -(a * g - c * d), C, -(a * k - b * h), a * e - b * d]
      .map((v) => v / det);
    return (p) => {
      const q = [p[0] - f.s[0], p[1] - f.s[1], p[2] - f.s[2]];
      return [m[0] * q[0] + m[1] * q[1] + m[2] * q[2], m[3] * q[0] + m[4] * q[1] + m[5] * q[2], m[6] * q[0] + m[7] * q[1] + m[8] * q[2]];
    };
  }

  function fmtNum(v) {
    return Math.abs(v) >= 1000 ? v.toFixed(0) : (+v.toFixed(3)).toString();
  }

  class Backplot {
    constructor(parent, ch, data, opts = {}) {
      this.ch = ch;
      this.data = data;
      this.n = ch.x.length;
      const el = document.createElement("div");
      el.className = "backplot";
      el.dataset.channel = ch.n;
      const bar = document.createElement("div");
      bar.className = "bar";
      const title = document.createElement("b");
      title.textContent = "channel " + ch.n;
      bar.appendChild(title);
      this.select = document.createElement("select");
      this.select.setAttribute("aria-label", "view of channel " + ch.n);
      for (const [key, v] of Object.entries(VIEWS)) {
        if (!v.iso && (!ch.has[v.h] || !ch.has[v.v])) continue;
        if (v.iso && ch.has.filter(Boolean).length < 3) continue;
        const o = document.createElement("option");
        o.value = key;
        o.textContent = v.label;
        this.select.appendChild(o);
      }
      const lathe = !ch.has[1] && ch.has[0] && ch.has[2];
      this.select.value = lathe ? "ZX" : ch.plane === "XZ" ? "XZ" : ch.plane;
      if (!this.select.value && this.select.options.length) this.select.value = this.select.options[0].value;
      this.select.onchange = () => { this.fit(); this.draw(); };
      bar.appendChild(this.select);
      this.coords = document.createElement("select");
      this.coords.setAttribute("aria-label", "coordinates of channel " + ch.n);
      this.coords.innerHTML = '<option value="mcs">machine coordinates (MCS)</option><option value="pcs">program coordinates (PCS)</option>';
      this.coords.onchange = () => { this.fit(); this.draw(); };
      bar.appendChild(this.coords);
      this.toPcs = (ch.frames || []).map(inverse);
      this.contour = ch.contour || [];
      const legend = document.createElement("span");
      legend.innerHTML = '<span class="legend-key"></span>feed <span class="legend-key rapid"></span>G0 rapid' +
        (this.contour.length ? ' <span class="legend-key programmed"></span>programmed contour (G41/G42)' : "") + " &nbsp; mm";
      bar.appendChild(legend);
      el.appendChild(bar);
      this.canvas = document.createElement("canvas");
      el.appendChild(this.canvas);
      this.info = document.createElement("div");
      this.info.className = "info";
      this.info.textContent = "Hover the path for its block; wheel to zoom, drag to pan, double-click to fit.";
      el.appendChild(this.info);
      parent.appendChild(el);
      this.el = el;
      this.multi = data.channels.length > 1;
      this.minSpan = opts.minSpan;
      const width = opts.width || (this.multi ? Math.floor((parent.clientWidth - 60) / 2) : Math.min(parent.clientWidth - 16, 900));
      this.resize(Math.max(opts.width ? 200 : 360, width), opts.height || 460);
      this.bindMouse();
      this.fit();
      this.draw();
    }

    resize(w, h) {
      const dpr = window.devicePixelRatio || 1;
      this.w = w; this.h = h;
      this.canvas.width = w * dpr; this.canvas.height = h * dpr;
      this.canvas.style.width = w + "px"; this.canvas.style.height = h + "px";
      this.el.style.width = w + 14 + "px";  // the title bar wraps instead of widening the box
      this.ctx = this.canvas.getContext("2d");
      this.ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    }

    pcs() { return this.coords.value === "pcs"; }
    frameOf(i) { return this.ch.frame ? this.ch.frame[i] : 0; }
    // Point i (machine coordinates) in the chosen coordinates; `frame`: in
    // that map's program coordinates (the start of a block with a new map).
    point(i, frame) {
      const ch = this.ch, p = [ch.x[i], ch.y[i], ch.z[i]];
      if (!this.pcs()) return p;
      if (ch.px) return [ch.px[i], ch.py[i], ch.pz[i]];
      const f = this.toPcs[frame == null ? this.frameOf(i) : frame];
      return f ? f(p) : p;
    }
    // The view's horizontal and vertical coordinate of a point.
    projectPoint(p) {
      const v = VIEWS[this.select.value] || VIEWS.XY;
      if (v.iso) return [(p[0] - p[1]) * C30, p[2] + (p[0] + p[1]) * S30];
      return [p[v.h], p[v.v]];
    }
    project(i) { return this.projectPoint(this.point(i)); }
    // Where the move to point i starts in the view: point i - 1 in point i's
    // program coordinates (differs from uv[i - 1] only where the map changed).
    segmentStart(i) {
      const f = this.frameOf(i);
      return this.pcs() && f !== this.frameOf(i - 1) ? this.projectPoint(this.point(i - 1, f)) : null;
    }
    contourPoints(run) {
      const pcs = this.pcs(), out = [];
      for (let k = 0; k < run.x.length; k++) out.push(pcs ? [run.px[k], run.py[k], run.pz[k]] : [run.x[k], run.y[k], run.z[k]]);
      return out;
    }

    // The extents of the drawn path per axis, in the chosen coordinates (what the test compares).
    extents() {
      const out = { min: [Infinity, Infinity, Infinity], max: [-Infinity, -Infinity, -Infinity] };
      for (let i = 0; i < this.n; i++) {
        const p = this.point(i);
        for (let a = 0; a < 3; a++) {
          out.min[a] = Math.min(out.min[a], p[a]);
          out.max[a] = Math.max(out.max[a], p[a]);
        }
      }
      return out;
    }

    fit() {
      let lo = [Infinity, Infinity], hi = [-Infinity, -Infinity];
      this.uv = new Float64Array(this.n * 2);
      for (let i = 0; i < this.n; i++) {
        const q = this.project(i);
        this.uv[2 * i] = q[0]; this.uv[2 * i + 1] = q[1];
        for (let k = 0; k < 2; k++) { lo[k] = Math.min(lo[k], q[k]); hi[k] = Math.max(hi[k], q[k]); }
      }
      this.jumps = new Map();  // point -> start of its move, where the map changed (PCS)
      for (let i = 1; i < this.n; i++) {
        const s = this.segmentStart(i);
        if (s) this.jumps.set(i, s);
      }
      this.pv = this.previewUV();
      for (const q of this.pv) {  // the program's preview is in view before it runs
        for (let k = 0; k < 2; k++) { lo[k] = Math.min(lo[k], q[k]); hi[k] = Math.max(hi[k], q[k]); }
      }
      if (lo[0] > hi[0]) { lo = [0, 0]; hi = [1, 1]; }
      const least = this.minSpan || 1e-3;
      const span = [Math.max(hi[0] - lo[0], least), Math.max(hi[1] - lo[1], least)];
      const m = 40;
      this.scale = Math.min((this.w - 2 * m) / span[0], (this.h - 2 * m) / span[1]);
      this.cx = (lo[0] + hi[0]) / 2; this.cy = (lo[1] + hi[1]) / 2;
    }

    toScreen(u, v) { return [this.w / 2 + (u - this.cx) * this.scale, this.h / 2 - (v - this.cy) * this.scale]; }
    toModel(x, y) { return [this.cx + (x - this.w / 2) / this.scale, this.cy - (y - this.h / 2) / this.scale]; }

    drawGrid(ctx) {
      const view = VIEWS[this.select.value] || VIEWS.XY;
      const [u0, v1] = this.toModel(0, 0), [u1, v0] = this.toModel(this.w, this.h);
      const step = niceStep(Math.max(u1 - u0, v1 - v0), 10);
      ctx.strokeStyle = "#e6e9ef"; ctx.fillStyle = "#667085"; ctx.lineWidth = 1; ctx.setLineDash([]);
      ctx.font = "11px system-ui, sans-serif";
      ctx.beginPath();
      for (let u = Math.ceil(u0 / step) * step; u <= u1; u += step) {
        const [x] = this.toScreen(u, 0);
        ctx.moveTo(x, 0); ctx.lineTo(x, this.h);
        if (!view.iso) ctx.fillText(fmtNum(u), x + 2, this.h - 4);  // isometric: no axis runs along the screen
      }
      for (let v = Math.ceil(v0 / step) * step; v <= v1; v += step) {
        const [, y] = this.toScreen(0, v);
        ctx.moveTo(0, y); ctx.lineTo(this.w, y);
        if (!view.iso) ctx.fillText(fmtNum(v), 2, y - 2);
      }
      ctx.stroke();
      const names = this.ch.axes;
      ctx.fillStyle = "#1d2330"; ctx.font = "12px system-ui, sans-serif";
      if (!view.iso) {
        ctx.fillText(names[view.h] + " (mm) →", this.w - 80, this.h - 18);
        ctx.fillText("↑ " + names[view.v] + " (mm)", 40, 14);
      } else {
        ctx.fillText("isometric: X, Y, Z (mm)", 8, 14);
      }
      // the machine zero, where it is in view
      const [zx, zy] = this.toScreen(0, 0);
      ctx.strokeStyle = "#98a2b3"; ctx.beginPath();
      ctx.moveTo(zx - 6, zy); ctx.lineTo(zx + 6, zy); ctx.moveTo(zx, zy - 6); ctx.lineTo(zx, zy + 6); ctx.stroke();
    }

    draw() {
      const ctx = this.ctx, ch = this.ch, n = this.n;
      ctx.clearRect(0, 0, this.w, this.h);
      ctx.fillStyle = "#fff"; ctx.fillRect(0, 0, this.w, this.h);
      this.drawGrid(ctx);
      this.drawPreview(ctx);
      ctx.lineWidth = 1.4; ctx.lineJoin = "round";
      const batch = Math.max(1, Math.ceil(n / 200));  // colour changes along the program in ~200 steps
      let i = 1;
      while (i < n) {
        const rapid = ch.rapid[i] === 1;
        const end = Math.min(n, i + batch);
        ctx.beginPath();
        let [x, y] = this.toScreen(this.uv[2 * i - 2], this.uv[2 * i - 1]);
        ctx.moveTo(x, y);
        let j = i;
        for (; j < end && (ch.rapid[j] === 1) === rapid; j++) {
          const s = this.jumps.get(j);
          if (s) ctx.moveTo(...this.toScreen(s[0], s[1]));
          [x, y] = this.toScreen(this.uv[2 * j], this.uv[2 * j + 1]);
          ctx.lineTo(x, y);
        }
        if (rapid) { ctx.strokeStyle = "#d62728"; ctx.setLineDash([5, 4]); }
        else { ctx.strokeStyle = "hsl(" + (215 - 185 * (i / n)).toFixed(0) + ",75%,42%)"; ctx.setLineDash([]); }
        ctx.stroke();
        i = j;
      }
      ctx.setLineDash([]);
      // the programmed contour under G41/G42: thin, on top
      ctx.strokeStyle = "rgba(17,17,17,0.85)"; ctx.lineWidth = 0.9;
      for (const run of this.contour) {
        ctx.beginPath();
        this.contourPoints(run).forEach((p, k) => {
          const [x, y] = this.toScreen(...this.projectPoint(p));
          if (k === 0) ctx.moveTo(x, y); else ctx.lineTo(x, y);
        });
        ctx.stroke();
      }
      // moves along the viewing direction (drilling, plunging in XY) as rings
      ctx.strokeStyle = "#344054"; ctx.lineWidth = 1.2;
      for (let k = 1; k < n; k++) {
        const du = this.uv[2 * k] - this.uv[2 * k - 2], dv = this.uv[2 * k + 1] - this.uv[2 * k - 1];
        if ((du * du + dv * dv) * this.scale * this.scale > 0.25 || ch.rapid[k] === 1) continue;
        // a plunge moves at least 2 px out of the plane; a short arc chord that is also short in
        // space (the benchmark's 0.25 mm semicircles) is no plunge and gets no ring
        const moved = Math.abs(ch.x[k] - ch.x[k - 1]) + Math.abs(ch.y[k] - ch.y[k - 1]) + Math.abs(ch.z[k] - ch.z[k - 1]);
        if (moved < 1e-3 || moved * this.scale < 2) continue;
        const [x, y] = this.toScreen(this.uv[2 * k], this.uv[2 * k + 1]);
        ctx.beginPath(); ctx.arc(x, y, 4, 0, 2 * Math.PI); ctx.stroke();
      }
      if (this.tool) this.drawTool(ctx);
      this.drawGhost(ctx);
      if (this.hover != null) {
        const [hx, hy] = this.toScreen(...this.hoverUV);
        ctx.strokeStyle = "#111"; ctx.lineWidth = 2; ctx.beginPath(); ctx.arc(hx, hy, 5, 0, 2 * Math.PI); ctx.stroke();
      }
      if (this.marker) {  // the time cursor's tool position
        const [mx, my] = this.toScreen(...this.projectPoint(this.marker));
        ctx.fillStyle = "#111"; ctx.strokeStyle = "#fff"; ctx.lineWidth = 2;
        ctx.beginPath(); ctx.arc(mx, my, 6, 0, 2 * Math.PI); ctx.fill(); ctx.stroke();
      }
    }

    // The tool where it stands now: a ring with a cross, over the path.
    drawTool(ctx) {
      const [x, y] = this.toScreen(...this.projectPoint(this.pcs() && this.tool.pcs ? this.tool.pcs : this.tool.mcs));
      ctx.strokeStyle = "#111"; ctx.fillStyle = "rgba(255, 200, 0, 0.55)"; ctx.lineWidth = 1.5;
      ctx.beginPath(); ctx.arc(x, y, 7, 0, 2 * Math.PI); ctx.fill(); ctx.stroke();
      ctx.beginPath(); ctx.moveTo(x - 11, y); ctx.lineTo(x + 11, y); ctx.moveTo(x, y - 11); ctx.lineTo(x, y + 11); ctx.stroke();
    }

    // Where the tool stands (machine and program coordinates, [x, y, z]).
    setTool(mcs, pcs) {
      this.tool = { mcs, pcs };
      this.redrawSoon();
    }

    // One more point of a live path: machine and program coordinates, G0 or
    // not, the block's file index and line. The view follows the path until
    // the operator zooms or pans it.
    append(mcs, pcs, rapid, file, line) {
      const ch = this.ch;
      ch.x.push(mcs[0]); ch.y.push(mcs[1]); ch.z.push(mcs[2]);
      ch.px.push(pcs[0]); ch.py.push(pcs[1]); ch.pz.push(pcs[2]);
      ch.rapid.push(rapid ? 1 : 0); ch.file.push(file); ch.line.push(line);
      this.n = ch.x.length;
      if (this.uv.length < 2 * this.n) {
        const grown = new Float64Array(Math.max(1024, 4 * this.n));
        grown.set(this.uv);
        this.uv = grown;
      }
      const q = this.project(this.n - 1);
      this.uv[2 * this.n - 2] = q[0]; this.uv[2 * this.n - 1] = q[1];
      const [sx, sy] = this.toScreen(q[0], q[1]);
      if (!this.moved && (sx < 20 || sy < 20 || sx > this.w - 20 || sy > this.h - 20)) {
        this.fit();
        this.scale /= 1.3;  // room to grow: not a refit for every point of a path that widens
      }
      this.redrawSoon();
    }

    // Forget the path (a new run).
    clear() {
      for (const k of ["x", "y", "z", "px", "py", "pz", "rapid", "file", "line"]) this.ch[k] = [];
      this.n = 0; this.moved = false; this.hover = null;
      this.fit();
      this.redrawSoon();
    }

    // At most one redraw per frame however many points arrive.
    redrawSoon() {
      if (this.pending) return;
      this.pending = true;
      requestAnimationFrame(() => { this.pending = false; this.draw(); });
    }

    // nck serve's HMI: the loaded program's path before it runs (GET
    // /api/v1/preview: x/y/z machine, px/py/pz program coordinates), under
    // the live path, light grey, G0 dashed.
    setPreview(p) {
      this.preview = p && p.points ? p : null;
      if (this.moved) this.pv = this.previewUV(); else this.fit();
      this.redrawSoon();
    }
    previewUV() {
      const p = this.preview, out = [];
      if (!p) return out;
      const [x, y, z] = this.pcs() ? [p.px, p.py, p.pz] : [p.x, p.y, p.z];
      for (let k = 0; k < x.length; k++) out.push(this.projectPoint([x[k], y[k], z[k]]));
      return out;
    }
    // One stroke per run of G0 or feed points (a preview has up to 100,000).
    drawPreview(ctx) {
      const uv = this.pv || [], rapid = this.preview ? this.preview.rapid : [];
      ctx.lineWidth = 1; ctx.strokeStyle = "#a8b0bd";
      for (let k = 1; k < uv.length;) {
        const g0 = rapid[k] === 1;
        ctx.setLineDash(g0 ? [4, 4] : []);
        ctx.beginPath(); ctx.moveTo(...this.toScreen(...uv[k - 1]));
        for (; k < uv.length && (rapid[k] === 1) === g0; k++) ctx.lineTo(...this.toScreen(...uv[k]));
        ctx.stroke();
      }
      ctx.setLineDash([]);
    }

    // nck diff --run --report: the other run's path (machine coordinates), grey and dashed.
    drawGhost(ctx) {
      const g = this.data.ghost;
      if (!g || this.ch.n !== 1 || this.pcs()) return;
      const p = g.path;
      ctx.strokeStyle = "rgba(90,90,90,0.7)"; ctx.lineWidth = 1.2; ctx.setLineDash([3, 3]);
      ctx.beginPath();
      for (let k = 0; k < p.x.length; k++) {
        const [x, y] = this.toScreen(...this.projectPoint([p.x[k], p.y[k], p.z[k]]));
        if (k === 0) ctx.moveTo(x, y); else ctx.lineTo(x, y);
      }
      ctx.stroke(); ctx.setLineDash([]);
    }

    // The time cursor: the tool at point p (machine coordinates), or none.
    setMarker(p) { this.marker = p; this.draw(); }

    // The path point nearest to the mouse, anywhere along a segment: the
    // segment's end point (the block that moved there) and where on it.
    nearest(px, py) {
      let best = -1, bestD = 12 * 12, at = null;
      const [mu, mv] = this.toModel(px, py);
      for (let i = 0; i < this.n; i++) {
        const u1 = this.uv[2 * i], v1 = this.uv[2 * i + 1];
        const u0 = i > 0 ? this.uv[2 * i - 2] : u1, v0 = i > 0 ? this.uv[2 * i - 1] : v1;
        const du = u1 - u0, dv = v1 - v0, dd = du * du + dv * dv;
        const f = dd > 0 ? Math.max(0, Math.min(1, ((mu - u0) * du + (mv - v0) * dv) / dd)) : 1;
        const qu = u0 + f * du, qv = v0 + f * dv;
        const d = ((qu - mu) * (qu - mu) + (qv - mv) * (qv - mv)) * this.scale * this.scale;
        if (d < bestD) { bestD = d; best = i; at = { uv: [qu, qv], f }; }
      }
      this.hoverUV = at ? at.uv : null;
      this.hoverF = at ? at.f : 1;
      return best;
    }

    describe(i) {
      const ch = this.ch, d = this.data;
      const text = d.lines[ch.file[i] + ":" + ch.line[i]] || "";
      const file = d.files[ch.file[i]] || "";
      const p = this.point(i);
      const pos = ch.axes.map((a, k) => (ch.has[k] ? a + " " + fmtNum(p[k]) : "")).filter(Boolean).join("  ");
      return (ch.line[i] ? file.split("/").pop() + ":" + ch.line[i] + "  " + text.trim() : "before the first block") +
        "  —  " + (ch.rapid[i] ? "G0 to " : "to ") + pos + " mm " + (this.pcs() ? "(PCS)" : "(MCS)");
    }

    bindMouse() {
      const c = this.canvas;
      let drag = null;
      c.addEventListener("wheel", (e) => {
        e.preventDefault();
        const r = c.getBoundingClientRect();
        const [u, v] = this.toModel(e.clientX - r.left, e.clientY - r.top);
        const f = Math.exp(-e.deltaY * 0.0015);
        this.scale *= f;
        this.moved = true;
        this.cx = u - (u - this.cx) / f; this.cy = v - (v - this.cy) / f;
        this.draw();
      }, { passive: false });
      c.addEventListener("mousedown", (e) => { drag = { x: e.clientX, y: e.clientY, cx: this.cx, cy: this.cy }; this.dragged = false; });
      window.addEventListener("mouseup", () => { drag = null; });
      c.addEventListener("mousemove", (e) => {
        if (drag) {
          this.dragged = this.dragged || Math.abs(e.clientX - drag.x) + Math.abs(e.clientY - drag.y) > 3;
          this.cx = drag.cx - (e.clientX - drag.x) / this.scale;
          this.cy = drag.cy + (e.clientY - drag.y) / this.scale;
          this.moved = true;
          this.draw();
          return;
        }
        const r = c.getBoundingClientRect();
        const i = this.nearest(e.clientX - r.left, e.clientY - r.top);
        this.hover = i >= 0 ? i : null;
        this.info.textContent = i >= 0 ? this.describe(i) : "";
        this.draw();
      });
      c.addEventListener("dblclick", () => { this.moved = false; this.fit(); this.draw(); });
      // a click on the path moves the time cursor there (player.js listens)
      c.addEventListener("click", (e) => {
        const r = c.getBoundingClientRect();
        const i = this.nearest(e.clientX - r.left, e.clientY - r.top);
        if (i < 0 || !this.ch.t || this.dragged) return;
        const t0 = i > 0 ? this.ch.t[i - 1] : this.ch.t[i];
        const t = t0 + this.hoverF * (this.ch.t[i] - t0);
        this.el.dispatchEvent(new CustomEvent("nck-seek", { bubbles: true, detail: { ch: this.ch.n, t } }));
      });
      c.addEventListener("dblclick", () => { this.fit(); this.draw(); });
    }
  }

  Backplot.inverse = inverse;  // player.js: the DRO's PCS
  window.NckBackplot = Backplot;
})();
