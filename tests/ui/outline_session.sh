#!/bin/sh
# The selection outlined in the 3D view under Xvfb: the vanity is picked (as a click selects
# it) and its box and its group's (basin, mixer, mirror, lamp) are drawn in the plan's
# selection colour over the 3D pane while the still view accumulates, once it is refined, and
# while the view moves; none of it shows before the pick or after the selection is cleared.
# The window logs the outline's box (locate selection); the shots are counted inside it.
#   usage: outline_session.sh TESSERA OUTDIR SCREENSHOT_CHECK DEMO_PROJECT
set -e
. "$(dirname "$0")/session_lib.sh"
session_start "$@"
cp "$4" "$out/demo.json" # a copy: no autosave beside the shipped demo
cat >"$out/outline.txt" <<SCRIPT
quality draft
panes one
view 3d
camera basin
wait 3
screenshot $out/before.png
locate selection
pick vanity
wait 1
screenshot $out/accumulating.png
locate selection
wait 150
screenshot $out/refined.png
orbit 40 0 frames 3
screenshot $out/moving.png
locate selection
wait 2
pick -
wait 3
screenshot $out/cleared.png
locate selection
quit
SCRIPT
session_window "$out/demo.json" 960x540 "$out/outline.txt" "$out/stderr.txt" \
    --frame-log "$out/frames.csv"
session_shots before accumulating refined moving cleared
grep -q '^tessera: locate selection: none shows' "$out/stderr.txt" ||
    { echo "FAIL: an outline before anything was selected"; exit 1; }
grep -q '^tessera: selected "vanity"' "$out/stderr.txt" || { echo "FAIL: the pick did not select"; exit 1; }
# The outline's box as the window drew it after the pick, and after the orbit.
boxes=$(sed -n 's/^tessera: locate selection at \([-0-9 ]*\)$/\1/p' "$out/stderr.txt")
test "$(echo "$boxes" | wc -l)" -eq 2 || { echo "FAIL: no outline box logged: $boxes"; exit 1; }
# The selection colour (plan_draw.c's 220, 110, 0) inside a box grown by 3 pixels.
count() { # SHOT X0 Y0 X1 Y1
    "$check" --count dc6e00 12 "$(($2 - 3)),$(($3 - 3)),$(($4 + 4)),$(($5 + 4))" "$out/$1.png"
}
# shellcheck disable=SC2046 # the box splits into four numbers on purpose
set -- $(echo "$boxes" | head -n 1)
picked=$(count accumulating "$@") refined=$(count refined "$@") before=$(count before "$@")
# shellcheck disable=SC2046
set -- $(echo "$boxes" | tail -n 1)
moving=$(count moving "$@") cleared=$(count cleared "$@")
echo "selection-coloured pixels: before $before, accumulating $picked, refined $refined," \
    "moving $moving, cleared $cleared"
# The box's 12 edges and the group's are long lines of 2-3 pixels: hundreds of pixels.
for n in "$picked" "$refined" "$moving"; do
    test "$n" -ge 300 || { echo "FAIL: the outline is missing from a shot ($n pixels)"; exit 1; }
done
for n in "$before" "$cleared"; do
    test "$n" -le 10 || { echo "FAIL: the selection colour shows with nothing selected ($n)"; exit 1; }
done
# The stages the shots were taken at: the frame log has moving, refining and still frames.
for stage in moving refining still; do
    grep -q ",$stage," "$out/frames.csv" || { echo "FAIL: no $stage frame logged"; exit 1; }
done
echo "outline_session: ok"
