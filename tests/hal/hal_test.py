#!/usr/bin/python3
"""nck in a LinuxCNC HAL session (issue 46), each case in its own namespaces
through scripts/hal-demo.sh and bounded in time. Exit 77 (skipped) when the
HAL components are not built or unshare is not allowed.

  hal_test.py SOURCE BUILD CASE   CASE: contour | operator | plc | period | wrong-type | missing-machine | missing-program
                                        | cia402 | cia402-fault | cia402-home | amp-fault | homing | plc-silent | serve | serve-bad-option | skip | vfd-spindle | thread-index | spindle-controls
"""
import json, math, os, re, subprocess, sys, tempfile

SKIP = 77
src, build, case = sys.argv[1], sys.argv[2], sys.argv[3]
demo = os.path.join(src, "scripts", "hal-demo.sh")
example = os.path.join(src, "examples", "hal", "mill-stepgen.hal")
mill = os.path.join(src, "examples", "mill")
contour = os.path.join(mill, "contour.nc")
STEP_MM = 1 / 10  # the example's position-scale
V_MAX_MM_S, T_SERVO_S = 500.0, 0.001  # the mill's rapid; the servo period


def skip(why):
    print(f"SKIPPED: {why}")
    sys.exit(SKIP)


if not os.path.exists(os.path.join(build, "hal", "nck.so")):
    skip("the HAL components are not built (NCK_HAL off: install linuxcnc-uspace-dev)")
if os.geteuid() != 0:
    skip("HAL sessions run in their own namespaces (unshare): run as root like scripts/test.sh")


def run(hal_text, program=contour, machine=mill, timeout=120):
    with tempfile.NamedTemporaryFile("w", suffix=".hal", delete=False) as f:
        f.write(hal_text)
    env = dict(os.environ, NCK_BUILD_DIR=build, NCK_HAL_TIMEOUT=str(timeout))
    p = subprocess.run([demo, f.name, program, machine], capture_output=True, text=True, env=env,
                       timeout=timeout + 30)
    os.unlink(f.name)
    out = p.stdout + p.stderr
    if "unshare" in out and "Operation not permitted" in out:
        skip("unshare is not permitted here")
    return p.returncode, out


def pins(out):
    """name -> value of every `show pin` row."""
    vals = {}
    for m in re.finditer(r"^\s*\d+\s+(bit|float|s32|u32)\s+(IN|OUT|I/O)\s+(\S+)\s+(\S+)", out, re.M):
        vals[m.group(4)] = m.group(3)
    return vals


def check(cond, what, out=""):
    if not cond:
        print(out[-4000:])
        print(f"FAILED: {what}")
        sys.exit(1)
    print(f"ok: {what}")


BOUND_MM = V_MAX_MM_S * T_SERVO_S + STEP_MM


def with_monitor(text):
    """The example with, per axis, a minmax on its following error and the
    time it spent outside v*T + 1 step (wcomp -> not -> integ), shown at the end."""
    lines = ["loadrt minmax count=3", "loadrt wcomp count=3", "loadrt not count=3",
             "loadrt conv_bit_float count=3", "loadrt integ count=3"]
    for i, a in enumerate("XYZ"):
        lines += [f"addf minmax.{i} servo-thread", f"addf wcomp.{i} servo-thread", f"addf not.{i} servo-thread",
                  f"addf conv-bit-float.{i} servo-thread", f"addf integ.{i} servo-thread",
                  f"setp wcomp.{i}.min {-BOUND_MM}", f"setp wcomp.{i}.max {BOUND_MM}",
                  f"net {a.lower()}-ferr nck.axis.{a}.f-error => minmax.{i}.in wcomp.{i}.in",
                  f"net {a.lower()}-inside wcomp.{i}.out => not.{i}.in",
                  f"net {a.lower()}-outside not.{i}.out => conv-bit-float.{i}.in",
                  f"net {a.lower()}-outside-f conv-bit-float.{i}.out => integ.{i}.in"]
    return text.replace("\nstart\n", "\n" + "\n".join(lines) + "\nstart\n").replace(
        "show pin nck.error\n", "show pin nck.error\nshow pin nck.cycles\nshow pin minmax\nshow pin integ\n")


example_text = open(example).read()
cia_machine = os.path.join(src, "examples", "mill-cia402")
cia_text = open(os.path.join(src, "examples", "hal", "mill-cia402.hal")).read()


