#!/usr/bin/env python3
"""Summarises planner frame logs (tessera open --frame-log) by state (idle, drag, job, bake):
frames, wall time (frame_ms) median, 95th percentile and maximum, and where the log has it the
window thread's CPU time (cpu_ms) median and maximum; then the longest frame. The first five
frames (the window compiling its programs) are left out. Usage: bake_frames.py F.csv ..."""
import csv
import sys


def pct(values, q):
    values = sorted(values)
    return values[min(len(values) - 1, int(q * len(values)))]


for path in sys.argv[1:]:
    rows = list(csv.DictReader(open(path)))[5:]  # the window's first frames compile programs
    print(path)
    for state in sorted({r["state"] for r in rows}):
        sel = [r for r in rows if r["state"] == state]
        wall = [float(r["frame_ms"]) for r in sel]
        line = (f"  {state:5} {len(sel):5} frames  wall median {pct(wall, 0.5):7.1f} ms  "
                f"p95 {pct(wall, 0.95):7.1f}  max {max(wall):7.1f}")
        if "cpu_ms" in sel[0]:
            cpu = [float(r["cpu_ms"]) for r in sel]
            line += f"  |  cpu median {pct(cpu, 0.5):6.1f} ms  max {max(cpu):6.1f}"
        print(line)
    worst = max(rows, key=lambda r: float(r["frame_ms"]))
    print(f"  longest: frame {worst['frame']} ({worst['state']}) {float(worst['frame_ms']):.1f} ms")
