// The 3D view (issue 31 item 4): one channel's tool path in machine
// coordinates, beside its plane view, for a channel with three linear axes.
// Drag rotates, the wheel zooms (towards the mouse), right-drag or
// shift-drag pans, double-click fits the path. G0 dashed red, feed moves
// coloured from blue to orange along the program as in backplot.js; the
// machine's software limits (kenngr.swe_neg/swe_pos) as a box; the player's
// time cursor as a tool (a cone whose tip is the point).
// It draws the backplot's own arrays (ch.x/y/z, ch.rapid): the page carries
// no second copy of the path. Renders on demand (a camera move, the cursor),
// never in a loop. This file is an ES module: the build bundles it with
// three.js (esbuild, CMakeLists.txt) into the report as window.NckView3d.
import {
  BufferGeometry, Color, ConeGeometry, Float32BufferAttribute, Group, LineBasicMaterial, LineDashedMaterial,
  LineSegments, Mesh, MeshBasicMaterial, OrthographicCamera, Scene, Vector3, WebGLRenderer,
} from "three";
import { OrbitControls } from "three/addons/controls/OrbitControls.js";

const RAPID = 0xd62728, LIMITS = 0x667085, AXES = [0xe8590c, 0x2ca02c, 0x1f6feb];
const MARKER_PX = 22;  // the tool marker's height on screen, whatever the zoom

// Vertex pairs (one per segment) of the moves that are (or are not) G0:
// segment i runs from point i - 1 to point i, coloured by point i.
function segments(ch, rapid) {
  const pos = [], col = [], n = ch.x.length, c = new Color();
  for (let i = 1; i < n; i++) {
    if ((ch.rapid[i] === 1) !== rapid) continue;
    pos.push(ch.x[i - 1], ch.y[i - 1], ch.z[i - 1], ch.x[i], ch.y[i], ch.z[i]);
    if (rapid) continue;
    c.setHSL((215 - 185 * (i / n)) / 360, 0.75, 0.42);  // backplot.js's colour along the program
    col.push(c.r, c.g, c.b, c.r, c.g, c.b);
  }
  const g = new BufferGeometry();
  g.setAttribute("position", new Float32BufferAttribute(pos, 3));
  if (!rapid) g.setAttribute("color", new Float32BufferAttribute(col, 3));
  return g;
}

// The twelve edges of the box min..max.
function boxEdges(min, max) {
  const p = [];
  const corner = (k) => [k & 1 ? max[0] : min[0], k & 2 ? max[1] : min[1], k & 4 ? max[2] : min[2]];
  for (let k = 0; k < 8; k++)
    for (const bit of [1, 2, 4]) if (!(k & bit)) p.push(...corner(k), ...corner(k | bit));
  const g = new BufferGeometry();
  g.setAttribute("position", new Float32BufferAttribute(p, 3));
  return g;
}

// X, Y and Z from the machine zero, `len` long (the backplot's colours are not reused: red is G0).
function axesAt(len) {
  const g = new Group();
  AXES.forEach((colour, a) => {
    const end = [0, 0, 0];
    end[a] = len;
    const geo = new BufferGeometry();
    geo.setAttribute("position", new Float32BufferAttribute([0, 0, 0, ...end], 3));
    g.add(new LineSegments(geo, new LineBasicMaterial({ color: colour })));
  });
  return g;
}

function bounds(ch) {
  const min = [Infinity, Infinity, Infinity], max = [-Infinity, -Infinity, -Infinity];
  const P = [ch.x, ch.y, ch.z];
  for (let a = 0; a < 3; a++)
    for (const v of P[a]) { if (v < min[a]) min[a] = v; if (v > max[a]) max[a] = v; }
  if (!ch.x.length) return { min: [0, 0, 0], max: [1, 1, 1] };
  return { min, max };
}

export class View3d {
  constructor(parent, ch, opts = {}) {
    this.ch = ch;
    const l = ch.limits;  // null for an axis the channel lacks: then no box
    this.limits = l && l.min.concat(l.max).every((v) => v != null) ? l : null;
    const el = document.createElement("div");
    el.className = "backplot view3d";
    el.dataset.channel = ch.n;
    el.innerHTML = '<div class="bar"><b>channel ' + ch.n + ": 3D (MCS)</b>" +
      '<button type="button" data-fit="path">fit path</button>' +
      (this.limits ? '<button type="button" data-fit="limits">fit soft limits</button>' +
        '<label><input type="checkbox" data-show="limits" checked> soft limits</label>' : "") +
      '<span><span class="legend-key"></span>feed <span class="legend-key rapid"></span>G0 rapid' +
      (this.limits ? ' <span class="legend-key limits"></span>software limits' : "") +
      ' &nbsp; <span class="axis-key x">X</span> <span class="axis-key y">Y</span> <span class="axis-key z">Z</span></span></div>';
    this.info = document.createElement("div");
    this.info.className = "info";
    this.info.textContent = "Drag to rotate, wheel to zoom, right-drag or shift-drag to pan, double-click to fit the path.";
    parent.appendChild(el);
    this.el = el;
    this.w = opts.width || 560;
    this.h = opts.height || 460;
    try {
      this.renderer = new WebGLRenderer({ antialias: true });
    } catch (e) {  // no WebGL (a locked-down browser): say so instead of a blank box
      this.info.textContent = "The 3D view needs WebGL, which this browser does not offer.";
      el.appendChild(this.info);
      el.style.width = this.w + 14 + "px";
      return;
    }
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    this.renderer.setSize(this.w, this.h);
    this.renderer.setClearColor(0xffffff);
    this.canvas = this.renderer.domElement;
    el.appendChild(this.canvas);
    el.appendChild(this.info);
    el.style.width = this.w + 14 + "px";
    this.build();
    this.bindUi();
    this.fit("path");
  }