def drive_modes_both_ways(program, axes):
    """Runs examples/mill-cia402's `program` through mill-cia402.hal (to its
    end) and through `nck run`: the HAL session's output and each run's
    (axis, mode) of the `drive` events of `axes`, in order."""
    path = os.path.join(cia_machine, program)
    rc, out = run(cia_text, program=path, machine=cia_machine, timeout=60)
    check(rc == 0 and "channel 1 done" in out, f"{program} ran to its end through nck_cia402_sim (exit {rc})", out)
    hal = [(a, m) for a, m in re.findall(r"^event t=\S+ ch=0 line=\d+ ev=drive axis=(\S+) mode=(\S+)", out, re.M) if a in axes]
    with tempfile.TemporaryDirectory() as d:
        ev = os.path.join(d, "ev.jsonl")
        subprocess.run([os.path.join(build, "nck"), "run", cia_machine, path, "--events", ev],
                       check=True, capture_output=True, timeout=120)
        ran = [(j["axis"], j["mode"]) for j in map(json.loads, open(ev)) if j.get("ev") == "drive" and j["axis"] in axes]
    return out, hal, ran


cia_enable = os.path.join(cia_machine, "enable.nc")
OP_ENABLED = 0x0637  # CiA 402 statusword: operation enabled, remote, target reached

if case == "contour":
    rc, out = run(with_monitor(example_text))
    check(rc == 0, f"halrun -f mill-stepgen.hal exits 0 (got {rc})", out)
    check("channel 1 done" in out, "nck-hal saw the program end", out)
    v = pins(out)
    check(v.get("nck.channel.1.status") == "3", "the channel ended (status 3)", out)
    check(v.get("nck.error-id") == "0x00000000", "no error on nck.error-id", out)
    final = subprocess.run([os.path.join(build, "nck"), "run", mill, contour, "--final", "-"],
                           capture_output=True, text=True, timeout=120)
    axes = json.loads(final.stdout)["channels"][0]["axes"]
    bound = BOUND_MM
    # On a non-real-time host whose cores are all busy (load above the core
    # count during the run) the stepgen's base thread starves for whole
    # milliseconds: what it then lags says nothing about nck.
    load, cpus = os.getloadavg()[0], os.cpu_count() or 1
    overloaded = load > cpus
    run_s = int(v["nck.cycles"], 16) * T_SERVO_S
    for i, a in enumerate("XYZ"):
        fb = float(v[f"nck.axis.{a}.pos-fb"])
        check(abs(fb - axes[a]["mcs"]) <= STEP_MM + 1e-9,
              f"{a}: stepgen's feedback {fb:.4f} within one step of nck run's {axes[a]['mcs']}", out)
        worst = max(abs(float(v[f"minmax.{i}.max"])), abs(float(v[f"minmax.{i}.min"])))
        outside_s = float(v[f"integ.{i}.out"])
        # A non-real-time host (CI) misses base-thread periods under load:
        # the stepgen then falls behind for reasons not nck's. The bound must
        # hold in 99 % of the cycles; docs/hal.md says how to judge every
        # period on a PREEMPT_RT host.
        print(f"{a}: worst |fb - cmd| {worst:.4f} mm; outside {bound:.3f} mm for {outside_s:.4f} s of {run_s:.1f} s")
        if overloaded:
            print(f"{a}: following not judged: the host is overloaded (load {load:.1f} on {cpus} cores), "
                  "the base thread misses periods")
            continue
        check(outside_s <= 0.01 * run_s, f"{a}: |fb - cmd| <= v*T + 1 step = {bound:.3f} mm in >= 99 % of the cycles", out)
elif case == "serve":
    # nck-hal --serve: nck serve's API for the kernel in the HAL thread. The
    # operator (serve_client.py, inside the session's namespaces) holds the
    # path with the API's feedhold, sets the override, is refused what the
    # HAL file owns, and watches the program end in the state and stream.
    with tempfile.NamedTemporaryFile("w", suffix=".token", delete=False) as t:
        t.write("0123456789abcdef0123456789abcdef\n")
    client = os.path.join(src, "tests", "hal", "serve_client.py")
    text = example_text.replace("nck-hal $(NCK_MACHINE)", f"nck-hal --serve --port 8765 --token-file {t.name} $(NCK_MACHINE)")
    text = text.replace("waitusr nck-hal\n", f"loadusr -w /usr/bin/python3 {client} 8765 {t.name}\nunloadusr nck-hal\n")
    rc, out = run(text, timeout=150)
    os.unlink(t.name)
    print("\n".join(l for l in out.splitlines() if l.startswith(("ok:", "FAILED:", "nck-hal:"))))
    check("serve client: done" in out and "FAILED" not in out, "every check of the API operator passed", out)
    check("nck-hal: http://127.0.0.1:8765/?token=" in out, "nck-hal printed its URL", out)
    check(pins(out).get("nck.channel.1.status") == "3", "the channel ended (status 3)", out)
