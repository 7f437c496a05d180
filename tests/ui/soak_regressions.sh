#!/bin/sh
# What the window's soak found, each kept as a scripted session under Xvfb:
# 1. a product dropped on the plan far outside the room (beyond the walls' snapping distance)
#    was placed there, and the saved project failed `tessera check` (outside-room): now refused;
# 2. the same for a fixture dragged there;
# 3. a fixture dragged where no wall is near enough to snap to was moved when the pointer was
#    inside the room, though its footprint reached through a wall (the shower screen, 10 mm);
# 4. a fixture against a wall turned by 90 degrees about its back (the shower system) reached
#    through the wall: both now refused, as any window edit that makes a fixture reach out.
#   usage: soak_regressions.sh TESSERA OUTDIR SCREENSHOT_CHECK PROJECT
set -e
. "$(dirname "$0")/session_lib.sh"
session_start "$@"
project=$4

# expect_refused NAME MESSAGE: the script $out/NAME.txt fails on its last line with MESSAGE,
# and its save before that action holds the project unchanged.
expect_refused() {
    set +e
    session_xvfb "$tessera" open "$project" --size 1024x600 --script "$out/$1.txt" \
        2>"$out/$1.log"
    rc=$?
    set -e
    cat "$out/$1.log"
    test "$rc" -eq 1 || { echo "FAIL: $1: the window exited $rc, not 1 (the action was taken)"; exit 1; }
    grep -q "$2" "$out/$1.log" || { echo "FAIL: $1: no \"$2\""; exit 1; }
}

cat >"$out/drop.txt" <<SCRIPT
quality draft
view plan
search basin
select 1
place-selected 1979 -1180
SCRIPT
expect_refused drop 'outside the room, nothing placed'

cat >"$out/drag.txt" <<SCRIPT
quality draft
view plan
drag wc 1979 -1180
SCRIPT
expect_refused drag 'wc: outside the room, not moved'
# The screen stands on the wall y = 0 along y (its back centre at 1740, 600, turned 90
# degrees): the pointer carries its footprint's centre 10 mm towards that wall.
cat >"$out/nudge.txt" <<SCRIPT
quality draft
view plan
drag shower-screen 1720 590
SCRIPT
expect_refused nudge 'shower-screen would reach through a wall: move refused'

cat >"$out/rotate.txt" <<SCRIPT
quality draft
view plan
edit rotate "shower-system" 90
SCRIPT
expect_refused rotate 'shower-system would reach through a wall: rotate refused'
echo "soak_regressions: ok"
