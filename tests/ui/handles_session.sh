#!/bin/sh
# Snap guides, distance labels and the 3D handles under Xvfb, driven by real X events
# (xdotool), the window telling where to press (locate) and waiting for each step (wait-file):
# 1. the vanity dragged in the plan 1000 mm along its wall towards the corner and held: the
#    guides and labels show (magenta pixels in the plan), the window logs the labels, the
#    right side is 0 from the corner wall and the left label is the distance the saved vanity
#    has to wall 0; after the release they are gone; undone;
# 2. in the 3D view the picked vanity shows its arrows and ring; its along-the-wall arrow
#    dragged 500 mm and held shows the guides and labels there too; let go, it has moved (and
#    its group) 500 mm in the saved project;
# 3. moved by an edit 500 mm out from its wall (at its walls a turn would reach through one,
#    which the window refuses), its ring dragged 52 degrees round turns it by 45 (whole
#    15-degree steps), group and all.
#   usage: handles_session.sh TESSERA OUTDIR SCREENSHOT_CHECK PROJECT
# Exit 77 (skipped) without xdotool (.ci/setup installs it).
set -e
if [ -z "$HANDLES_SESSION_DISPLAY" ]; then
    command -v xdotool >/dev/null || { echo "SKIP: xdotool is not installed"; exit 77; }
    . "$(dirname "$0")/session_lib.sh"
    session_start "$@"
    HANDLES_SESSION_DISPLAY=1 session_xvfb sh "$0" "$@"
    exit $?
fi
tessera=$1 out=$2 check=$3 project=$4
log="$out/stderr.txt"
cp "$project" "$out/demo.json" # a copy: no autosave beside the shipped demo

# wait_log PATTERN: until the window's log has a line matching PATTERN (grep -E), 60 s at most.
wait_log() {
    i=0
    until grep -qE "$1" "$log"; do
        kill -0 "$pid" 2>/dev/null || { cat "$log"; echo "FAIL: the window exited early"; exit 1; }
        i=$((i + 1))
        test $i -le 600 || { cat "$log"; echo "FAIL: no \"$1\" in the log within 60 s"; exit 1; }
        sleep 0.1
    done
}

# drag X0 Y0 X1 Y1 [hold]: press at X0 Y0, move to X1 Y1 in 12 steps, let go unless hold.
drag() {
    xdotool mousemove "$1" "$2"
    sleep 0.3
    xdotool mousedown 1
    sleep 0.3
    for i in 1 2 3 4 5 6 7 8 9 10 11 12; do
        xdotool mousemove "$(($1 + ($3 - $1) * i / 12))" "$(($2 + ($4 - $2) * i / 12))"
        sleep 0.1
    done
    sleep 0.5
    test -n "$5" || xdotool mouseup 1
}

cat >"$out/session.txt" <<SCRIPT
quality draft
panes one
view plan
wait 3
screenshot $out/plan-before.png
locate fixture vanity
locate plan 0 0
locate plan 1000 1000
wait-file $out/held
screenshot $out/plan-held.png
wait-file $out/released
wait 3
screenshot $out/plan-released.png
save $out/plan.json
undo
save $out/undone.json
view 3d
camera basin
pick -
wait 3
screenshot $out/unpicked.png
pick vanity
wait 3
screenshot $out/handles.png
locate handle move-x
wait-file $out/moving
screenshot $out/moving.png
wait-file $out/moved
wait 3
screenshot $out/moved.png
save $out/moved.json
edit move "vanity" 2100 1850 160
wait 3
locate handle rotate
wait-file $out/turning
screenshot $out/turning.png
wait-file $out/turned
wait 3
screenshot $out/turned.png
save $out/turned.json
quit
SCRIPT

"$tessera" open "$out/demo.json" --size 1024x600 --script "$out/session.txt" 2>"$log" &
pid=$!

# 1. The plan drag, held while the window takes its picture.
wait_log "waiting for .*/held"
# shellcheck disable=SC2046 # "X Y" splits on purpose
set -- $(sed -n 's/^tessera: locate fixture "vanity" at \([0-9-]*\) \([0-9-]*\)$/\1 \2/p' "$log") \
    $(sed -n 's/^tessera: locate plan 0 0 at \([0-9-]*\) \([0-9-]*\)$/\1 \2/p' "$log") \
    $(sed -n 's/^tessera: locate plan 1000 1000 at \([0-9-]*\) \([0-9-]*\)$/\1 \2/p' "$log")
test $# -eq 6 || { cat "$log"; echo "FAIL: the window did not locate the vanity and the plan"; exit 1; }
# 50 mm off the wall (-x) and 1000 mm along it (+y) in plan pixels.
tx=$(($1 - ($5 - $3) * 50 / 1000)) ty=$(($2 + ($6 - $4)))
drag "$1" "$2" "$tx" "$ty" hold
touch "$out/held"
wait_log "waiting for .*/released"
xdotool mouseup 1
touch "$out/released"

# 2. The along-the-wall arrow, 500 mm.
wait_log "^tessera: locate handle move-x at"
# shellcheck disable=SC2046
set -- $(sed -n 's/^tessera: locate handle move-x at \([0-9-]*\) \([0-9-]*\) to \([0-9-]*\) \([0-9-]*\)$/\1 \2 \3 \4/p' "$log")
test $# -eq 4 || { cat "$log"; echo "FAIL: no move-x handle located"; exit 1; }
wait_log "waiting for .*/moving"
drag "$1" "$2" "$3" "$4" hold
touch "$out/moving"
wait_log "waiting for .*/moved"
xdotool mouseup 1
touch "$out/moved"