elif case == "serve-bad-option":
    # A token file too short and an unknown option: nck-hal refuses with an
    # ID before HAL sees it ready, so loadusr -W fails and the file stops.
    with tempfile.NamedTemporaryFile("w", suffix=".token", delete=False) as t:
        t.write("short\n")
    text = example_text.replace("nck-hal $(NCK_MACHINE)", f"nck-hal --serve --token-file {t.name} $(NCK_MACHINE)")
    rc, out = run(text, timeout=30)
    os.unlink(t.name)
    check(rc != 0 and "error 940408" in out and "at least 32" in out, f"a short token: error 940408, the file stops (exit {rc})", out)
    rc, out = run(example_text.replace("nck-hal $(NCK_MACHINE)", "nck-hal --sreve $(NCK_MACHINE)"), timeout=30)
    check(rc != 0 and "error 940403" in out, f"an unknown option: error 940403 with the usage (exit {rc})", out)
elif case == "skip":
    # nck.channel.1.skip-mask reaches nck-hal's preparation (set before
    # `start`, it rules the first blocks too): the /1 block is skipped, X
    # never passes 10 (a minmax on pos-cmd); after M19 the orient pin is on.
    head = example_text[:example_text.index("\nstart\n")]
    tail = """
loadrt minmax count=1
addf minmax.0 servo-thread
net x-cmd => minmax.0.in
setp nck.channel.1.skip-mask 1
start
waitusr nck-hal
show pin minmax.0.max
show pin nck.spindle.S1.orient
show pin nck.channel.1.status
stop
"""
    rc, out = run(head + "\n" + tail, program=os.path.join(src, "tests", "hal", "skip.nc"), timeout=60)
    v = pins(out)
    check(rc == 0 and v.get("nck.channel.1.status") == "3", f"skip.nc ran to its end (exit {rc})", out)
    check(float(v["minmax.0.max"]) == 10.0, f"the /1 block was skipped: X at most {v['minmax.0.max']}", out)
    check(v.get("nck.spindle.S1.orient") == "TRUE", "nck.spindle.S1.orient is on after M19", out)
elif case == "plc":
    # (d): spindle.nc with the example's plain-HAL PLC (timedelay acknowledges
    # each M/H function) waits where `nck run --plc spindle.plc` waits.
    spindle = os.path.join(mill, "spindle.nc")
    rc, out = run(example_text, program=spindle, timeout=90)
    check(rc == 0 and "channel 1 done" in out, f"spindle.nc ran to its end through HAL (exit {rc})", out)
    hal_waits = re.findall(r"^event t=\S+ ch=1 line=(\d+) ev=wait reason=(\S+)", out, re.M)
    with tempfile.TemporaryDirectory() as d:
        ev = os.path.join(d, "ev.jsonl")
        subprocess.run([os.path.join(build, "nck"), "run", mill, spindle, "--plc", os.path.join(mill, "spindle.plc"),
                        "--events", ev], check=True, capture_output=True, timeout=120)
        run_waits = [(str(j["line"]), j["reason"]) for j in map(json.loads, open(ev)) if j.get("ev") == "wait"]
    print("HAL waits:", hal_waits)
    print("nck run waits:", run_waits)
    check(len(run_waits) > 0 and hal_waits == run_waits,
          "the same waits (line, reason), in the same order, as nck run --plc spindle.plc", out)
elif case == "period":
    rc, out = run(example_text.replace("period2=1000000", "period2=2000000"), timeout=30)
    check("940400" in out, "a 2 ms thread for a 1 ms machine: error 940400", out)
    check(pins(out).get("nck.error-id") == "0x000E5970", "nck.error-id shows 940400 (0xE5970)", out)
    check(pins(out).get("nck.error") == "TRUE", "nck.error is on", out)
    check("Segmentation" not in out and "crash" not in out.lower(), "rtapi_app did not crash", out)