  build() {
    const ch = this.ch;
    this.scene = new Scene();
    this.box = bounds(ch);
    const size = Math.max(...[0, 1, 2].map((a) => this.box.max[a] - this.box.min[a]), 1e-3);
    this.feed = new LineSegments(segments(ch, false), new LineBasicMaterial({ vertexColors: true }));
    this.rapid = new LineSegments(segments(ch, true),
      new LineDashedMaterial({ color: RAPID, dashSize: size / 120, gapSize: size / 160 }));
    this.rapid.computeLineDistances();
    this.scene.add(this.feed, this.rapid);
    if (this.limits) {
      this.limitBox = new LineSegments(boxEdges(this.limits.min, this.limits.max), new LineBasicMaterial({ color: LIMITS }));
      this.limitBox.name = "software limits";
      this.scene.add(this.limitBox);
    }
    this.scene.add(axesAt(size / 5));
    const cone = new ConeGeometry(0.3, 1, 16);
    cone.rotateX(-Math.PI / 2);   // the tip towards -Z, as a tool points
    cone.translate(0, 0, 0.5);    // and at the origin: the marker's position is the tool tip
    this.marker = new Mesh(cone, new MeshBasicMaterial({ color: 0x111111 }));
    this.marker.visible = false;
    this.scene.add(this.marker);
    // orthographic, as a machine drawing: the limit box, far or near, stays a box and does not
    // sweep perspective lines across the path
    this.camera = new OrthographicCamera(-1, 1, 1, -1, 0, 1);
    this.camera.up.set(0, 0, 1);  // Z up, as on the machine (before the controls read it)
    this.controls = new OrbitControls(this.camera, this.canvas);
    this.controls.screenSpacePanning = true;
    this.controls.zoomToCursor = true;
    this.controls.addEventListener("change", () => this.renderSoon());
  }

  bindUi() {
    this.el.querySelectorAll("[data-fit]").forEach((b) => b.addEventListener("click", () => this.fit(b.dataset.fit)));
    const show = this.el.querySelector("[data-show=limits]");
    if (show) show.addEventListener("change", () => { this.limitBox.visible = show.checked; this.renderSoon(); });
    this.canvas.addEventListener("dblclick", () => this.fit("path"));
    this.canvas.addEventListener("contextmenu", (e) => e.preventDefault());
  }

  // Looks at the path's (or the limits') box from the front right, above;
  // the box's bounding sphere fills the view's height.
  fit(what) {
    if (!this.camera) return;
    const b = what === "limits" && this.limits ? this.limits : this.box;
    const centre = new Vector3((b.min[0] + b.max[0]) / 2, (b.min[1] + b.max[1]) / 2, (b.min[2] + b.max[2]) / 2);
    const radius = Math.max(Math.hypot(b.max[0] - b.min[0], b.max[1] - b.min[1], b.max[2] - b.min[2]) / 2, 1e-3);
    const c = this.camera, aspect = this.w / this.h;
    c.top = radius; c.bottom = -radius; c.left = -radius * aspect; c.right = radius * aspect; c.zoom = 1;
    // the camera stands outside the whole scene (path, limits) at any rotation: nothing is clipped
    const scene = [this.box, this.limits].filter(Boolean).map((x) => Math.hypot(...[0, 1, 2].map((a) => x.max[a] - x.min[a])));
    const dist = Math.max(radius, ...scene) * 2 + Math.hypot(centre.x, centre.y, centre.z);
    c.position.copy(centre).add(new Vector3(1, -1.4, 1).normalize().multiplyScalar(dist));
    c.near = 0;
    c.far = 2 * dist;
    c.updateProjectionMatrix();
    this.controls.target.copy(centre);
    this.controls.update();
    this.renderSoon();
  }

  // The time cursor: the tool at p (machine coordinates), or none (player.js).
  setMarker(p) {
    if (!this.marker) return;
    this.marker.visible = !!p;
    if (p) this.marker.position.set(p[0], p[1], p[2]);
    this.markerAt = p;
    this.renderSoon();
  }

  // Where the camera stands and looks (the browser test rotates the view and compares).
  cameraState() {
    if (!this.camera) return null;
    const r = (v) => [v.x, v.y, v.z].map((x) => +x.toFixed(4));
    return { position: r(this.camera.position), target: r(this.controls.target) };
  }

  renderSoon() {
    if (this.pending) return;
    this.pending = true;
    requestAnimationFrame(() => { this.pending = false; this.render(); });
  }

  render() {
    const c = this.camera;  // the marker keeps its size on screen at any zoom
    this.marker.scale.setScalar(((c.top - c.bottom) / c.zoom) * (MARKER_PX / this.h));
    this.renderer.render(this.scene, this.camera);
    this.canvas.dataset.camera = JSON.stringify(this.cameraState());
  }
}

window.NckView3d = View3d;
