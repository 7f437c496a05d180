#!/bin/sh
# Walk mode with real key events under Xvfb (xdotool sends them to the window): from the
# stored viewpoint "basin" Tab enters walk mode (at eye height, where the view was, facing the
# vanity) and W is held 3 s, straight at the vanity; then from "bath" the same towards the bath.
# No frame's eye may come within the walker's body radius (200 mm, less 1 mm) of the vanity's or
# the bath's footprint (the window logs both with `locate box`), each walk must have moved and
# reached its fixture (an eye within 400 mm of it), and the shots (from where each walk starts,
# facing the washstand and the bath, and where it ends) show the room.
#   usage: walk_session.sh TESSERA OUTDIR SCREENSHOT_CHECK PROJECT
# Exit 77 (skipped) without xdotool (.ci/setup installs it).
set -e
if [ -z "$WALK_SESSION_DISPLAY" ]; then
    command -v xdotool >/dev/null || { echo "SKIP: xdotool is not installed"; exit 77; }
    . "$(dirname "$0")/session_lib.sh"
    session_start "$@"
    cp "$4" "$out/project.json" # a copy: no autosave beside the shipped project
    WALK_SESSION_DISPLAY=1 session_xvfb sh "$0" "$1" "$2" "$3" "$out/project.json"
    exit $?
fi
tessera=$1 out=$2 check=$3 project=$4
log="$out/stderr.txt"

wait_log() {
    i=0
    until [ "$(grep -cE "$1" "$log")" -ge "${2:-1}" ]; do
        kill -0 "$pid" 2>/dev/null || { cat "$log"; echo "FAIL: the window exited early"; exit 1; }
        i=$((i + 1))
        test $i -le 300 || { cat "$log"; echo "FAIL: no \"$1\" in the log within 30 s"; exit 1; }
        sleep 0.1
    done
}

cat >"$out/session.txt" <<SCRIPT
quality draft
locate box vanity
locate box bath
camera basin
wait 5
locate eye
wait-file $out/entered-vanity
wait 3
screenshot $out/vanity-start.png
wait-file $out/walked-vanity
wait 3
locate eye
screenshot $out/vanity.png
mode orbit
camera bath
wait 5
locate eye
wait-file $out/entered-bath
wait 3
screenshot $out/bath-start.png
wait-file $out/walked-bath
wait 3
locate eye
screenshot $out/bath.png
quit
SCRIPT

"$tessera" open "$project" --size 960x540 --script "$out/session.txt" \
    --frame-log "$out/frames.csv" 2>"$log" &
pid=$!

# walk NAME N: Tab into walk mode (the Nth time; the script takes a shot from there), then W
# held 3 s; the script goes back to the orbit. The pointer over the 3D view (at 960 x 540 it
# spans x 250..680, y 53..518) makes it active.
walk() {
    wait_log "waiting for .*/entered-$1"
    xdotool mousemove --window "$win" 465 285
    sleep 0.5
    xdotool key --window "$win" Tab
    wait_log '^tessera: status: Walk mode' "$2"
    touch "$out/entered-$1"
    wait_log "waiting for .*/walked-$1"
    xdotool keydown --window "$win" w
    sleep 3
    xdotool keyup --window "$win" w
    touch "$out/walked-$1"
}
wait_log "waiting for .*/entered-vanity"
win=$(xdotool search --name '^Tessera' | head -1)
test -n "$win" || { cat "$log"; echo "FAIL: no window named Tessera"; exit 1; }
walk vanity 1
walk bath 2

set +e
wait "$pid"
rc=$?
set -e
cat "$log"
test "$rc" -eq 0 || { echo "FAIL: the window exited $rc"; exit 1; }
for shot in vanity-start vanity bath-start bath; do
    test -s "$out/$shot.png" || { echo "FAIL: no screenshot $shot"; exit 1; }
done
"$check" "$out/vanity-start.png" "$out/vanity.png" "$out/bath-start.png" "$out/bath.png"
python3 - "$log" "$out/frames.csv" <<'PY'
import csv, math, re, sys
log = open(sys.argv[1]).read()
boxes = {m[0]: [float(v) for v in m[1:]] for m in re.findall(
    r'locate box "(\w+)" centre (\S+) (\S+) half (\S+) (\S+) angle (\S+) z (\S+) (\S+)', log)}
assert set(boxes) == {"vanity", "bath"}, f"boxes logged: {sorted(boxes)}"
eyes = [tuple(float(v) for v in m) + (mode,) for *m, mode in
        re.findall(r'locate eye at (\S+) (\S+) (\S+) (\w+)', log)]
assert len(eyes) == 4, f"{len(eyes)} eyes logged"

def distance(x, y, box):
    cx, cy, hx, hy, a = box[:5]
    c, s = math.cos(math.radians(a)), math.sin(math.radians(a))
    lx = abs(c * (x - cx) + s * (y - cy)) - hx
    ly = abs(-s * (x - cx) + c * (y - cy)) - hy
    if lx <= 0 and ly <= 0:
        return max(lx, ly)  # inside: negative
    return math.hypot(max(lx, 0), max(ly, 0))

radius = 200 - 1
rows = list(csv.DictReader(open(sys.argv[2])))
walking = [r for r in rows if abs(float(r["eye_z"]) - 1600) < 0.5]
assert len(walking) > 10, f"only {len(walking)} frames at eye height"
for k, name in enumerate(["vanity", "bath"]):
    box = boxes[name]
    start, end = eyes[2 * k], eyes[2 * k + 1]
    moved = math.hypot(end[0] - start[0], end[1] - start[1])
    closest = min(distance(float(r["eye_x"]), float(r["eye_y"]), box) for r in walking)
    print(f"walk session: towards the {name}: moved {moved:.0f} mm, closest eye "
          f"{closest:.1f} mm from its footprint, ended {distance(end[0], end[1], box):.1f} mm")
    assert start[3] == "orbit" and end[3] == "walk" and moved > 300, \
        f"the walk towards the {name} did not move"
    assert closest >= radius, f"the eye came {closest:.1f} mm near the {name} (body radius 200)"
    assert closest < 400, f"the walker never reached the {name} ({closest:.0f} mm)"
PY
echo "walk_session: ok"
