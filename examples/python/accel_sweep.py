"""The cycle time of part.nc for three values of the spindle's run-up
acceleration (s1.lis getriebe[0].slope_profil.a_beschl, P-AXIS-00001, deg/s²):
a machine folder copied per value, run with nck.batch, the times written as
CSV and, with python3-matplotlib installed, plotted as PNG. The program
waits for the spindle to reach its speed before it cuts, so a slower
run-up costs cycle time.

    PYTHONPATH=build/default/python python3 examples/python/accel_sweep.py [OUT_DIR]
"""
import csv
import pathlib
import re
import shutil
import sys
import tempfile

import nck

HERE = pathlib.Path(__file__).resolve().parent
VALUES_DEG_S2 = [2000, 6000, 20000]  # s1.lis units, deg/s^2 (the example's own: 20000)
KEY = "getriebe[0].slope_profil.a_beschl"


def variant(folder, accel):
    """examples/mill with S1's run-up acceleration set to accel."""
    shutil.copytree(HERE.parent / "mill", folder)
    lis = folder / "s1.lis"
    text, count = re.subn(rf"^({re.escape(KEY)}\s+)\S+", rf"\g<1>{accel}", lis.read_text(), flags=re.M)
    assert count == 1, f"{KEY} not found once in {lis}"
    lis.write_text(text)
    return folder


def main(out_dir):
    out_dir.mkdir(parents=True, exist_ok=True)
    work = pathlib.Path(tempfile.mkdtemp())
    jobs = [(variant(work / f"mill_{a}", a), HERE / "part.nc") for a in VALUES_DEG_S2]
    rows = nck.batch(jobs, workers=2)
    with open(out_dir / "accel_sweep.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["a_beschl_deg_s2", "time_s", "exit"])
        for a, r in zip(VALUES_DEG_S2, rows):
            w.writerow([a, r["time_s"], r["exit"]])
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib is not installed (Debian: python3-matplotlib): CSV only", file=sys.stderr)
    else:
        plt.plot(VALUES_DEG_S2, [r["time_s"] for r in rows], marker="o")
        plt.xlabel("S1 slope_profil.a_beschl (deg/s²)")
        plt.ylabel("cycle time (s)")
        plt.title("part.nc on examples/mill")
        plt.savefig(out_dir / "accel_sweep.png", dpi=100)
    shutil.rmtree(work)
    return rows


if __name__ == "__main__":
    for a, r in zip(VALUES_DEG_S2, main(pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "out/python"))):
        print(f"a_beschl {a} deg/s^2: {r['time_s']:.3f} s (exit {r['exit']})")
