// Browser checks of the report's 3D view (web/view3d.js) and of the path
// acceleration/jerk plot; report_test.mjs calls them for the cases that ask
// (report_cases.mjs: `view3d`, `accel`).

// The 3D view of channel 1: drawn from the backplot's points, the soft-limit
// box of the machine data, the player's tool marker, and a mouse drag on its
// canvas rotates the camera about the path (the target stays).
export async function check3d(page, name, want, { fail, ok }) {
  const info = await page.evaluate(() => {
    const v = window.nckReport.views3d[0], b = window.nckReport.backplots[0];
    if (!v) return null;
    if (!v.renderer) return { noGl: v.info.textContent };
    v.canvas.scrollIntoView({ block: "center" });
    const box = v.limitBox;
    if (box) box.geometry.computeBoundingBox();
    const bb = box && box.geometry.boundingBox;
    // what the canvas shows now: render and read back in the same task (the drawing buffer is kept until then)
    v.render();
    const gl = v.renderer.getContext(), w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
    const px = new Uint8Array(w * h * 4);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, px);
    let drawn = 0, red = 0;
    for (let i = 0; i < px.length; i += 4) {
      if (px[i] < 250 || px[i + 1] < 250 || px[i + 2] < 250) drawn++;
      // the G0 colour (or its antialiased blend with white: g and b alike), not the X axis' orange
      if (px[i] - px[i + 1] > 60 && Math.abs(px[i + 1] - px[i + 2]) < 20) red++;
    }
    return {
      segments: v.feed.geometry.getAttribute("position").count / 2 + v.rapid.geometry.getAttribute("position").count / 2,
      points: b.n, sharesData: v.ch === b.ch,
      limits: v.limits, box: bb && { min: bb.min.toArray(), max: bb.max.toArray() }, boxShown: !!box && box.visible,
      inScene: !!v.scene.getObjectByName("software limits"),
      marker: v.markerAt, planeMarker: b.marker, markerShown: v.marker.visible,
      drawn, red, rapids: v.rapid.geometry.getAttribute("position").count / 2, camera: v.cameraState(), attr: v.canvas.dataset.camera,
      // G0 segments that move (the timed path has points where a G0 block stands still: they draw nothing)
      movingRapids: b.ch.rapid.filter((r, i) => r && i > 0 && (b.ch.x[i] !== b.ch.x[i - 1] || b.ch.y[i] !== b.ch.y[i - 1] || b.ch.z[i] !== b.ch.z[i - 1])).length,
    };
  });
  if (!info) return fail(name, "no 3D view");
  if (info.noGl) return fail(name, "3D view without WebGL: " + info.noGl);
  if (!info.sharesData || info.segments !== info.points - 1)
    fail(name, `3D path: ${info.segments} segments for ${info.points} backplot points (shared data: ${info.sharesData})`);
  else ok(name, `3D path: ${info.segments} segments of the backplot's own ${info.points} points`);
  const near = (a, b) => a && b && a.every((v, k) => Math.abs(v - b[k]) < 1e-6);
  if (!info.inScene || !info.boxShown || !near(info.box.min, want.limits.min) || !near(info.box.max, want.limits.max) ||
      !near(info.limits.min, want.limits.min))
    fail(name, `soft-limit box ${JSON.stringify(info.box)} (shown ${info.boxShown}), machine data ${JSON.stringify(want.limits)}`);
  else ok(name, `soft-limit box ${JSON.stringify(info.box)} as the machine data`);
  if (info.drawn < 500 || (info.movingRapids > 0) !== (info.red > 5))
    fail(name, `3D canvas: ${info.drawn} drawn pixels, ${info.red} of G0 red for ${info.movingRapids} G0 segments that move`);
  else ok(name, `3D canvas: ${info.drawn} drawn pixels, ${info.red} of G0 red`);
  if (!info.markerShown || !near(info.marker, info.planeMarker))
    fail(name, `3D tool marker ${JSON.stringify(info.marker)} (shown ${info.markerShown}), plane view's ${JSON.stringify(info.planeMarker)}`);
  else ok(name, `3D tool marker at the time cursor's point ${info.marker.map((v) => v.toFixed(3))}`);
  // rotate: drag across the canvas with the left button
  const r = await page.evaluate(() => {
    const c = window.nckReport.views3d[0].canvas.getBoundingClientRect();
    return { x: c.left + c.width / 2, y: c.top + c.height / 2 };
  });
  await page.mouse.move(r.x, r.y);
  await page.mouse.down();
  await page.mouse.move(r.x + 120, r.y + 40, { steps: 8 });
  await page.mouse.up();
  await page.waitForTimeout(100);  // renders on the next frame
  const after = await page.evaluate(() => {
    const v = window.nckReport.views3d[0];
    return { camera: v.cameraState(), attr: v.canvas.dataset.camera };
  });
  const moved = Math.hypot(...after.camera.position.map((v, k) => v - info.camera.position[k]));
  if (!(moved > 1e-3) || !near(after.camera.target, info.camera.target) || after.attr === info.attr)
    fail(name, `dragging the 3D view: camera ${JSON.stringify(info.camera)} -> ${JSON.stringify(after.camera)}`);
  else ok(name, `dragging rotates the 3D view: the camera moved ${moved.toFixed(2)} mm about ${after.camera.target}`);
  await page.mouse.move(0, 0);
}

// The channel's path acceleration and jerk: one panel, path.a in mm/s² and
// path.j in mm/s³, every value finite and some not zero.
export async function checkAccel(page, name, want, { fail, ok }) {
  const got = await page.evaluate((want) => {
    const p = window.nckReport.plots.find((p) => p.title === want.panel);
    if (!p) return null;
    const labels = p.u.series.slice(1).map((s) => s.label);
    const axes = p.u.axes.slice(1).map((a) => a.label);
    const data = p.u.data.slice(1).map((v) => ({
      finite: v.every((x) => x != null && Number.isFinite(x)), n: v.length,
      max: v.reduce((m, x) => Math.max(m, Math.abs(x)), 0),
    }));
    return { labels, axes, data, legend: [...p.u.root.querySelectorAll(".u-legend .u-label")].map((e) => e.textContent) };
  }, want);
  if (!got) return fail(name, `no panel "${want.panel}"`);
  const labels = ["path.a (mm/s²)", "path.j (mm/s³)"];
  if (JSON.stringify(got.labels) !== JSON.stringify(labels) || !labels.every((l) => got.legend.includes(l)) ||
      JSON.stringify(got.axes) !== JSON.stringify(["mm/s²", "mm/s³"]))
    return fail(name, `acceleration/jerk panel: series ${got.labels}, legend ${got.legend}, axes ${got.axes}`);
  if (got.data.some((d) => !d.finite || d.n < 2 || !(d.max > 0)))
    return fail(name, `acceleration/jerk values: ${JSON.stringify(got.data)}`);
  ok(name, `path.a up to ${got.data[0].max} mm/s², path.j up to ${got.data[1].max} mm/s³, ${got.data[0].n} finite points each`);
}
