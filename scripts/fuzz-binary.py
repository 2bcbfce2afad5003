#!/usr/bin/env python3
"""Whole-binary fuzzing: mutate programs, machine folders and --plc scenarios
from examples/ and run `nck run/parse/check` (an ASan build) on each with a
timeout. Reports crashes (signals, sanitizer reports), hangs, exit codes
outside {0,1,2} and leaks; every failing input is kept in OUT/.

usage: scripts/fuzz-binary.py [--nck build/asan/nck] [--count 500] [--seed 1] [--out fuzz-out]
"""
import argparse, os, random, shutil, subprocess, sys, tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
TOKENS = [b"$IF 1\n", b"$ENDIF\n", b"$WHILE 1\n", b"$ENDWHILE\n", b"#VAR\n", b"#ENDVAR\n", b"[", b"]",
          b"G2 X10 Y0 I5 J0\n", b"M3 S1000\n", b"M19 S.POS=350\n", b"G74 X1\n", b"#CS ON [1,2,3,0,0,30]\n",
          b"#CS OFF\n", b"L sub.nc\n", b"\xff", b"\xe4", b"\x00", b"N99999999999999999999 ", b"1e308", b"-0"]


def mutate(data: bytes, rng: random.Random) -> bytes:
    b = bytearray(data)
    for _ in range(rng.randint(1, 6)):
        op = rng.randrange(5)
        if op == 0 and b:  # flip a byte
            b[rng.randrange(len(b))] = rng.randrange(256)
        elif op == 1:  # insert a token
            at = rng.randint(0, len(b))
            b[at:at] = rng.choice(TOKENS)
        elif op == 2 and b:  # delete a span
            at = rng.randrange(len(b))
            del b[at:at + rng.randint(1, 40)]
        elif op == 3 and b:  # duplicate a line
            lines = bytes(b).split(b"\n")
            i = rng.randrange(len(lines))
            lines.insert(i, lines[i])
            b = bytearray(b"\n".join(lines))
        else:  # truncate
            b = b[: rng.randint(0, len(b))]
    return bytes(b)


def run(cmd, cwd):
    env = dict(os.environ, ASAN_OPTIONS="detect_leaks=1:abort_on_error=0", UBSAN_OPTIONS="print_stacktrace=1")
    try:
        p = subprocess.run(cmd, cwd=cwd, capture_output=True, timeout=20, env=env)
    except subprocess.TimeoutExpired:
        return "hang", b""
    bad = p.returncode not in (0, 1, 2) or b"Sanitizer" in p.stderr or b"runtime error" in p.stderr
    return ("fail" if bad else "ok"), p.stderr


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--nck", default=str(ROOT / "build/asan/nck"))
    ap.add_argument("--count", type=int, default=500)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--out", default="fuzz-out")
    a = ap.parse_args()
    rng = random.Random(a.seed)
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    programs = sorted((ROOT / "examples").glob("*/*.nc"))
    found = 0
    for i in range(a.count):
        with tempfile.TemporaryDirectory() as tmp:
            tmp = Path(tmp)
            src = rng.choice(programs)
            machine = tmp / "machine"
            shutil.copytree(src.parent, machine)
            kind = rng.randrange(3)
            if kind == 1:  # a mutated list file
                lis = rng.choice(sorted(machine.glob("*.lis")))
                lis.write_bytes(mutate(lis.read_bytes(), rng))
            prog = machine / src.name
            if kind == 0:
                prog.write_bytes(mutate(prog.read_bytes(), rng))
            args = [a.nck, "run", str(machine), str(prog), "--max-time", "120", "--events", str(tmp / "e.jsonl"),
                    "--final", str(tmp / "f.json")]
            plcs = sorted(machine.glob("*.plc"))
            if kind == 2 and plcs:
                plc = rng.choice(plcs)
                plc.write_bytes(mutate(plc.read_bytes(), rng))
                args += ["--plc", str(plc)]
            for cmd in (args, [a.nck, "parse", str(prog)], [a.nck, "check", str(machine)]):
                verdict, err = run(cmd, tmp)
                if verdict != "ok":
                    found += 1
                    keep = out / f"{i:05d}-{verdict}"
                    shutil.copytree(machine, keep, dirs_exist_ok=True)
                    (keep / "command.txt").write_text(" ".join(cmd) + "\n")
                    (keep / "stderr.txt").write_bytes(err)
                    print(f"{verdict}: {' '.join(cmd[1:2])} -> {keep}", flush=True)
    print(f"{a.count} inputs, {found} failure(s); kept in {out}/")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