elif case == "wrong-type":
    rc, out = run(example_text.replace("=> stepgen.0.position-cmd", "=> stepgen.0.enable"), timeout=30)
    check(rc != 0, f"a float pin netted to a bit pin: the HAL file fails to load (exit {rc})", out)
    check(re.search(r"type", out, re.I) is not None, "halcmd names the type mismatch", out)
elif case == "missing-machine":
    rc, out = run(example_text, machine="/nonexistent-machine", timeout=30)
    check(rc != 0 and "940403" in out, f"a missing machine folder: error 940403, the file stops (exit {rc})", out)
elif case == "missing-program":
    rc, out = run(example_text, program="/nonexistent.nc", timeout=30)
    check(rc != 0 and "940403" in out, f"a missing program: error 940403, the file stops (exit {rc})", out)
elif case == "operator":
    head = example_text[:example_text.index("\nstart\n")]
    tail = """
setp nck.channel.1.feedhold 1
start
loadusr -w sleep 1
show pin nck.axis.X.pos-cmd
setp nck.channel.1.feedhold 0
setp nck.channel.1.feed-override 50
loadusr -w sleep 2
show pin nck.channel.1.program-state
show pin nck.axis.X.pos-cmd
setp nck.channel.1.cycle-start 1
waitusr nck-hal
show pin nck.channel.1.status
show pin nck.axis.X.pos-cmd
show pin nck.error-id
stop
"""
    rc, out = run(head + "\n" + tail, program=os.path.join(src, "tests", "hal", "operator.nc"), timeout=60)
    rows = re.findall(r"^\s*\d+\s+(?:bit|float|s32|u32)\s+(?:IN|OUT)\s+(\S+)\s+(\S+)", out, re.M)
    xs = [float(v) for v, n in rows if n == "nck.axis.X.pos-cmd"]
    state = [v for v, n in rows if n == "nck.channel.1.program-state"]
    check(rc == 0 and len(xs) == 3, f"the session ran (exit {rc})", out)
    check(xs[0] == 0.0, "feedhold on at the start: X has not moved after 1 s", out)
    check(state == ["2"] and xs[1] == 10.0, "after feedhold off the program holds at M0 (program-state 2) with X at 10", out)
    check(xs[2] == 20.0 and pins(out).get("nck.channel.1.status") == "3", "cycle start released M0: X at 20, ended", out)
    check("event" in out and "channel 1 done" in out, "nck-hal saw the end", out)
elif case == "cia402":
    # (b) through HAL pins: nck powers the three simulated CiA 402 drives up
    # to operation enabled (the program waits for them), runs the square
    # in cyclic synchronous position and ends where `nck run` ends.
    rc, out = run(cia_text, program=cia_enable, machine=cia_machine, timeout=60)
    check(rc == 0 and "channel 1 done" in out, f"enable.nc ran to its end through nck_cia402_sim (exit {rc})", out)
    check(re.search(r"ev=wait reason=drive_enable", out) is not None, "the program waited for the drives (drive_enable)", out)
    v = pins(out)
    for a in "XYZ":
        check(int(v.get(f"nck.axis.{a}.cia-statusword", "0"), 16) == OP_ENABLED and v.get(f"nck.axis.{a}.cia-opmode") == "8",
              f"{a}: statusword 0x{OP_ENABLED:04X} (operation enabled) in mode 8 (cyclic synchronous position)", out)
    final = subprocess.run([os.path.join(build, "nck"), "run", cia_machine, cia_enable, "--final", "-"],
                           capture_output=True, text=True, timeout=120)
    axes = json.loads(final.stdout)["channels"][0]["axes"]
    for a, i in (("X", 0), ("Y", 1), ("Z", 2)):
        fb = float(v[f"nck-cia402-sim.{i}.pos-fb"])
        check(abs(fb - axes[a]["mcs"]) < 1e-9, f"{a}: the drive stands at {fb}, where nck run ends ({axes[a]['mcs']})", out)
