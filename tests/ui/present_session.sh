#!/bin/sh
# The presentation mode and the print screenshot under Xvfb: open the demo, fly to the door
# viewpoint, present with the turntable turning, take a screenshot and a print-quality one
# (twice the window size), leave the presentation and draw again. The app must exit 0 (a GL
# error fails the next render, and so the run), every screenshot must show the room and differ
# from the one before. The window is small: the print screenshot renders at the print preset
# (supersampled, traced self-reflections), whose cost grows with its pixels.
#   usage: present_session.sh TESSERA OUTDIR SCREENSHOT_CHECK DEMO_PROJECT
set -e
. "$(dirname "$0")/session_lib.sh"
session_start "$@"
demo=$4
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
session_window "$out/demo.json" 256x144 "$out/present.txt" "$out/stderr.txt"
session_shots basin present print-shot after
# The print screenshot is twice the window's size.
grep -q 'print-quality screenshot .*print-shot.png (512x288)' "$out/stderr.txt" ||
    { echo "FAIL: the print screenshot is not 512x288"; exit 1; }
# Each screenshot shows the room, and each step changed the picture; the print screenshot,
# at another size, is checked on its own (a difference across sizes would prove nothing).
"$check" "$out/basin.png" "$out/present.png" "$out/after.png"
"$check" "$out/print-shot.png"
echo "present session: ok"
