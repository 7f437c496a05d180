#!/bin/sh
# The live view and the cameras under Xvfb, in presentation mode (the whole window is the 3D
# view): from the basin viewpoint the orbit is turned to look up from below the floor, then
# level again, zoomed out 40 steps (far beyond the walls) and turned along them; then the view is left still until
# it is refined; then walk mode from there, and a walk. Every logged eye
# must be inside the room (walls, floor, ceiling, with the margin), no shot may be black, the
# log must show the moving frames and then the still view at full resolution (scale 1.0, the
# window's size) refined to the end, every strip with the one exposure of the whole view.
#   usage: live_session.sh TESSERA OUTDIR SCREENSHOT_CHECK DEMO_PROJECT
set -e
. "$(dirname "$0")/session_lib.sh"
session_start "$@"
demo=$4
cp "$demo" "$out/demo.json" # a copy: no autosave beside the shipped demo
cat >"$out/live.txt" <<SCRIPT
quality interactive
camera basin
present on
wait 3
orbit 600 -400 frames 10
screenshot $out/floor.png
orbit 0 300 frames 5
zoom -40 frames 10
orbit 600 0 frames 30
screenshot $out/wall.png
wait 400
screenshot $out/still.png
mode walk
wait 3
screenshot $out/walk.png
walk 1200 0 frames 30
wait 3
screenshot $out/walked.png
quit
SCRIPT
session_window "$out/demo.json" 960x540 "$out/live.txt" "$out/stderr.txt" \
    --frame-log "$out/frames.csv"
# Each shot shows a room; the still view differs from the moving one only in sharpness, so it
# is checked on its own.
"$check" "$out/floor.png" "$out/wall.png" "$out/walk.png"
"$check" "$out/still.png"
for shot in floor wall still walk walked; do
    # The mean colour, 0..1 (the channel selection converts to float).
    avg=$(oiiotool "$out/$shot.png" --ch R,G,B --printstats | sed -n 's/.*Stats Avg: \([0-9.]*\) \([0-9.]*\) \([0-9.]*\).*/\1 \2 \3/p')
    echo "$shot: mean $avg"
    echo "$avg" | awk -v s="$shot" '{ if (NF != 3 || $1 > 1 || $1 + $2 + $3 < 0.3) {
        print "FAIL: " s ".png is dark (or its mean unread)"; exit 1 } }'
done
python3 - "$out/frames.csv" "$out/demo.json" <<'PY'
import csv, json, sys
rows = list(csv.DictReader(open(sys.argv[1])))
plan = json.load(open(sys.argv[2]))["plan"]
xs = [c[0] for c in plan["corners"]]
ys = [c[1] for c in plan["corners"]]
h = plan.get("height_mm", 2500)
margin = 150 - 1
bad = [r for r in rows if not (min(xs) + margin <= float(r["eye_x"]) <= max(xs) - margin and
                               min(ys) + margin <= float(r["eye_y"]) <= max(ys) - margin and
                               margin <= float(r["eye_z"]) <= h - margin)]
assert not bad, f"{len(bad)} frames with the eye outside the room, first {dict(bad[0])}"
moving = [i for i, r in enumerate(rows) if r["live"] == "moving" and r["state"] == "drag"]
assert moving, "no moving frames logged"
after = rows[moving[-1] + 1:]
still = [r for r in after if r["live"] == "still"]
assert still, "the view never finished refining after the orbit"
assert all(float(r["render_scale"]) == 1.0 and r["width"] == "960" and r["height"] == "540"
           for r in still), "a still frame not at full resolution"
assert float(still[0]["progress"]) == 1.0
refining = [r for r in after if r["live"] == "refining"]
assert refining and all(float(r["render_scale"]) == 1.0 for r in refining)
# One exposure for a whole still (the demo's exposure is auto; interactive's ladder has one
# step): strips that metered themselves would each log their own EV, and show bands.
runs, run = [], []
for r in rows + [{"live": "moving"}]:
    if r["live"] == "refining":
        run.append(r["exposure_ev"])
    elif run:
        runs.append(run)
        run = []
assert runs and all(len(set(run)) == 1 for run in runs), \
    f"a still's strips used several exposures: {[sorted(set(run))[:4] for run in runs]}"
walk = [r for r in rows[rows.index(still[-1]) + 1:]]
assert walk and all(abs(float(r["eye_z"]) - 1600) < 1 for r in walk[2:]), "walker not at 1.6 m"
scales = sorted(float(r["render_scale"]) for r in rows if r["live"] == "moving")
print(f"live session: {len(rows)} frames, moving scale {scales[0]:.2f}-{scales[-1]:.2f}, "
      f"{len(refining)} refining frames, then still at 1.0; eye always inside")
PY
