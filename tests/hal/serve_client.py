#!/usr/bin/python3
"""The operator of hal_test.py's `serve` case: runs inside the HAL session's
namespaces (loadusr -w from the HAL file) and talks to nck-hal --serve on the
namespace's own loopback while contour.nc runs in the HAL thread. Prints
`ok: ...` per check and `FAILED: ...` at the first one that fails; exits 0
only when all passed. Every wait is bounded.

  serve_client.py PORT TOKEN_FILE
"""
import json, os, subprocess, sys, time, urllib.error, urllib.request

port, token = int(sys.argv[1]), open(sys.argv[2]).read().strip()
base = f"http://127.0.0.1:{port}"


def check(cond, what):
    print(("ok: " if cond else "FAILED: ") + what, flush=True)
    if not cond:
        sys.exit(1)


def request(path, body=None, auth=True):
    """(status, parsed JSON or text) of one request."""
    req = urllib.request.Request(base + path, data=None if body is None else json.dumps(body).encode(),
                                 method="GET" if body is None else "POST")
    if auth:
        req.add_header("Authorization", f"Bearer {token}")
    if body is not None:
        req.add_header("Content-Type", "application/json")
    try:
        with urllib.request.urlopen(req, timeout=5) as r:
            status, text = r.status, r.read().decode()
    except urllib.error.HTTPError as e:
        status, text = e.code, e.read().decode()
    try:
        return status, json.loads(text)
    except ValueError:
        return status, text


def channel():
    status, s = request("/api/v1/state")
    if status != 200:
        check(False, f"GET /api/v1/state answers 200 (got {status} {s})")
    return s["channels"][0]


def wait_for(cond, what, limit_s=30):
    end = time.monotonic() + limit_s
    while time.monotonic() < end:
        c = channel()
        if cond(c):
            return c
        time.sleep(0.05)
    check(False, f"{what} within {limit_s} s (last state {channel()})")


def pin(name):
    out = subprocess.run(["halcmd", "getp", name], capture_output=True, text=True, timeout=10).stdout.strip()
    return float(out) if out not in ("TRUE", "FALSE") else out == "TRUE"


for _ in range(100):  # the server is bound before nck-hal is ready: this is HAL's start
    try:
        request("/api/v1/version")
        break
    except OSError:
        time.sleep(0.1)

status, _ = request("/api/v1/state", auth=False)
check(status == 401, f"no token: 401 (got {status})")
status, page = request("/")
check(status == 200 and "<html" in str(page).lower(), "GET / serves the HMI page")
status, m = request("/api/v1/machine")
check(status == 200 and m["channels"][0]["axes"][:3] == ["X", "Y", "Z"], "GET /api/v1/machine names X, Y, Z")

c = wait_for(lambda c: c["state"] == "running" and c["path_velocity_mm_s"] > 1, "the program runs and moves")
check(c["block"]["file"].endswith("/contour.nc") and c["block"]["line"] > 0, f"the state names the block: {c['block']}")

# The HMI page in a browser (tests/hal/hal_hmi_check.mjs), while the program runs.
here = os.path.dirname(os.path.abspath(__file__))
if os.path.isdir(os.path.join(here, "..", "..", "node_modules", "playwright-core")):
    page = subprocess.run(["node", os.path.join(here, "hal_hmi_check.mjs"), f"{base}/?token={token}"],
                          capture_output=True, text=True, timeout=90)
    print(page.stdout.strip(), flush=True)
    check(page.returncode == 0, f"the HMI page works against nck-hal ({page.stderr.strip()[-500:]})")
else:
    print("skipped: the HMI page check (node_modules/playwright-core missing: npm ci)", flush=True)

status, r = request("/api/v1/command", {"command": "feedhold", "on": True})
check(status == 200 and r.get("ok"), f"feedhold on through the API: {status} {r}")
c = wait_for(lambda c: c["path_velocity_mm_s"] == 0 and c["feedhold"], "the path stands under the API's feedhold", 5)
check(pin("nck.channel.1.path-velocity") == 0, "nck.channel.1.path-velocity is 0 in HAL")
standing = c["mcs"]
time.sleep(0.3)
check(channel()["mcs"] == standing, "the axes stay where they stopped")

status, r = request("/api/v1/command", {"command": "feed_override", "percent": 50})
check(status == 200, "feed_override 50 through the API")
wait_for(lambda c: c["feed_override_pct"] == 50, "the state shows the API's override", 5)

status, r = request("/api/v1/command", {"command": "spindle_override", "spindle": "S1", "percent": 70})
check(status == 200, f"spindle_override S1 70 through the API ({status} {r})")
end = time.monotonic() + 5
while request("/api/v1/state")[1]["spindles"][0]["override_pct"] != 70 and time.monotonic() < end:
    time.sleep(0.05)
check(request("/api/v1/state")[1]["spindles"][0]["override_pct"] == 70, "the state shows S1's override from the API")

for body, what in (({"command": "mdi", "text": "G0 X0"}, "MDI"), ({"command": "load", "program": "x.nc"}, "load"),
                   ({"command": "jog", "axis": "X", "direction": "+"}, "jog")):
    status, r = request("/api/v1/command", body)
    check(status == 409 and r["error"]["id"] == 940407, f"{what}: 409 with 940407 (got {status} {r})")
status, r = request("/api/v1/estop", {"on": True})
check(status == 409 and r["error"]["id"] == 940407, "E-stop through the API: 409 940407 (the pin owns it)")

req = urllib.request.Request(base + "/api/v1/stream", headers={"Authorization": f"Bearer {token}"})
with urllib.request.urlopen(req, timeout=5) as stream:
    head = stream.read1(65536).decode()
    check("event: machine" in head and "event: state" in head, "the stream starts with the machine and the state")
    status, r = request("/api/v1/command", {"command": "feedhold", "on": False})
    check(status == 200, "feedhold off through the API")
    seen, end = "", time.monotonic() + 10
    while "event: events" not in seen and time.monotonic() < end:
        seen += stream.read1(65536).decode()
    events = [l for l in seen.splitlines() if l.startswith("data: [")]
    check(bool(events) and '"ev":"block"' in events[0], "the stream carries the kernel's events (block events)")
wait_for(lambda c: c["path_velocity_mm_s"] > 0 or c["state"] == "ended", "the path moves again", 5)
status, r = request("/api/v1/command", {"command": "feed_override", "percent": 100})
c = wait_for(lambda c: c["state"] == "ended", "the program ends", 90)
check(c["last_error"] is None, "no error")

status, prog = request("/api/v1/program?channel=1")
check(status == 200 and prog["file"] == "contour.nc" and len(prog["lines"]) > 5, "GET /api/v1/program: the program's text")
status, prev = request("/api/v1/preview?channel=1")
check(status == 200 and prev["points"] > 10, f"GET /api/v1/preview: {prev['points']} points")
status, path = request("/api/v1/path?channel=1")
check(status == 200 and path["points"] > 10, f"GET /api/v1/path: {path['points']} points of the run")

print("serve client: done", flush=True)
