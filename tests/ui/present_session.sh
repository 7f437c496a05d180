#!/bin/sh
# The presentation mode and the print screenshot under Xvfb: open the demo, fly to the door
# viewpoint, present with the turntable turning, take a screenshot and a print-quality one
# (twice the window size), leave the presentation and draw again. The app must exit 0 (a GL
# error fails the next render, and so the run), every screenshot must show the room and differ
# from the one before. The window is small: the print screenshot renders at the print preset
# (supersampled, traced self-reflections), whose cost grows with its pixels.
#   usage: present_session.sh TESSERA OUTDIR SCREENSHOT_CHECK DEMO_PROJECT
set -e
tessera=$1
out=$2
check=$3
demo=$4
rm -rf "$out"
mkdir -p "$out"
cp "$demo" "$out/demo.json" # a copy: no autosave beside the shipped demo
cat >"$out/present.txt" <<SCRIPT
wait 2
camera basin
quality interactive
wait 2
screenshot $out/basin.png
fly door 1
wait 20
present on
turntable on
wait 10
screenshot $out/present.png
print-shot $out/print-shot.png
present off
turntable off
wait 2
screenshot $out/after.png
quit
SCRIPT
xvfb-run -a -s "-screen 0 1280x720x24" "$tessera" open "$out/demo.json" --size 256x144 \
    --script "$out/present.txt" 2>"$out/stderr.txt" || {
    cat "$out/stderr.txt"
    echo "FAIL: the session did not exit 0"
    exit 1
}
cat "$out/stderr.txt"
for shot in basin present print-shot after; do
    test -s "$out/$shot.png" || { echo "FAIL: no screenshot $shot"; exit 1; }
done
# The print screenshot is twice the window's size.
grep -q 'print-quality screenshot .*print-shot.png (512x288)' "$out/stderr.txt" ||
    { echo "FAIL: the print screenshot is not 512x288"; exit 1; }
# Each screenshot shows the room, and each step changed the picture.
"$check" "$out/basin.png" "$out/present.png" "$out/print-shot.png" "$out/after.png"
echo "present session: ok"