elif case == "cia402-fault":
    # (b) a drive fault in motion and its reset, through HAL pins: Y's fault
    # input is error 940501 naming Y; with the fault gone a channel reset
    # writes the fault reset and the drive powers up to operation enabled.
    head = cia_text[:cia_text.index("\nstart\n")]
    tail = """
start
loadusr -w sleep 2
setp nck-cia402-sim.1.fault 1
loadusr -w sleep 0.5
show pin nck.axis.Y.cia-statusword
setp nck-cia402-sim.1.fault 0
setp nck.channel.1.reset 1
loadusr -w sleep 0.5
setp nck.channel.1.reset 0
show pin nck.axis.Y.cia-statusword
show pin nck.error-id
stop
"""
    rc, out = run(head + "\n" + tail, program=cia_enable, machine=cia_machine, timeout=60)
    check(rc == 0, f"the session ran (exit {rc})", out)
    check(re.search(r"ev=error id=940501 axis=Y", out) is not None, "Y's drive fault is error 940501 naming Y", out)
    words = [int(w, 16) for w in re.findall(r"^\s*\d+\s+u32\s+IN\s+(0x[0-9A-F]+)\s+nck\.axis\.Y\.cia-statusword", out, re.M)]
    check(len(words) == 2 and words[0] & 0x0008 and words[1] == OP_ENABLED,
          f"Y's statusword: fault (0x{words[0] if words else 0:04X}), then after the reset 0x{OP_ENABLED:04X}", out)
    check(pins(out).get("nck.error-id") == "0x00000000", "after the reset nck.error-id is 0 again (and nck.cycle never stopped)", out)
elif case == "cia402-spindle":
    # (c) spindle modes through HAL pins: S1's simulated CiA 402 drive runs
    # homing mode for G74 (the drive homes itself), cyclic synchronous
    # velocity for M3, position for M19 and velocity again, in the order
    # `nck run` reports them (its `drive` events).
    out, hal_modes, run_modes = drive_modes_both_ways("spindle_modes.nc", ("S1",))
    hal_modes, run_modes = [m for _, m in hal_modes], [m for _, m in run_modes]
    print("HAL S1 modes:", hal_modes)
    print("nck run S1 modes:", run_modes)
    check(run_modes == ["csv", "homing", "csv", "csp", "csv"], f"nck run: S1 homes, turns, positions, turns ({run_modes})", out)
    check(hal_modes == run_modes, "through HAL the drive runs the same modes in the same order", out)
    v = pins(out)
    check(v.get("nck.spindle.S1.homed") == "TRUE", "nck.spindle.S1.homed after G74", out)
    check(int(v.get("nck.spindle.S1.cia-statusword", "0"), 16) & 0x6F == 0x27 and v.get("nck.spindle.S1.cia-opmode") == "9",
          "S1's drive is in operation enabled, in velocity mode at the end", out)
elif case == "cia402-home":
    # G74 of path axes on DRIVE_CONTROLLED CiA 402 drives (home.nc): each
    # nck_cia402_sim drive runs homing mode while its block waits, in the
    # order `nck run` reports; the axes end homed at the program's places.
    out, hal_modes, run_modes = drive_modes_both_ways("home.nc", ("X", "Y", "Z"))
    print("HAL modes:", hal_modes)
    print("nck run modes:", run_modes)
    check(("Z", "homing") in run_modes and ("X", "homing") in run_modes, f"nck run: the drives home ({run_modes})", out)
    check(hal_modes == run_modes, "through HAL the drives run the same modes in the same order", out)
    v = pins(out)
    for a, at in (("X", 20.0), ("Y", 10.0), ("Z", 0.0)):
        check(v.get(f"nck.axis.{a}.homed") == "TRUE", f"{a} is homed", out)
        check(abs(float(v[f"nck.axis.{a}.pos-fb"]) - at) <= 1e-6, f"{a} ends at {at} (the drive's reference is the machine's)", out)
    check(v.get("nck.error-id") == "0x00000000", "no error", out)
elif case == "plc-silent":
    # Bad input: a PLC that never acknowledges. mill-stepgen.hal without its
    # acknowledgements runs spindle.nc: M3 waits for its ack for
    # m3_prozess_zeit (2 s, examples/mill/channel1.lis), then error 960021
    # on nck.error-id; the program ends and the session ends by itself.
    text = re.sub(r"^net plc-ack-\d+ .*$", "", example_text, flags=re.M)
    rc, out = run(text, program=os.path.join(mill, "spindle.nc"), timeout=60)
    check(rc == 0 and "channel 1 done" in out, f"the session ended by itself (exit {rc})", out)
    check(re.search(r"ev=error id=960021", out) is not None, "the missing acknowledgement is error 960021", out)
    v = pins(out)
    check(v.get("nck.error") == "TRUE" and v.get("nck.error-id") == "0x000EA615", "nck.error-id shows 960021", out)
