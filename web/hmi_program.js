// A channel's program text: numbered lines, the current block highlighted
// and kept in view; clicking a line with an N number asks for a block
// search to it (onSearch(n, line)).
(function () {
  "use strict";
  const { el } = window.NckUi;

  // The N number a line starts with (after an optional skip slash), or null.
  function blockNumber(text) {
    const m = /^\s*(?:\/\d*\s*)?N(\d+)/i.exec(text);
    return m ? Number(m[1]) : null;
  }

  class ProgramView {
    constructor(onSearch) {
      this.onSearch = onSearch;
      this.list = el("ol", { class: "program-lines", "aria-label": "program text" });
      this.el = el("div", { class: "program" }, this.list);
      this.path = "";
      this.current = null;
      this.lines = [];
    }

    // The program as /api/v1/program gives it.
    show(program) {
      this.path = program.path || "";
      this.lines = program.lines || [];
      this.list.replaceChildren(...this.lines.map((text, i) => this.row(text, i + 1)));
      this.current = null;
    }

    row(text, line) {
      const n = blockNumber(text);
      const li = el("li", { "data-line": line, title: n != null ? `block search to N${n}` : "no N number: no block search here" },
        el("span", { class: "ln" }, String(line)), el("code", { text: text || " " }));
      if (n != null) {
        li.classList.add("searchable");
        li.addEventListener("click", () => this.onSearch(n, line));
      }
      return li;
    }

    // The block the channel stands at; only lines of this file are marked.
    highlight(file, line) {
      const li = file === this.path && line > 0 ? this.list.children[line - 1] : null;
      if (li === this.current) return;
      if (this.current) this.current.classList.remove("current");
      this.current = li || null;
      if (!li) return;
      li.classList.add("current");
      // scroll the list only, never the page (.program is the lines' offsetParent)
      const top = li.offsetTop, view = this.el.clientHeight;
      if (top < this.el.scrollTop || top + li.offsetHeight > this.el.scrollTop + view)
        this.el.scrollTop = Math.max(0, top - view / 3);
    }

    // The text of line `line` (for the backplot's hover).
    text(line) { return this.lines[line - 1] || ""; }
  }

  window.NckProgramView = ProgramView;
  window.NckProgramView.blockNumber = blockNumber;
})();
