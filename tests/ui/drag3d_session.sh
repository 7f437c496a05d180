#!/bin/sh
# A fixture dragged in the 3D view under Xvfb: the basin is grabbed and moved
# along its wall over 20 frames (moved live in the renderer), let go (one move edit, snapped to
# the wall), saved; undone, saved again; then wall 1 dragged 300 mm outward in the plan and
# undone. The app must exit 0, the view must change with the
# drag and return with the undo, and the saved files must hold the moved and the first place.
#   usage: drag3d_session.sh TESSERA OUTDIR SCREENSHOT_CHECK DEMO_PROJECT
set -e
. "$(dirname "$0")/session_lib.sh"
session_start "$@"
demo=$4
cp "$demo" "$out/demo.json" # a copy: no autosave beside the shipped demo
cat >"$out/drag.txt" <<SCRIPT
quality draft
camera basin
wait 3
screenshot $out/before.png
drag3d basin 2600 1450 frames 20
wait 3
screenshot $out/moved.png
save $out/moved.json
undo
wait 3
screenshot $out/undone.png
save $out/undone.json
move-wall 1 300
save $out/wall.json
undo
save $out/wall-undone.json
quit
SCRIPT
session_window "$out/demo.json" 800x450 "$out/drag.txt" "$out/stderr.txt" \
    --frame-log "$out/frames.csv"
# Each step changed the picture (the basin moved, then came back).
"$check" "$out/before.png" "$out/moved.png" "$out/undone.png"
# One move edit, snapped to the wall; the saved basin is where it was let go, the undone one
# where it started; the drag's frames were logged as "drag".
grep -q 'move "basin" .* snap wall' "$out/stderr.txt" || { echo "FAIL: no move edit"; exit 1; }
python3 - "$out" <<'PY'
import json, sys
out = sys.argv[1]
def basin(name):
    objs = json.load(open(f"{out}/{name}.json"))["objects"]
    return [o for o in objs if o["name"] == "basin"][0]["position"]
moved, undone = basin("moved"), basin("undone")
assert abs(moved[1] - 1450) <= 5, f"moved basin at {moved}, expected y 1450"
assert abs(moved[0] - 2600) <= 30, f"moved basin at {moved}, expected against the wall x 2600"
assert undone[:2] == [2600, 1850], f"undone basin at {undone}, expected [2600, 1850]"
# Wall 1 dragged 300 mm outward: both its corners moved by 300 mm along x (it runs along y
# at x = 2600), one undo step brings both back.
def corners(name):
    return json.load(open(f"{out}/{name}.json"))["plan"]["corners"]
c0, c1, c2 = corners("undone"), corners("wall"), corners("wall-undone")
moved = [i for i in range(len(c0)) if c0[i] != c1[i]]
assert len(moved) == 2, f"wall drag moved corners {moved}"
assert all(abs(c1[i][0] - c0[i][0] - 300) < 1e-6 and c1[i][1] == c0[i][1] for i in moved), (c0, c1)
assert c2 == c0, f"one undo did not restore the wall: {c2} against {c0}"
drag = [l for l in open(f"{out}/frames.csv") if ",drag," in l]
assert len(drag) >= 19, f"{len(drag)} frames logged as drag, expected 20"
print("drag3d session: moved to", moved, "undone to", undone, len(drag), "drag frames")
PY
