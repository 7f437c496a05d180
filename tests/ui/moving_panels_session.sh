#!/bin/sh
# The panels show while the 3D view moves: a turntable and a flight keep every frame a moving
# one (the 3D view rendered, shown, then read back for the still view to start from), and the
# screenshot of such a frame shows the menu, the toolbar, the columns and the plan beside the
# room (screenshot_check --panes on the rectangles the window logged). The readback once left
# the render's own framebuffer bound, and the panels of every moving frame went there.
#   usage: moving_panels_session.sh TESSERA OUTDIR SCREENSHOT_CHECK PROJECT
set -e
. "$(dirname "$0")/session_lib.sh"
session_start "$@"
cat >"$out/moving.txt" <<SCRIPT
quality draft
wait 2
turntable on
wait 1
screenshot $out/turntable.png
turntable off
fly shower 3
wait 0.5
screenshot $out/flight.png
quit
SCRIPT
session_window "$4" 1280x720 "$out/moving.txt" "$out/moving.log"
session_shots turntable flight
layout=$(grep '^tessera: layout' "$out/moving.log" | tail -n 1)
rects=$(echo "$layout" | awk '{ for (i = 4; i < NF; i += 2) { split($(i + 1), r, ",")
    if (r[3] <= 0 || r[4] <= 0) continue
    if ($i == "left" || $i == "right") printf " panel %s", $(i + 1)
    if ($i == "2d" || $i == "3d") printf " view %s", $(i + 1) } }')
case "$rects" in *panel*view*view*) ;; *) echo "FAIL: no side-by-side layout in the log: $layout"; exit 1 ;; esac
for shot in turntable flight; do
    # shellcheck disable=SC2086 # the rectangles are separate arguments
    "$check" --panes "$out/$shot.png" $rects || { echo "FAIL: $shot.png: the panels are not drawn"; exit 1; }
done
if grep -q 'bound after the 3D view' "$out/moving.log"; then
    echo "FAIL: the 3D view left an off-screen framebuffer bound for the panels"
    exit 1
fi
echo "moving_panels_session: ok"
