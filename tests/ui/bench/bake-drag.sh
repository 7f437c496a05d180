#!/bin/sh
# A hand's drag while the light is baked (docs/rendering.md, "Baked indirect light", "In the
# window"): under Xvfb, xdotool drags the vanity in the plan (plan and 3D side by side, 1280 x
# 720, interactive); the window shoots itself before, just after, twice during the bake, and
# after it; the frame log is summarised by state. XDG_CACHE_HOME with the project's bake in it
# (tessera bake PROJECT) makes the edit's bake a partial one.
#   usage: bake-drag.sh TESSERA PROJECT OUTDIR   (writes OUTDIR/shot-*.png, drive.csv)
set -e
if [ -z "$BAKE_DRAG_INSIDE" ]; then
    out=$3
    mkdir -p "$out"
    . "$(dirname "$0")/../session_lib.sh"
    BAKE_DRAG_INSIDE=1 session_xvfb sh "$0" "$@"
    exit $?
fi
tessera=$1 project=$2 out=$3
mkdir -p "$out"
rm -f "$out/dragged" "$out"/shot-*.png
cp "$project" "$out/demo.json"
cat >"$out/drive.txt" <<SCRIPT
quality interactive
panes both
camera basin
view plan
wait 10
locate fixture vanity
screenshot $out/shot-0-before.png
wait-file $out/dragged
wait 2
screenshot $out/shot-1-released.png
wait 20
screenshot $out/shot-2-baking.png
wait 60
screenshot $out/shot-3-baking.png
wait-bake
wait 300
screenshot $out/shot-4-after.png
quit
SCRIPT
"$tessera" open "$out/demo.json" --size 1280x720 --script "$out/drive.txt" \
    --frame-log "$out/drive.csv" 2>"$out/stderr.txt" &
pid=$!
i=0
until grep -q "waiting for" "$out/stderr.txt"; do
    sleep 0.2
    i=$((i + 1))
    test $i -lt 600 || { kill "$pid"; echo "the window never waited for the drag"; exit 1; }
done
sleep 1
# shellcheck disable=SC2046 # "X Y" splits into two arguments on purpose
set -- $(sed -n 's/^tessera: locate fixture "vanity" at \([0-9-]*\) \([0-9-]*\).*/\1 \2/p' \
    "$out/stderr.txt" | tail -n 1)
x=$1 y=$2
xdotool mousemove "$x" "$y"
sleep 0.3
xdotool mousedown 1
sleep 0.2
for k in 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20; do
    xdotool mousemove "$x" $((y - 3 * k))
    sleep 0.05
done
sleep 0.2
xdotool mouseup 1
touch "$out/dragged"
wait "$pid"
grep "tessera: light:\|tessera: move" "$out/stderr.txt"
python3 "$(dirname "$0")/bake_frames.py" "$out/drive.csv"