elif case == "vfd-spindle":
    # (issue 46 item 3) a spindle on a conventional drive: S1 of
    # examples/mill-analog through mill-velocity.hal's VFD model (5 % slow,
    # an encoder read back as revs and speed-in). M3 runs on the VFD's own
    # speed; M19 ends in position only because nck closes the loop with kv
    # (without it the slow VFD stops short and M19 never ends).
    analog = os.path.join(src, "examples", "mill-analog")
    text = open(os.path.join(src, "examples", "hal", "mill-velocity.hal")).read().replace(
        "show pin nck.error\n", "show pin nck.error\nshow pin nck.spindle.S1\n")
    rc, out = run(text, program=os.path.join(src, "tests", "hal", "vfd_spindle.nc"), machine=analog, timeout=60)
    check(rc == 0 and "channel 1 done" in out, f"vfd_spindle.nc ran to its end: M19 reached its position (exit {rc})", out)
    v = pins(out)
    check(v.get("nck.error-id") == "0x00000000", "no error", out)
    revs = float(v["nck.spindle.S1.revs"])
    angle = (revs - math.floor(revs)) * 360
    check(abs(angle - 90) < 0.05, f"the encoder reads S1 at {angle:.4f} deg (M19 to 90)", out)
    check(v.get("nck.spindle.S1.orient") == "TRUE", "nck.spindle.S1.orient is on", out)
elif case == "spindle-controls":
    # The HLI's spindle control as pins: the override at 50 % runs M3 S1000
    # at 500 rpm; the spindle's feedhold brings its set point to 0; released,
    # it runs up again and the program ends. Then a spindle command from the
    # PLC (plc-cmd-*) turns S1 again, and its reset pin stops it.
    head = example_text[:example_text.index("\nstart\n")]
    tail = """
setp nck.spindle.S1.override 50
start
loadusr -w sleep 1.2
show pin nck.spindle.S1.speed-cmd-rpm
setp nck.spindle.S1.feedhold 1
loadusr -w sleep 0.8
show pin nck.spindle.S1.speed-cmd-rpm
setp nck.spindle.S1.feedhold 0
waitusr nck-hal
setp nck.spindle.S1.plc-cmd-m 3
setp nck.spindle.S1.plc-cmd-rpm 300
setp nck.spindle.S1.plc-cmd-request 1
loadusr -w sleep 0.8
show pin nck.spindle.S1.speed-cmd-rpm
show pin nck.spindle.S1.plc-cmd-done
setp nck.spindle.S1.reset 1
loadusr -w sleep 0.8
show pin nck.spindle.S1.speed-cmd-rpm
show pin nck.channel.1.status
show pin nck.error-id
stop
"""
    rc, out = run(head + "\n" + tail, program=os.path.join(src, "tests", "hal", "spindle_controls.nc"), timeout=60)
    rpm = [float(m) for m in re.findall(r"^\s*\d+\s+float\s+OUT\s+(\S+)\s+nck.spindle.S1.speed-cmd-rpm", out, re.M)]
    check(rc == 0 and "channel 1 done" in out and len(rpm) == 4, f"spindle_controls.nc ran to its end (exit {rc})", out)
    check(abs(rpm[0] - 500) < 1e-6, f"override 50 %: M3 S1000 runs at {rpm[0]} rpm", out)
    check(rpm[1] == 0, f"the spindle's feedhold: its set point is {rpm[1]} rpm", out)
    check(abs(rpm[2] - 150) < 1e-6 and pins(out).get("nck.spindle.S1.plc-cmd-done") == "TRUE",
          f"after the program the PLC's command M3 REV300 (FCT-S1 2.9) runs S1 at {rpm[2]} rpm (override 50 %), done", out)
    check(rpm[3] == 0, f"the spindle's reset pin (spdl_reset) stops it: {rpm[3]} rpm", out)
    check(pins(out).get("nck.error-id") == "0x00000000", "no error", out)
