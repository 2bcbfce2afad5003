// A channel's program text: numbered lines, the current block highlighted
// and kept in view; clicking a line with an N number asks for a block
// search to it (onSearch(n, line)).
//
// The server gives the text in pages of at most 2 MiB of JSON (docs/api.md,
// GET /api/v1/program): the next page is fetched when the operator scrolls
// near the end of the lines loaded, or when the running block lies beyond
// them. Only the rows in view (and some around them) are in the document, at
// a fixed height each: a program of a million lines stays one scroll box.
(function () {
  "use strict";
  const { el } = window.NckUi;
  const ROW_PX = 18;     // .program-lines li's height (hmi.css)
  const AROUND = 100;    // rows drawn above and below the view
  const AHEAD_PX = 2000; // fetch the next page when the view comes this close to the end

  // The N number a line starts with (after an optional skip slash), or null.
  function blockNumber(text) {
    const m = /^\s*(?:\/\d*\s*)?N(\d+)/i.exec(text);
    return m ? Number(m[1]) : null;
  }

  class ProgramView {
    // fetchPage(from): a promise of the page from line `from` on
    // (/api/v1/program?channel=N&from=L); onError(e): a page was refused.
    constructor(onSearch, fetchPage, onError) {
      Object.assign(this, { onSearch, fetchPage, onError });
      this.list = el("ol", { class: "program-lines", "aria-label": "program text" });
      this.el = el("div", { class: "program", onscroll: () => { this.draw(); this.nearEnd(); } }, this.list);
      this.path = "";
      this.lines = [];
      this.nextLine = null;  // the first line not loaded yet, null: all are
      this.generation = 0;   // a new program: pages asked for the old one are dropped
      this.loading = false;
      this.retryAt = 0;      // after a refused page: not before this time (performance.now)
      this.currentLine = 0;  // the highlighted line (0: none)
      this.wanted = 0;       // a current line beyond the loaded ones
      this.drawn = [0, 0];
    }

    // The program's first page as /api/v1/program gives it.
    show(program) {
      this.path = program.path || "";
      this.lines = program.lines || [];
      this.nextLine = program.next_line ?? null;
      this.generation++;
      this.loading = false;
      this.retryAt = 0;
      this.currentLine = this.wanted = 0;
      this.drawn = [0, 0];
      this.el.scrollTop = 0;
      this.draw();
    }

    // The rows in view and AROUND them; the list keeps every line's height.
    draw(force) {
      const top = this.el.scrollTop, view = this.el.clientHeight || 420, n = this.lines.length;
      const first = Math.max(0, Math.floor(top / ROW_PX) - AROUND);
      const last = Math.min(n, Math.ceil((top + view) / ROW_PX) + AROUND);
      if (!force && first === this.drawn[0] && last === this.drawn[1]) return;
      this.drawn = [first, last];
      this.list.style.height = n * ROW_PX + "px";
      this.list.style.paddingTop = first * ROW_PX + "px";
      const rows = [];
      for (let i = first; i < last; i++) rows.push(this.row(this.lines[i], i + 1));
      this.list.replaceChildren(...rows);
    }

    row(text, line) {
      const n = blockNumber(text);
      const li = el("li", { "data-line": line, title: n != null ? `block search to N${n}` : "no N number: no block search here" },
        el("span", { class: "ln" }, String(line)), el("code", { text: text || " " }));
      if (n != null) {
        li.classList.add("searchable");
        li.addEventListener("click", () => this.onSearch(n, line));
      }
      if (line === this.currentLine) li.classList.add("current");
      return li;
    }

    // The next page when the view nears the end of the loaded lines.
    nearEnd() {
      const end = this.lines.length * ROW_PX;
      if (this.el.scrollTop + this.el.clientHeight + AHEAD_PX >= end) this.more();
    }

    async more() {
      if (this.loading || this.nextLine == null || performance.now() < this.retryAt) return;
      const generation = this.generation, from = this.nextLine;
      this.loading = true;
      let page = null;
      try {
        page = await this.fetchPage(from);
      } catch (e) {
        this.retryAt = performance.now() + 5000;  // a highlight asks 40 times a second
        this.onError(e);
      }
      if (generation !== this.generation) return;
      this.loading = false;
      if (!page || page.first_line !== this.lines.length + 1) return;
      for (const text of page.lines) this.lines.push(text);  // push(...lines) overflows the stack for 100,000s
      this.nextLine = page.next_line ?? null;
      this.draw(true);
      if (this.wanted) this.highlight(this.path, this.wanted);
      else this.nearEnd();
    }

    // The block the channel stands at; only lines of this file are marked.
    highlight(file, line) {
      const on = file === this.path && line > 0 ? line : 0;
      if (on > this.lines.length) {  // beyond the pages loaded: fetch on, mark it then
        this.wanted = this.nextLine == null ? 0 : on;
        if (this.wanted) this.more();
        return;
      }
      this.wanted = 0;
      if (on === this.currentLine) return;
      const old = this.list.querySelector("li.current");
      if (old) old.classList.remove("current");
      this.currentLine = on;
      if (!on) return;
      // scroll the list only, never the page (.program is the rows' offsetParent)
      const top = (on - 1) * ROW_PX, view = this.el.clientHeight;
      if (top < this.el.scrollTop || top + ROW_PX > this.el.scrollTop + view) this.el.scrollTop = Math.max(0, top - view / 3);
      this.draw();
      const li = this.list.querySelector(`li[data-line="${on}"]`);
      if (li) li.classList.add("current");
    }

    // The text of line `line` (for the backplot's hover).
    text(line) { return this.lines[line - 1] || ""; }
  }

  window.NckProgramView = ProgramView;
  window.NckProgramView.blockNumber = blockNumber;
})();