# 3. The ring, 52 degrees round, held for a picture of the turning ghost, then let go.
wait_log "^tessera: locate handle rotate at"
# shellcheck disable=SC2046
set -- $(sed -n 's/^tessera: locate handle rotate at \([0-9-]*\) \([0-9-]*\) to \([0-9-]*\) \([0-9-]*\)$/\1 \2 \3 \4/p' "$log")
test $# -eq 4 || { cat "$log"; echo "FAIL: no rotate handle located"; exit 1; }
wait_log "waiting for .*/turning"
drag "$1" "$2" "$3" "$4" hold
touch "$out/turning"
wait_log "waiting for .*/turned"
xdotool mouseup 1
touch "$out/turned"

set +e
wait "$pid"
rc=$?
set -e
cat "$log"
test "$rc" -eq 0 || { echo "FAIL: the window exited $rc"; exit 1; }
for shot in plan-before plan-held plan-released unpicked handles moving moved turning turned; do
    test -s "$out/$shot.png" || { echo "FAIL: no screenshot $shot"; exit 1; }
done

# The guides' and labels' magenta (plan_draw.h UI_PLAN_GUIDE_COLOUR) in the plan only while
# the drag is held.
guides() { "$check" --count d6008c 12 0,0,1024,600 "$out/$1.png"; }
before=$(guides plan-before) held=$(guides plan-held) released=$(guides plan-released)
echo "guide pixels: before $before, held $held, released $released"
test "$held" -ge 150 || { echo "FAIL: no guides or labels while dragging ($held pixels)"; exit 1; }
if [ "$before" -gt 10 ] || [ "$released" -gt 10 ]; then
    echo "FAIL: guide colour without a drag ($before, $released)"
    exit 1
fi
# The same guides and labels at the fixture's foot in the 3D view while the arrow is held.
moving=$(guides moving) moved=$(guides moved)
echo "3D guide pixels: held $moving, released $moved"
test "$moving" -ge $((moved + 100)) || { echo "FAIL: no guides in the 3D view while dragging"; exit 1; }
# The handles' red arrow and blue ring only once the vanity is picked.
arrows() { "$check" --count dc3c3c 12 0,0,1024,600 "$out/$1.png"; }
ring() { "$check" --count 288cdc 12 0,0,1024,600 "$out/$1.png"; }
echo "arrow pixels: unpicked $(arrows unpicked), picked $(arrows handles);" \
    "ring pixels: unpicked $(ring unpicked), picked $(ring handles)"
test "$(arrows handles)" -ge $(($(arrows unpicked) + 50)) || { echo "FAIL: no move arrows"; exit 1; }
test "$(ring handles)" -ge $(($(ring unpicked) + 100)) || { echo "FAIL: no rotation ring"; exit 1; }

grep -q '^tessera: snap "vanity" wall 1 corner;' "$log" ||
    { echo "FAIL: the drag never showed the corner snap"; exit 1; }
labels=$(grep '^tessera: snap "vanity"' "$log" | tail -n 1)
python3 - "$out" "$labels" <<'PY'
import json, re, sys
out, labels = sys.argv[1], sys.argv[2]
m = re.search(r'wall (\d+) corner; left (\d+) right (\d+) front (\d+); box (\d+) x (\d+)', labels)
assert m, f"last labels not a corner snap: {labels}"
wall, left, right, front, width, depth = map(int, m.groups())
def obj(name, file):
    return [o for o in json.load(open(f"{out}/{file}.json"))["objects"] if o["name"] == name][0]
v = obj("vanity", "plan")
# Released where the guides said: on wall 1 (x 2600), its right side on wall 2 (y 3200), and
# the left label is its box's distance from wall 0 (y 0).
assert wall == 1 and right == 0, labels
assert abs(v["position"][0] - 2600) < 0.5, v
assert abs(v["position"][1] + width / 2 - 3200) <= 1, (v, width)
assert abs(left - (v["position"][1] - width / 2)) <= 1, (labels, v)
assert 0 < front <= 2600 - depth, labels
assert obj("vanity", "undone")["position"] == [2600, 1850, 160], "the plan drag was not undone"
# The 3D arrow: 500 mm along the wall (the vanity and its basin moved together), still on
# the wall; the ring: turned 45 degrees, a whole 15-degree step.
start, moved = obj("vanity", "undone")["position"], obj("vanity", "moved")["position"]
assert abs(moved[0] - 2600) < 0.5, moved
assert abs(abs(moved[1] - start[1]) - 500) <= 20, (start, moved)
basin0, basin1 = obj("basin", "undone")["position"], obj("basin", "moved")["position"]
assert abs((basin1[1] - basin0[1]) - (moved[1] - start[1])) < 0.5, (basin0, basin1)
r0, r1 = obj("vanity", "moved")["rotation"][2], obj("vanity", "turned")["rotation"][2]
turn = (r1 - r0) % 360
assert turn == 45, f"turned by {turn} degrees ({r0} -> {r1}), expected 45"
assert (obj("basin", "turned")["rotation"][2] - r1) % 360 == 0, "the basin did not turn with it"
print(f"handles_session: plan labels {labels.split(': ', 1)[1]}; vanity saved at {start}, "
      f"arrow-moved to {moved}, turned {r0} -> {r1}")
PY
echo "handles_session: ok"
