#!/usr/bin/env python3
"""pnr-phase.py LOG | --watch SECONDS PREFIX PATH PID -- where a running
nextpnr is, read from its log: the progress lines of scripts/pnr.sh,
pnr-seeds.sh and bitstream.sh (scripts/pnr-progress.sh; a placement of a
full LFE5U-85F takes half an hour to three hours here, silent otherwise).

LOG: prints one line, the phase nextpnr last entered and how far it is in
it.  --watch: every SECONDS, one line "PREFIX: H:MM:SS elapsed; PHASE"
with the phase of the log at PATH; or, when PATH is a folder, "...
elapsed; seed K PHASE; ..." for each of its files (named by a seed,
holding the path of that seed's log; the caller adds a file when a
placement starts and removes it when it ends), nothing while the folder
is empty.  It stops when the folder is removed or when PID, the caller
that starts it, is no longer its parent process: so a caller killed
before the watcher starts leaves no watcher (a parent read at start-up
would already be init's).
Phases, in nextpnr's order (ECP5 and iCE40 alike):

  starting                     no log yet
  packing                      before the placer
  HeAP placement               "Running main analytical placer", then
                               its "at iteration #N, type ALL" lines
  annealing                    "Running simulated annealing placer",
                               then its "at iteration #N: temp" lines
  routing                      router1: "Routing N arcs." then its
                               progress rows (iterations | ... | arcs
                               left | time); router2: its "iter=N ...
                               overused=M" lines
  reporting                    after "Router1 time" / "Router2 time"
  finished                     "Program finished normally."

Exit status 0; 2 on a bad argument.  A log that cannot be read (not
written yet) is "starting".
"""
import os
import re
import sys
import time

HEAP = re.compile(r"at iteration #(\d+), type ALL")
SA = re.compile(r"at iteration #(\d+): temp")
ARCS = re.compile(r"^Info: Routing (\d+) arcs\.")
# router1's progress row: "Info:  132000 |  50344  81655 |  402  598 |  227130|  12.96  1369.67|"
ROUTER1 = re.compile(r"^Info:\s+(\d+) \|\s+\d+\s+\d+ \|\s+\d+\s+\d+ \|\s+(\d+)\|")
ROUTER2 = re.compile(r"iter=(\d+) .*overused=(\d+)")


def phase(lines):
    """The phase of a nextpnr log, given as its lines (a file or a list; see above)."""
    state, detail, arcs = "packing", "", None
    for line in lines:
        if "Program finished normally" in line:
            state, detail = "finished", ""
        elif re.search(r"Router[12] time", line):
            state, detail = "reporting", ""
        elif "Running main analytical placer" in line:
            state, detail = "HeAP placement", ""
        elif "Running simulated annealing placer" in line:
            state, detail = "annealing", ""
        elif line.startswith("Info: Routing globals") or "Running router2" in line:
            state, detail = "routing", ""
        elif state == "HeAP placement" and (m := HEAP.search(line)):
            detail = f"iteration {m.group(1)}"
        elif state == "annealing" and (m := SA.search(line)):
            detail = f"iteration {m.group(1)}"
        elif state == "routing" and (m := ARCS.match(line)):
            arcs = int(m.group(1))
            detail = f"{arcs:,} arcs"
        elif state == "routing" and (m := ROUTER1.match(line)):
            left = int(m.group(2))
            of = f" of {arcs:,}" if arcs else ""
            detail = f"{left:,}{of} arcs left after {int(m.group(1)):,} iterations"
        elif state == "routing" and (m := ROUTER2.search(line)):
            detail = f"router2 iteration {m.group(1)}, {int(m.group(2)):,} wires overused"
    return state + (f" ({detail})" if detail else "")


def log_phase(path):
    """phase() of the log at path; "starting" when it cannot be read."""
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            return phase(f)
    except OSError:
        return "starting"


def watch(seconds, prefix, path, parent):
    """The --watch loop (see above); returns when parent is no longer the
    parent process, or the folder at path is removed."""
    start = time.monotonic()
    folder = os.path.isdir(path)
    if os.getppid() != parent:
        return
    while True:
        time.sleep(seconds)
        if os.getppid() != parent or (folder and not os.path.isdir(path)):
            return
        parts = seed_phases(path) if folder else [log_phase(path)]
        if parts:
            e = int(time.monotonic() - start)
            print(f"{prefix}: {e // 3600}:{e % 3600 // 60:02d}:{e % 60:02d} elapsed; "
                  + "; ".join(parts), flush=True)


def seed_phases(folder):
    """ "seed K PHASE" for each seed registered in folder, by seed."""
    parts = []
    for seed in sorted(os.listdir(folder), key=lambda n: (len(n), n)):
        try:
            with open(os.path.join(folder, seed), encoding="utf-8") as f:
                log = f.read().strip()
        except OSError:
            continue  # the placement ended between the listing and here
        parts.append(f"seed {seed} {log_phase(log)}")
    return parts


def main(argv):
    if len(argv) == 2 and argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0
    if len(argv) == 2:
        print(log_phase(argv[1]))
        return 0
    if (len(argv) == 6 and argv[1] == "--watch" and re.fullmatch(r"[1-9]\d*", argv[2])
            and re.fullmatch(r"[1-9]\d*", argv[5])):
        try:
            watch(int(argv[2]), argv[3], argv[4], int(argv[5]))
        except KeyboardInterrupt:
            pass
        return 0
    print(__doc__.strip(), file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
