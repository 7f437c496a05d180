#!/bin/sh
# The baked light in the background under Xvfb (docs/rendering.md, "Baked indirect light", "In
# the window"), in presentation mode on a small room (bake-room.json: a block on the floor). The
# window opens and bakes its first light on the worker while it draws. The block is moved (an
# edit that needs a re-bake) with the bake held back until the view, drawn with the light
# carried from before the edit, is refined; then the bake runs while the window draws, and the
# new light fades in. Checked: from the edit to the end of the fade, the window's thread works
# under 100 ms in every frame but the edit's own (its scene rebuild): its CPU time, as a wall
# time on this shared machine is the load's as much as the window's (the longest wall time is
# printed; docs/rendering.md has it measured); the edit's bake is a partial one (elements from
# the cache); the picture changes when the new light arrives, by more than it changes between
# two refined frames of the same light.
#   usage: bake_session.sh TESSERA OUTDIR SCREENSHOT_CHECK PROJECT
set -e
. "$(dirname "$0")/session_lib.sh"
session_start "$@"
cp "$4" "$out/room.json"
export XDG_CACHE_HOME="$out/cache" # a cold cache: the first light is baked in full
cat >"$out/bake.txt" <<SCRIPT
quality interactive
camera front
present on
wait-bake
wait 120
screenshot $out/first.png
bake-hold on
edit move block 850 700 350
wait 120
screenshot $out/carried.png
bake-hold off
wait-bake
wait 120
screenshot $out/after.png
wait 30
screenshot $out/after2.png
quit
SCRIPT
session_window "$out/room.json" 640x480 "$out/bake.txt" "$out/stderr.txt" \
    --frame-log "$out/frames.csv"
session_shots first carried after after2
"$check" "$out/first.png" "$out/carried.png" "$out/after.png"
bakes=$(grep -c "tessera: light: baked" "$out/stderr.txt") || true
test "$bakes" -eq 2 || { echo "FAIL: $bakes bakes applied, want 2 (the first light, the edit's)"; exit 1; }
grep "tessera: light: baked" "$out/stderr.txt" | tail -1 | grep -q "([1-9][0-9]* of [0-9]* elements from the cache)" ||
    { echo "FAIL: the edit's bake reused nothing from the cache"; exit 1; }
# The mean absolute difference of two shots, 0..1 over R, G and B.
meandiff() {
    oiiotool "$1" --ch R,G,B "$2" --ch R,G,B --absdiff --printstats |
        sed -n 's/.*Stats Avg: \([0-9.e-]*\) \([0-9.e-]*\) \([0-9.e-]*\).*/\1 \2 \3/p' |
        awk '{ printf "%.6f\n", ($1 + $2 + $3) / 3 }'
}
light=$(meandiff "$out/carried.png" "$out/after.png")
noise=$(meandiff "$out/after.png" "$out/after2.png")
echo "the new light changed the picture by $light on average; two refined frames differ by $noise"
awk -v l="$light" -v n="$noise" 'BEGIN { if (!(l > 0.002 && l > 4 * n)) {
    print "FAIL: the picture did not change when the new light arrived"; exit 1 } }'
python3 - "$out/frames.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
# Runs of "bake" rows: a bake settling, running or fading in. frame_ms of row i is the length of
# frame i - 1 (from its start to frame i's), so a run's frames are timed by the rows from its
# second to the one after it; the second row of the edit's run holds the edit's scene rebuild.
runs, start = [], None
for i, r in enumerate(rows + [{"state": "end"}]):
    if r["state"] == "bake" and start is None:
        start = i
    elif r["state"] != "bake" and start is not None:
        runs.append((start, i))
        start = None
assert runs, "no frames logged while a bake waited or ran"
edit, last = runs[-1]  # the edit's: held, run, faded in
timed = [i for i in range(edit + 2, min(last + 1, len(rows)))]
assert len(timed) > 20, f"only {len(timed)} frames from the edit to the new light"
worst = max(float(rows[i]["frame_ms"]) for i in timed)
work = max(float(rows[i]["cpu_ms"]) for i in timed)
print(f"bake session: {len(rows)} frames; from the edit to the new light {len(timed)} frames, "
      f"the longest {worst:.1f} ms, the window thread's most work in one {work:.1f} ms CPU "
      f"(the edit's own frame, with its rebuild: {float(rows[edit + 1]['frame_ms']):.1f} ms)")
assert work <= 100.0, f"a frame with {work:.1f} ms of the window thread's work during the bake"
PY
