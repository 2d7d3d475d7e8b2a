#!/usr/bin/env python3
"""The exact pipe's build time against OpenCascade's, measured so that the ratio is stable
(docs/BENCHMARKS.md, "Pipes against OpenCascade", session 16; issue 17).

Both sides are timed in the same run, alternately, round after round, so that both see the
same machine state (the load of a shared machine changes within seconds):

* rcagd: ``benches/pipe_profile.rs`` (release) builds the exact pipe around the PH quintic
  with every certificate ``N`` times in one process and prints the CPU time of every build
  (the scheduler's run time of all its threads, ``/proc/self/task/*/schedstat``, ns);
* OpenCascade: ``BRepOffsetAPI_MakePipe`` of the circle of the same radius in the normal
  plane at the start along the same spine (rcagd's STEP of the ``ph_curve``, read once
  before the timing: the build from the curve in memory, as rcagd's starts from its curve
  in memory), ``N`` times per round, CPU time of this process per build
  (``time.process_time_ns``, ``CLOCK_PROCESS_CPUTIME_ID``); and, for comparison with the
  earlier tables, ``N`` builds that read the spine's STEP file inside the timing, as
  ``benches/occ/bspline_pipe.py bench`` does.

The first build of every round is a warm-up on both sides and is not counted. Reported per
side and spine: the number of builds, median, minimum, quartiles and maximum of the CPU
time, the median wall time; the ratio of the medians, and the spread of the per-round ratios
(median of rcagd's builds in a round over OpenCascade's in the same round).

Usage (through the OpenCascade venv: ``py="$(scripts/occ_venv.sh)"``; benches/occ/pipe_ratio.sh
does all of it):
    python benches/occ/pipe_ratio.py SPINE_DIR ROUNDS N LABEL=PIPE_PROFILE_BINARY...
``SPINE_DIR`` holds ``gallery.step`` and ``issue.step`` (the spines, written by ``rcagd build``);
several rcagd binaries (e.g. ``before=…`` ``after=…``) are run in turn within each round.
"""

from __future__ import annotations

import statistics
import subprocess
import sys
import time

from bspline_pipe import pipe_along, spine_curve  # benches/occ, beside this script

# (spine name, pipe_profile argument, radius)
SPINES = [("gallery quintic, r = 1/10", "x", "gallery.step", 0.1),
          ("issue 17's quintic, r = 1/8", "issue", "issue.step", 0.125)]


def occ_round(curve, radius: float, n: int, path: str | None = None) -> tuple[list[float], list[float]]:
    """``n`` builds (after one warm-up); with ``path`` the spine is read from that STEP file
    inside every timed build, as ``benches/occ/bspline_pipe.py bench`` times it."""
    cpu, wall = [], []
    for _ in range(n + 1):
        c, w = time.process_time_ns(), time.perf_counter_ns()
        pipe_along(spine_curve(path) if path else curve, radius)
        cpu.append((time.process_time_ns() - c) / 1e6)
        wall.append((time.perf_counter_ns() - w) / 1e6)
    return cpu[1:], wall[1:]


def rcagd_round(binary: str, which: str, n: int) -> tuple[list[float], list[float]]:
    out = subprocess.run([binary, which, str(n + 1)], check=True, capture_output=True,
                         text=True).stdout
    cpu = wall = None
    for line in out.splitlines():
        if line.startswith("per-run CPU ms:"):
            cpu = [float(x) for x in line.split(":", 1)[1].split()]
        elif line.startswith("per-run wall ms:"):
            wall = [float(x) for x in line.split(":", 1)[1].split()]
    if not cpu or not wall or len(cpu) != n + 1:
        raise SystemExit(f"{binary}: no per-run times in its output:\n{out}")
    return cpu[1:], wall[1:]


def stats(v: list[float]) -> str:
    q = statistics.quantiles(v, n=4)
    return (f"{statistics.median(v):.2f} | {min(v):.2f} | {q[0]:.2f}–{q[2]:.2f} | {max(v):.2f}")


def main() -> None:
    if len(sys.argv) < 5:
        raise SystemExit(__doc__)
    spine_dir, rounds, n = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    bins = [a.split("=", 1) for a in sys.argv[4:]]
    load0 = open("/proc/loadavg").read().split()[0]
    t0 = time.strftime("%H:%M:%S", time.gmtime())
    for name, which, step, radius in SPINES:
        curve = spine_curve(f"{spine_dir}/{step}")
        cpu = {"OpenCascade": [], "OpenCascade+read": []} | {label: [] for label, _ in bins}
        wall = {k: [] for k in cpu}
        round_ratio = {label: [] for label, _ in bins}
        for _ in range(rounds):
            oc, ow = occ_round(curve, radius, n)
            cpu["OpenCascade"] += oc
            wall["OpenCascade"] += ow
            rc_, rw_ = occ_round(curve, radius, n, f"{spine_dir}/{step}")
            cpu["OpenCascade+read"] += rc_
            wall["OpenCascade+read"] += rw_
            for label, binary in bins:
                rc, rw = rcagd_round(binary, which, n)
                cpu[label] += rc
                wall[label] += rw
                round_ratio[label].append(statistics.median(rc) / statistics.median(oc))
        print(f"\n{name}: {rounds} rounds × {n} builds per side (alternately)")
        print("| side | builds | CPU median ms | min | quartiles | max | wall median ms |")
        print("| --- | --- | --- | --- | --- | --- | --- |")
        for k, v in cpu.items():
            side = {
                "OpenCascade": "OpenCascade BRepOffsetAPI_MakePipe (curve in memory)",
                "OpenCascade+read": "OpenCascade, reading the spine's STEP file + MakePipe",
            }.get(k, f"rcagd {k}")
            print(f"| {side} | {len(v)} | {stats(v)} | {statistics.median(wall[k]):.2f} |")
        occ = statistics.median(cpu["OpenCascade"])
        occ_read = statistics.median(cpu["OpenCascade+read"])
        for label, _ in bins:
            rr = round_ratio[label]
            print(f"ratio rcagd {label} / OpenCascade MakePipe (CPU medians): "
                  f"{statistics.median(cpu[label]) / occ:.1f}×; per round: median "
                  f"{statistics.median(rr):.1f}×, range {min(rr):.1f}–{max(rr):.1f}×; "
                  f"against read + MakePipe: {statistics.median(cpu[label]) / occ_read:.1f}×")
    load1 = open("/proc/loadavg").read().split()[0]
    t1 = time.strftime("%H:%M:%S", time.gmtime())
    print(f"\nrun {t0}–{t1} UTC, load (1 min) {load0} → {load1}")


if __name__ == "__main__":
    main()
