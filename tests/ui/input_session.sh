#!/bin/sh
# Real X input under Xvfb, sent by xdotool through XTEST as a hand would, while every frame is
# slowed to 10 fps or less (TESSERA_FRAME_DELAY_MS=100; INPUT_SESSION_FRAME_DELAY_MS=N for
# another delay, to measure):
# 1. typing into the catalog search with Backspace, Delete, arrows, Home/End, Ctrl+A and
#    Ctrl+C/V gives exactly the string a desktop text field would (read back from the window's
#    log and expect-search); a V typed there is text, and after Enter V switches the view;
# 2. 20 clicks of 30 ms, each shorter than a frame, alternately on two fixtures of the plan:
#    every one selects its fixture;
# 3. the wheel over the left column scrolls it until the selection's "Rotate 90" button, below the fold,
#    is shown whole; the wheel over the plan zooms the plan, not a panel.
# The window tells where to click (locate) and waits for each step (wait-file).
#   usage: input_session.sh TESSERA OUTDIR SCREENSHOT_CHECK PROJECT
# Exit 77 (skipped) without xdotool (.ci/setup installs it).
set -e
if [ -z "$INPUT_SESSION_DISPLAY" ]; then
    command -v xdotool >/dev/null || { echo "SKIP: xdotool is not installed"; exit 77; }
    . "$(dirname "$0")/session_lib.sh"
    session_start "$@"
    # The same script again, inside the X server, with its window and xdotool.
    INPUT_SESSION_DISPLAY=1 session_xvfb sh "$0" "$@"
    exit $?
fi
tessera=$1 out=$2 check=$3 project=$4
log="$out/stderr.txt"

# wait_log PATTERN [N]: until the window's log has N lines (1) matching PATTERN (grep -E), 30 s
# at most.
wait_log() {
    i=0
    until [ "$(grep -cE "$1" "$log")" -ge "${2:-1}" ]; do
        kill -0 "$pid" 2>/dev/null || { cat "$log"; echo "FAIL: the window exited early"; exit 1; }
        i=$((i + 1))
        test $i -le 300 || { cat "$log"; echo "FAIL: no \"$1\" in the log within 30 s"; exit 1; }
        sleep 0.1
    done
}

# where WHAT: the x y the last "locate WHAT" logged.
where() {
    sed -n "s/^tessera: locate $1 at \([0-9-]*\) \([0-9-]*\).*/\1 \2/p" "$log" | tail -n 1
}

# click X Y MS: a left click held MS milliseconds, at X Y.
click() {
    xdotool mousemove "$1" "$2"
    sleep 0.1
    xdotool mousedown 1 sleep "$(echo "$3" | awk '{print $1 / 1000}')" mouseup 1
}

cat >"$out/session.txt" <<SCRIPT
quality draft
view plan
wait 3
locate widget search
wait-file $out/typed
expect-search metro-hallmetro-hall
screenshot $out/typed.png
locate fixture wc
locate fixture bath
wait-file $out/clicked
wait 3
screenshot $out/clicked.png
locate widget Rotate 90
wait-file $out/scrolled
wait 3
locate widget Rotate 90
screenshot $out/scrolled.png
quit
SCRIPT

TESSERA_FRAME_DELAY_MS=${INPUT_SESSION_FRAME_DELAY_MS:-100} "$tessera" open "$project" --size 1024x600 --script "$out/session.txt" \
    2>"$log" &
pid=$!

# 1. Typing. The field gets the keyboard with a click; each line's result is what any
# desktop text field gives. The V typed is text, not the view shortcut.
wait_log "waiting for .*/typed"
# shellcheck disable=SC2046 # "X Y" splits into two arguments on purpose
set -- $(where 'widget "search"')
test $# -eq 2 || { cat "$log"; echo "FAIL: the window did not locate its search field"; exit 1; }
click "$1" "$2" 30
xdotool type --delay 40 "basinv"
xdotool key --delay 40 BackSpace               # basin
xdotool key --delay 40 Left Left BackSpace     # bain
xdotool key --delay 40 End                     #
xdotool type --delay 40 "metro"                # bainmetro
xdotool key --delay 40 ctrl+a                  # all selected
xdotool type --delay 40 "metro-hallx"          # metro-hallx
xdotool key --delay 40 BackSpace Home Delete   # etro-hall
xdotool type --delay 40 "m"                    # metro-hall
wait_log 'catalog search "metro-hall"$'
xdotool key --delay 40 ctrl+a ctrl+c End ctrl+v # metro-hallmetro-hall (the clipboard)
wait_log 'catalog search "metro-hallmetro-hall"$'
sleep 0.5 # nothing more arrives
# Enter lets go of the keyboard: V is the view shortcut again (to the 3D view and back).
xdotool key Return
sleep 0.5
xdotool key v
wait_log '^tessera: view 3D'
xdotool key v
wait_log '^tessera: view plan' 2 # the script's own "view plan" was the first
touch "$out/typed"

# 2. Clicks shorter than a frame, alternately on two fixtures: each one selects.
wait_log "waiting for .*/clicked"
# shellcheck disable=SC2046
set -- $(where 'fixture "wc"') $(where 'fixture "bath"')
test $# -eq 4 || { cat "$log"; echo "FAIL: the plan has no wc and bath"; exit 1; }
n=0
while [ $n -lt 10 ]; do
    click "$1" "$2" 30
    click "$3" "$4" 30
    n=$((n + 1))
done
touch "$out/clicked"

# 3. The wheel: over the View panel it scrolls the panel, over the plan it zooms the plan.
wait_log "waiting for .*/scrolled"
xdotool mousemove 120 150 sleep 0.3 click --repeat 8 --delay 60 5
sleep 0.5
xdotool mousemove 470 240 sleep 0.3 click --repeat 3 --delay 60 4
touch "$out/scrolled"

set +e
wait "$pid"
rc=$?
set -e
cat "$log"
test "$rc" -eq 0 || { echo "FAIL: the window exited $rc"; exit 1; }
for shot in typed clicked scrolled; do
    test -s "$out/$shot.png" || { echo "FAIL: no screenshot $shot"; exit 1; }
done

# Every click selected: 20 clicks, 20 changes of the selection, alternating.
selected=$(grep -cE '^tessera: selected "(wc|bath)"' "$log")
test "$selected" -eq 20 ||
    { echo "FAIL: $selected of 20 clicks shorter than a frame selected a fixture"; exit 1; }
grep '^tessera: selected' "$log" | awk 'NR > 1 && $0 == prev { bad = 1 } { prev = $0 }
    END { exit bad }' || { echo "FAIL: a click did not change the selection"; exit 1; }
# The wheel scrolled the left column: the selection's Rotate 90 button was below the fold, now it shows.
grep -q 'locate widget "Rotate 90" at .* hidden' "$log" ||
    { echo "FAIL: the selection's Rotate 90 was not below the fold to begin with"; exit 1; }
grep 'locate widget "Rotate 90"' "$log" | tail -n 1 | grep -q visible ||
    { echo "FAIL: the wheel did not scroll the left column"; exit 1; }
# Each step changed the picture (the typed search, the selection, the scroll and zoom).
"$check" "$out/typed.png" "$out/clicked.png" "$out/scrolled.png"
echo "input_session: ok"