elif case == "thread-index":
    # G33 with the spindle encoder's index: mill-velocity.hal's S1 VFD
    # drives LinuxCNC's sim_encoder (25 lines, A/B/Z), read by its encoder
    # component; nck.spindle.S1.index-enable <=> encoder.0.index-enable.
    # Each G33 pass asks for the reset, the encoder resets its count at the
    # index and clears the pin, the pass starts on it.
    analog = os.path.join(src, "examples", "mill-analog")
    text = open(os.path.join(src, "examples", "hal", "mill-velocity.hal")).read()
    for old, new in (
        ("loadrt threads name1=servo-thread period1=1000000 fp1=1",
         "loadrt threads name1=base-thread period1=100000 fp1=0 name2=servo-thread period2=1000000 fp2=1\n"
         "loadrt sim_encoder num_chan=1\nloadrt encoder num_chan=1"),
        ("addf nck.cycle servo-thread\n",
         "addf sim-encoder.make-pulses base-thread\naddf encoder.update-counters base-thread\n"
         "addf encoder.capture-position servo-thread\naddf nck.cycle servo-thread\naddf sim-encoder.update-speed servo-thread\n"),
        ("setp scale.4.gain 0.002777777777777778", "setp scale.4.gain 0.002777777777777778\nsetp sim-encoder.0.ppr 25\n"
         "setp encoder.0.position-scale 100"),
        ("net s1-motor lowpass.3.out => integ.3.in scale.5.in", "net s1-motor lowpass.3.out => integ.3.in scale.5.in scale.4.in"),
        ("net s1-deg integ.3.out => scale.4.in\n", ""),
        ("net s1-revs scale.4.out => nck.spindle.S1.revs",
         "net s1-rps scale.4.out => sim-encoder.0.speed\nnet s1-a sim-encoder.0.phase-A => encoder.0.phase-A\n"
         "net s1-b sim-encoder.0.phase-B => encoder.0.phase-B\nnet s1-z sim-encoder.0.phase-Z => encoder.0.phase-Z\n"
         "net s1-revs encoder.0.position => nck.spindle.S1.revs\n"
         "net s1-index nck.spindle.S1.index-enable <=> encoder.0.index-enable"),
        ("show pin nck.error\n", "show pin nck.error\nshow pin encoder.0\nshow pin integ.3\nshow pin nck.spindle.S1\n")):
        assert old in text, old
        text = text.replace(old, new)
    rc, out = run(text, program=os.path.join(src, "tests", "hal", "thread_index.nc"), machine=analog, timeout=60)
    check(rc == 0 and "channel 1 done" in out, f"thread_index.nc ran to its end (exit {rc})", out)
    waits = re.findall(r"ev=(wait|wait_end) reason=zero_mark", out)
    check(waits == ["wait", "wait_end", "wait", "wait_end"], f"both passes waited for the zero mark and started ({waits})", out)
    v = pins(out)
    turned = float(v["integ.3.out"]) / 360
    count = float(v["encoder.0.position"])
    print(f"S1 turned {turned:.2f} revolutions; the encoder counts {count:.2f} since its last index reset")
    check(v.get("nck.spindle.S1.index-enable") == "FALSE", "the encoder cleared index-enable (it reset at the index)", out)
    check(0 < count < turned - 5, "the encoder's count restarted at an index after the start (the 2nd pass)", out)
elif case == "conventional":
    # (issue 46 item 3) conventional velocity drives (kenngr.antr_typ 1):
    # nck closes the position loops with kv through vel-cmd into the drive
    # model of examples/hal/mill-velocity.hal (a lagging velocity loop and
    # an integrating motor); the axes follow and end where `nck run` ends.
    analog = os.path.join(src, "examples", "mill-analog")
    text = open(os.path.join(src, "examples", "hal", "mill-velocity.hal")).read()
    lines = ["loadrt minmax count=3"]
    for i, a in enumerate("XYZ"):
        lines += [f"addf minmax.{i} servo-thread", f"net {a.lower()}-ferr nck.axis.{a}.f-error => minmax.{i}.in"]
    text = text.replace("\nstart\n", "\n" + "\n".join(lines) + "\nstart\n").replace(
        "show pin nck.error\n", "show pin nck.error\nshow pin minmax\n")
    rc, out = run(text, machine=analog, timeout=90)
    check(rc == 0 and "channel 1 done" in out, f"contour.nc ran to its end on velocity drives (exit {rc})", out)
    v = pins(out)
    check(v.get("nck.channel.1.status") == "3" and v.get("nck.error-id") == "0x00000000", "ended, no error", out)
    final = subprocess.run([os.path.join(build, "nck"), "run", analog, contour, "--final", "-"],
                           capture_output=True, text=True, timeout=120)
    axes = json.loads(final.stdout)["channels"][0]["axes"]
    for i, a in enumerate("XYZ"):
        fb = float(v[f"nck.axis.{a}.pos-fb"])
        worst = max(abs(float(v[f"minmax.{i}.max"])), abs(float(v[f"minmax.{i}.min"])))
        print(f"{a}: end {fb:.6f} (nck run {axes[a]['mcs']}); worst |pos-cmd - pos-fb| {worst:.4f} mm")
        check(abs(fb - axes[a]["mcs"]) <= 0.001, f"{a}: the loop settles within 1 um of nck run's end", out)
        # pos-cmd of this cycle against the position of the last: v*T (at most
        # 500 mm/s * 1 ms = 0.5 mm) and the drive's lag that kv takes back.
        check(worst <= 1.5, f"{a}: the axis follows (worst following {worst:.4f} mm <= 1.5 mm)", out)
