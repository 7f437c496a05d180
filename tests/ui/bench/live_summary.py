#!/usr/bin/env python3
"""Summarises planner frame logs (tessera open --frame-log): for each CSV, the median frame
and render scale over the frames logged as dragging (after the first 40 frames), the longest
frame, and from the view's stop to the still view at its preset (the first frame logged
"still" after the last moving one) the seconds and the refining frames' lengths. Prints a Markdown table. Usage:
    live_summary.py LOG.csv..."""
import csv
import statistics
import sys


def summary(path):
    rows = list(csv.DictReader(open(path)))
    drag = [r for r in rows[40:] if r["state"] == "drag"]
    # frame_ms of row i is the time since the previous frame began: the previous frame's length
    # and the wait for input before row i (wait_ms: the idle window's), which is no frame's.
    def length(i):
        return float(rows[i]["frame_ms"]) - float(rows[i].get("wait_ms") or 0)

    lengths = [length(i + 1) for i in range(len(rows) - 1)]
    out = {"frames": len(rows), "longest_ms": max(lengths) if lengths else 0}
    if drag:
        ms = statistics.median(float(r["frame_ms"]) for r in drag)
        out["drag_median_ms"] = ms
        out["drag_fps"] = 1000.0 / ms if ms > 0 else 0
        out["drag_scale"] = statistics.median(float(r["render_scale"]) for r in drag)
    moving = [i for i, r in enumerate(rows) if r["live"] == "moving"]
    if moving:
        start = moving[-1] + 1
        done = next((i for i in range(start, len(rows)) if rows[i]["live"] == "still"), None)
        if done is not None:
            refining = [length(i) for i in range(start + 1, done + 1)]
            out["to_still_s"] = sum(float(rows[i]["frame_ms"]) for i in range(start + 1, done + 1)) / 1e3
            out["still_median_ms"] = statistics.median(refining)
            out["still_longest_ms"] = max(refining)
            out["still_over_100"] = f"{sum(1 for f in refining if f > 100)} of {len(refining)}"
            # The 3D view's own time in those frames (the rest is the panels, present and swap).
            views = [float(rows[i]["render_ms"]) for i in range(start, done)]
            out["view_longest_ms"] = max(views)
            out["view_over_100"] = sum(1 for v in views if v > 100)
    return out


def cell(d, key, fmt):
    return fmt.format(d[key]) if key in d else "-"


print("| log | frames | median frame while dragging | render scale | longest frame | stop to still at preset | refining frames: median / longest / over 100 ms | their 3D view: longest / over 100 ms |")
print("|---|---|---|---|---|---|---|---|")
for path in sys.argv[1:]:
    d = summary(path)
    print(f"| {path} | {d['frames']} | {cell(d, 'drag_median_ms', '{:.1f} ms')} "
          f"({cell(d, 'drag_fps', '{:.1f} fps')}) | {cell(d, 'drag_scale', '{:.2f}')} | "
          f"{d['longest_ms']:.0f} ms | {cell(d, 'to_still_s', '{:.2f} s')} | "
          f"{cell(d, 'still_median_ms', '{:.1f}')} / {cell(d, 'still_longest_ms', '{:.0f} ms')} / "
          f"{cell(d, 'still_over_100', '{}')} | "
          f"{cell(d, 'view_longest_ms', '{:.0f} ms')} / {cell(d, 'view_over_100', '{}')} |")
