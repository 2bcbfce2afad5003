// Small DOM builders for the HMI: elements, labelled buttons, checkboxes and
// sliders. Controls show what the machine reports, not what was clicked:
// `set` writes a value from a snapshot unless the operator is touching it.
(function () {
  "use strict";

  // el("div", {class: "x", onclick: f}, child, "text", ...)
  function el(tag, attrs, ...children) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) {
      if (v == null || v === false) continue;
      if (k.startsWith("on")) e.addEventListener(k.slice(2), v);
      else if (k === "class") e.className = v;
      else if (k === "text") e.textContent = v;
      else e.setAttribute(k, v === true ? "" : v);
    }
    for (const c of children) if (c != null) e.append(c);
    return e;
  }

  function button(text, title, onclick, cls) {
    return el("button", { type: "button", title, class: cls, onclick }, text);
  }

  // A checkbox with its label; onchange(checked).
  function check(text, title, onchange) {
    const box = el("input", { type: "checkbox", onchange: () => onchange(box.checked) });
    const label = el("label", { class: "check", title }, box, " " + text);
    return { el: label, box, set: (on) => { if (document.activeElement !== box) box.checked = !!on; } };
  }

  // A range slider with its value; oninput(value) fires while it is dragged.
  function slider(text, min, max, step, unit, oninput) {
    const input = el("input", { type: "range", min, max, step, "aria-label": text });
    const value = el("span", { class: "value" });
    let touching = false;
    input.addEventListener("pointerdown", () => { touching = true; });
    input.addEventListener("pointerup", () => { touching = false; });
    input.addEventListener("input", () => {
      value.textContent = input.value + unit;
      oninput(Number(input.value));
    });
    const row = el("label", { class: "slider" }, el("span", { class: "name" }, text), input, value);
    return {
      el: row, input,
      set: (v) => {
        if (touching || document.activeElement === input) return;
        input.value = v;
        value.textContent = Math.round(v) + unit;
      },
    };
  }

  // A number as the DRO shows it: fixed decimals, a minus sign that keeps its place.
  function fixed(v, decimals) {
    if (v == null || !Number.isFinite(v)) return "—";
    const s = v.toFixed(decimals);
    return s === "-" + (0).toFixed(decimals) ? (0).toFixed(decimals) : s;
  }

  window.NckUi = { el, button, check, slider, fixed };
})();
