#!/bin/sh
# A planner session under Xvfb: open the demo, look around, search "basin" in the
# catalog, place one, drag it against another wall, undo, redo, tile a wall and change its
# pattern, save; then wall 1's elevation, its pattern, grout and start through the tile
# actions, save again; then check the saved project. (The presentation mode and the print
# screenshot are present_session.sh, a test of its own that runs beside this one.) The app must exit 0 (a GL error fails the
# next render, and so the run), every screenshot must show the room, each action must change
# the picture, and the plan screenshots must match their goldens.
#   usage: session.sh TESSERA OUTDIR SCREENSHOT_CHECK GOLDEN_DIR
set -e
. "$(dirname "$0")/session_lib.sh"
session_start "$@"
golden=$4
# The shipped demo as `tessera open` alone would open it, but a copy: the session edits it, and
# an autosave must not land beside the shipped file (it would offer recovery to every session).
cp "$golden/../../assets/projects/designed-bathroom.json" "$out/demo.json"
cat >"$out/session.txt" <<SCRIPT
wait 2
screenshot $out/open.png
orbit 240 40 frames 20
screenshot $out/orbit.png
mode walk
walk 600 0 frames 10
walk 20000 0 frames 20
screenshot $out/walk.png
search basin
expect-hits 5
select 1
view plan
wait 2
screenshot $out/plan.png
place-selected 1200 300
expect-added 1
wait 1
screenshot $out/placed.png
drag - 1200 2700
wait 1
screenshot $out/dragged.png
undo
redo
expect-added 1
search field tile 300 x 600
expect-hits 1
select 1
tile-selected wall:1
edit tile wall:1 pattern half-offset
wait 1
screenshot $out/tiled.png
save $out/saved.json
view 3d
camera basin
quality draft
wait 3
screenshot $out/draft.png
quality interactive
elevation-wall 1
tile-pattern wall:1 herringbone
expect-pattern wall:1 herringbone
tile-grout wall:1 4
tile-start wall:1 300 200
wait 1
screenshot $out/elevation.png
save $out/saved-tiles.json
quit
SCRIPT
session_window "$out/demo.json" 800x450 "$out/session.txt" "$out/stderr.txt" \
    --frame-log "$out/frames.csv"
session_shots open orbit walk plan placed dragged tiled draft
# Each screenshot shows a room or a plan, and each action changed the picture.
"$check" "$out/open.png" "$out/orbit.png" "$out/walk.png" "$out/plan.png" "$out/placed.png" \
    "$out/dragged.png" "$out/tiled.png" "$out/draft.png"
# The tile actions: wall 1's elevation drawn, its new pattern, grout and start saved.
"$check" "$out/tiled.png" "$out/elevation.png"
grep -q '"herringbone"' "$out/saved-tiles.json" || { echo "FAIL: herringbone not saved"; exit 1; }
grep -q '"origin":.\[300, 200\]' "$out/saved-tiles.json" || {
    echo "FAIL: the tile start was not saved"
    exit 1
}
# The plan views against their goldens; the status bar (the frame time, at the bottom) is masked.
for shot in placed dragged; do
    "$check" --golden "$golden/ui-$shot.png" --mask 0,428,800,450 "$out/$shot.png"
done
# The saved project holds the edits and passes the project checks' reader.
grep -q '"half-offset"' "$out/saved.json" || { echo "FAIL: the pattern was not saved"; exit 1; }
grep -q '"product"' "$out/saved.json" || { echo "FAIL: the placed product was not saved"; exit 1; }
set +e
"$tessera" check "$out/saved.json"
rc=$?
set -e
test "$rc" -le 1 || { echo "FAIL: tessera check exit $rc"; exit 1; }
test "$(wc -l <"$out/frames.csv")" -gt 40 || { echo "FAIL: frame log too short"; exit 1; }
