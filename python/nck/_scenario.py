"""Machine.run's scenario arguments as the scenario lines they mean
(docs/plc-scenario.md): override= and feedhold= become timed lines, a plc
given as a list is the lines of a scenario file. No temporary .plc file:
the core takes the lines as text (RunOptions::plc_texts)."""
import numbers
import os

from . import _args

# The names the core gives the texts' diagnostics as their file.
OPTIONS_NAME, LIST_NAME = "<override/feedhold>", "<plc>"


def _percent(value, name):
    # The range is the scenario grammar's (0..200, docs/plc-scenario.md):
    # it refuses a value out of it as it does in a file (960003), one rule.
    return _args.number(value, name)


def override_lines(override):
    """override=80: the feed override from the start; a dict names each one:
    {"feed": 80, "rapid": 50, "S1": 120} (a spindle by its name)."""
    if override is None:
        return []
    if isinstance(override, numbers.Real) and not isinstance(override, bool):
        return [f"0 feed_override {_percent(override, 'override')!r}"]
    if not isinstance(override, dict):
        _args.fail("override", "a percentage or a dict like {'feed': 80, 'S1': 120}", override)
    lines = []
    for key, value in override.items():
        name = _args.text(key, "override's key")
        v = _percent(value, f"override[{name!r}]")
        if name in ("feed", "rapid"):
            lines.append(f"0 {name}_override {v!r}")
        elif name[:1] in ("S", "s") and name.isidentifier():
            lines.append(f"0 override {name} {v!r}")
        else:
            _args.fail("override's key", "'feed', 'rapid' or a spindle name (S1)", key)
    return lines


def feedhold_lines(feedhold):
    """feedhold=(1.0, 2.5): held from 1.0 s to 2.5 s; a list of such pairs."""
    if feedhold is None:
        return []
    wanted = "(on_s, off_s) or a list of such pairs"
    if not isinstance(feedhold, (tuple, list)):
        _args.fail("feedhold", wanted, feedhold)
    one = len(feedhold) == 2 and all(isinstance(x, numbers.Real) for x in feedhold)
    lines = []
    for pair in [feedhold] if one else feedhold:
        if not isinstance(pair, (tuple, list)) or len(pair) != 2:
            _args.fail("feedhold", wanted, feedhold)
        on, off = (_args.number(t, "feedhold") for t in pair)
        if not 0 <= on < off:
            _args.fail("feedhold", "(on_s, off_s) with 0 <= on_s < off_s", pair)
        lines += [f"{on!r} feedhold on", f"{off!r} feedhold off"]
    return lines


def plc_inputs(plc, override=None, feedhold=None):
    """(file, texts) for the core: the --plc file ("" for none) and the
    scenario texts as (name, text) pairs, override/feedhold first (so that
    the plc's own lines at the same time act after them)."""
    texts = []
    lines = override_lines(override) + feedhold_lines(feedhold)
    if lines:
        texts.append((OPTIONS_NAME, "\n".join(lines)))
    if plc is None or isinstance(plc, (str, os.PathLike)):
        return _args.optional_path(plc, "plc"), texts
    if isinstance(plc, (list, tuple)):
        for line in plc:
            if not isinstance(line, str) or "\n" in line or "\r" in line:
                _args.fail("plc", "a path or a list of scenario lines (one str each)", line)
        texts.append((LIST_NAME, "\n".join(plc)))
        return "", texts
    _args.fail("plc", "a path or a list of scenario lines", plc)


def trace_columns(value):
    """"path.v,path.a" / ["path.v", "path.a"] / None as the core's text."""
    if value is None:
        return ""
    if isinstance(value, str):
        return value
    if isinstance(value, (list, tuple)) and all(isinstance(v, str) for v in value):
        return ",".join(value)
    _args.fail("trace_columns", "names like 'path.v' (a str or a list of them)", value)
