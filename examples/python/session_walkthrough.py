"""A step-by-step session (docs/python.md): run to a block, hold there,
read the state, lower the feed override, and go on to the end.

    PYTHONPATH=build/default/python python3 examples/python/session_walkthrough.py
"""
import pathlib

import nck

HERE = pathlib.Path(__file__).resolve().parent


def main():
    s = nck.Machine(HERE.parent / "mill").session(HERE / "part.nc")
    assert s.run_until(block="N60"), "N60 never started"
    s.hold()                                   # feedhold: the path brakes
    s.step(500)
    ch = s.state()["channels"][0]
    print(f"t={s.time_s:.3f} s at line {ch['line']} (N{ch['n']}), {ch['program_state']}, "
          f"X={ch['axes']['X']['mcs']:.3f} mm, path {ch['path_velocity_mm_s']:.1f} mm/s")
    s.override(feed=50)                        # the rest at half the feed
    s.hold(False)
    assert s.run_until(event="end")
    print(f"program end at {s.time_s:.3f} s; errors: {s.errors()}")
    return s.time_s


if __name__ == "__main__":
    main()
