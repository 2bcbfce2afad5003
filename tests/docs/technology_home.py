#!/usr/bin/env python3
"""3D distance control keeps to its home (docs/architecture.md, "Adding a
technology"): outside src/distctrl/, include/nck/distctrl/ and
tests/unit/distctrl/, its types are named only in its five registrations and
in the readers the recipe names. Prints each file that names them elsewhere,
and each registration that lost them; exit 1 if any."""
import pathlib
import re
import sys

root = pathlib.Path(__file__).resolve().parents[2]
HOME = ("src/distctrl/", "include/nck/distctrl/", "tests/unit/distctrl/")
TYPES = re.compile(r"\b(DistCtrl|DistCtrlOp|DistChange|StateEvent|DistUnit)\b")
REGISTRATIONS = {
    "include/nck/nc/hash_commands.hpp",   # nc::HashCommand
    "include/nck/prep/technologies.hpp",  # PrepTechnologies
    "include/nck/kernel/attachment.hpp",  # kernel::Attachment
    "include/nck/kernel/event.hpp",       # EventPayload
    "src/kernel/technologies.hpp",        # ChannelTechnologies
}
READERS = {
    "src/nc/modal_apply.cpp",   # the decoder's memory of the mode (310024, 310025)
    "src/kernel/kernel.cpp",    # the final state's dist block
    "src/sim/dry_run.cpp",      # the simulated sensor switched on
    "src/sim/prep_thread.cpp",  # ... with the preparation thread
}
assert len(REGISTRATIONS) <= 5, "the recipe's bar is five registrations"

naming = set()
for folder in ("src", "include", "apps", "python/src"):
    for path in (root / folder).rglob("*"):
        rel = path.relative_to(root).as_posix()
        if path.suffix in (".hpp", ".cpp", ".h") and path.is_file() and not rel.startswith(HOME):
            if TYPES.search(path.read_text(errors="replace")):
                naming.add(rel)
problems = [f"{f}: names distance control outside its home, its registrations and its readers"
            for f in sorted(naming - REGISTRATIONS - READERS)]
problems += [f"{f}: a registration that no longer names distance control" for f in sorted(REGISTRATIONS - naming)]
print("\n".join(problems) if problems else
      f"technology home: distance control is registered in {len(REGISTRATIONS)} files, read in {len(READERS)}")
sys.exit(1 if problems else 0)
