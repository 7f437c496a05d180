#!/bin/sh
# A planner session under Xvfb (issue 8): open the demo, orbit, walk, switch quality, take
# screenshots; the app must exit 0 and every screenshot must show the room, not a blank or
# single-colour window.  usage: session.sh TESSERA OUTDIR GOLDEN_TOOL
set -e
tessera=$1
out=$2
mkdir -p "$out"
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
wait 1
screenshot $out/search.png
camera basin
quality draft
wait 3
screenshot $out/draft.png
quality print
wait 1
screenshot $out/print.png
quality interactive
fly door 1
wait 20
present on
turntable on
wait 10
screenshot $out/present.png
print-shot $out/print-shot.png
quit
SCRIPT
xvfb-run -a -s "-screen 0 1280x720x24" "$tessera" open --size 1024x576 --script "$out/session.txt" \
    --frame-log "$out/frames.csv"
for shot in open orbit walk search draft print present print-shot; do
    test -s "$out/$shot.png" || { echo "FAIL: no screenshot $shot"; exit 1; }
done
# Each screenshot has many colours (a rendered room), and the orbit changed the picture.
"$3" "$out/open.png" "$out/orbit.png" "$out/walk.png" "$out/search.png" "$out/draft.png"
"$3" "$out/print.png" "$out/present.png" "$out/print-shot.png"
test "$(wc -l <"$out/frames.csv")" -gt 40 || { echo "FAIL: frame log too short"; exit 1; }