elif case == "homing":
    # (issue 46) G74 on conventional drives: each axis of
    # examples/hal/mill-velocity.hal searches its home cam (wcomp on the
    # motor position: X <= -25, Y <= -15, Z >= +5 mm from power-up) and the
    # cam's edge becomes pos_refpkt (0); home.nc then moves to X20 Y10 Z5,
    # which are the motors' -5, -5 and 10 mm.
    analog = os.path.join(src, "examples", "mill-analog")
    text = open(os.path.join(src, "examples", "hal", "mill-velocity.hal")).read()
    rc, out = run(text, program=os.path.join(analog, "home.nc"), machine=analog, timeout=90)
    check(rc == 0 and "channel 1 done" in out, f"home.nc ran to its end (exit {rc})", out)
    v = pins(out)
    check(v.get("nck.channel.1.status") == "3" and v.get("nck.error-id") == "0x00000000", "ended, no error", out)
    for a, motor in (("X", -5.0), ("Y", -5.0), ("Z", 10.0)):
        fb = float(v[f"nck.axis.{a}.pos-fb"])
        print(f"{a}: motor at {fb:.4f} mm (cam edge + programmed position {motor})")
        check(v.get(f"nck.axis.{a}.homed") == "TRUE", f"{a} is homed", out)
        # The edge is taken one cycle late at 5 mm/s, plus the drive's lag.
        check(abs(fb - motor) <= 0.1, f"{a}: the cam's edge is pos_refpkt within 0.1 mm", out)
elif case == "amp-fault":
    # (issue 46) Y's amplifier fault while contour.nc runs: error 930750
    # naming Y on nck.error-id, the channel brakes and its program ends in
    # error (the session ends by itself), the enables go off at standstill.
    head = example_text[:example_text.index("\nstart\n")]
    tail = """
start
loadusr -w sleep 1
setp nck.axis.Y.amp-fault-in 1
waitusr nck-hal
loadusr -w sleep 0.1
show pin nck.axis.Y.enable
show pin nck.channel.1.status
show pin nck.error
show pin nck.error-id
stop
"""
    rc, out = run(head + "\n" + tail, timeout=60)
    check(rc == 0 and "channel 1 done" in out, f"the session ended by itself (exit {rc})", out)
    check(re.search(r"ev=error id=930750 axis=Y", out) is not None, "Y's amplifier fault is error 930750 naming Y", out)
    v = pins(out)
    check(v.get("nck.error-id") == "0x000E33BE" and v.get("nck.error") == "TRUE",
          "nck.error / nck.error-id show 930750 (0xE33BE)", out)
    check(v.get("nck.channel.1.status") == "4" and v.get("nck.axis.Y.enable") == "FALSE",
          "the program was aborted (status 4) and the enables are off", out)
elif case == "spindle-amp-fault":
    # (issue 46) S1's amplifier fault while spindle.nc runs: error 930750
    # naming S1 on nck.error-id; the program ends in error by itself.
    head = example_text[:example_text.index("\nstart\n")]
    tail = """
start
loadusr -w sleep 1
setp nck.spindle.S1.amp-fault-in 1
waitusr nck-hal
show pin nck.channel.1.status
show pin nck.error-id
stop
"""
    rc, out = run(head + "\n" + tail, program=os.path.join(mill, "spindle.nc"), timeout=60)
    check(rc == 0 and "channel 1 done" in out, f"the session ended by itself (exit {rc})", out)
    check(re.search(r"ev=error id=930750 axis=S1", out) is not None, "S1's amplifier fault is error 930750 naming S1", out)
    v = pins(out)
    check(v.get("nck.error-id") == "0x000E33BE" and v.get("nck.channel.1.status") == "4",
          "nck.error-id shows 930750, the program was aborted (status 4)", out)
else:
    print(f"unknown case {case}")
    sys.exit(2)
