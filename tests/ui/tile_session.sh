#!/bin/sh
# The tile panel and the elevation view under Xvfb: open the demo,
# show wall 1's elevation, change its pattern, grout and start point through the tile actions
# (the same edit lines the panel sends), click the elevation to move the start, undo and redo
# that click, give wall 2 a band and a border row of a tile picked in the catalog browser,
# turn the floor's tiles, save; then the saved project must hold exactly those values, read
# back through `tessera check`, and the elevation screenshots must show the drawing and
# differ after each change. Last the panel over the 3D view: a pattern change shows there.
#   usage: tile_session.sh TESSERA OUTDIR SCREENSHOT_CHECK DEMO_PROJECT
set -e
. "$(dirname "$0")/session_lib.sh"
session_start "$@"
demo=$4
# A copy, so no autosave of the shipped demo (another session's) is offered, and ours stays here.
cp "$demo" "$out/demo.json"
cat >"$out/tiles.txt" <<SCRIPT
wait 2
elevation-wall 1
wait 1
screenshot $out/elevation.png
expect-tiles wall:1 20
tile-pattern wall:1 vertical-stack
expect-pattern wall:1 vertical-stack
tile-grout wall:1 5 0.2 0.3 0.4
tile-start wall:1 450 300
wait 1
screenshot $out/changed.png
elevation-click 1004 797
undo
expect-pattern wall:1 vertical-stack
redo
wait 1
screenshot $out/clicked.png
search border 50 x 300
select 1
tile-band wall:2 0 1500
tile-border wall:2 600
elevation-wall 2
wait 1
screenshot $out/border.png
tile-surface floor
tile-rotate floor 45
expect-pattern floor straight
expect-tiles floor 20
wait 1
screenshot $out/floor.png
save $out/saved.json
tile-panel on
view 3d
camera basin
quality draft
wait 3
screenshot $out/room.png
tile-pattern wall:1 diagonal
tile-grout wall:1 8 0.05 0.05 0.05
wait 3
screenshot $out/room-diagonal.png
quit
SCRIPT
session_window "$out/demo.json" 1280x720 "$out/tiles.txt" "$out/log.txt"
session_shots elevation changed clicked border floor room room-diagonal
# Each screenshot shows a drawing, and each change changed the picture.
"$check" "$out/elevation.png" "$out/changed.png" "$out/clicked.png" "$out/border.png" \
    "$out/floor.png"
# The 3D view with the tile panel over it: a pattern and grout change shows in the room at once.
"$check" "$out/room.png" "$out/room-diagonal.png"

# One tiling's lines of the saved file (cJSON's layout: one field a line, tabs).
tiling() {
    awk -v name="$1" '
        $0 ~ "\"name\":\t\"" name "\"" { on = 1 }
        on { print }
        on && /"to":/ { exit }' "$out/saved.json"
}
expect() { # NAME TEXT: the tiling NAME has the line TEXT
    tiling "$1" | grep -q -F "$2" || {
        echo "FAIL: tiling $1 has no line '$2':"
        tiling "$1"
        exit 1
    }
}
TAB=$(printf '\t')
expect wall-1 "\"pattern\":$TAB\"vertical-stack\""
expect wall-1 "\"grout\":${TAB}5"
expect wall-1 "\"grout_color\":$TAB[0.2, 0.3, 0.4]"
expect wall-1 "\"align\":$TAB\"line\""
expect wall-1 "\"origin\":$TAB[1000, 800]" # the click, snapped to 10 mm
expect wall-2 "\"to\":${TAB}1500"
expect floor "\"rotation\":${TAB}45"
# Wall 2 keeps its border row at 1200 and has a second one at 600.
awk '/"name":\t"wall-2"/ { on = 1 } on && /"name":\t"wall-3"/ { exit } on' "$out/saved.json" \
    >"$out/wall-2.txt"
grep -q -F "\"bottom\":${TAB}1200" "$out/wall-2.txt" &&
    grep -q -F "\"bottom\":${TAB}600" "$out/wall-2.txt" || {
    echo "FAIL: wall 2's border rows:"
    cat "$out/wall-2.txt"
    exit 1
}
# The saved project reads back (exit 0: no findings that are errors, 1: findings).
set +e
"$tessera" check "$out/saved.json" >/dev/null
rc=$?
set -e
test "$rc" -le 1 || { echo "FAIL: tessera check exit $rc"; exit 1; }
echo "tile session: ok"
