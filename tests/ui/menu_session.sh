#!/bin/sh
# The window driven by real X events under Xvfb (xdotool), as a user drives it: the pointer
# over the plan and over the 3D view makes each the active pane (the status bar says so), Tab
# switches to walk mode (said too), View > Plan only shows the plan alone, the toolbar's
# side-by-side button brings the 3D view back, a drag of the splitter moves it, File > Quit
# closes the window (exit 0). Each step is checked in the window's stderr: its layout lines
# and status messages. Skipped (77) without xdotool.
#   usage: menu_session.sh TESSERA OUTDIR SCREENSHOT_CHECK DEMO_PROJECT
set -e
if [ "$1" = "--inside" ]; then
    tessera=$2 out=$3
    log=$out/stderr.txt
    "$tessera" open "$out/demo.json" --size 1280x720 2>"$log" &
    pid=$!
    # mark: the log so far; wait_for TEXT WHAT: TEXT appears in the log after the mark within
    # 30 s, else the test fails.
    seen=0
    mark() { seen=$(wc -l <"$log"); }
    wait_for() {
        i=0
        while ! tail -n +$((seen + 1)) "$log" | grep -q -- "$1"; do
            i=$((i + 1))
            if [ $i -gt 60 ] || ! kill -0 $pid 2>/dev/null; then
                cat "$log"
                echo "FAIL: $2 (no \"$1\" on stderr)"
                kill $pid 2>/dev/null || true
                exit 1
            fi
            sleep 0.5
        done
    }
    wait_for "tessera: layout 1280x720 " "the window did not lay itself out"
    # click X Y: as a hand clicks: the pointer there first, the button held a moment.
    click() {
        xdotool mousemove --window "$win" "$1" "$2"
        sleep 0.5
        xdotool mousedown 1
        sleep 0.3
        xdotool mouseup 1
    }
    win=$(xdotool search --name '^Tessera$' | head -1)
    test -n "$win" || { echo "FAIL: no window named Tessera"; kill $pid; exit 1; }
    sleep 1
    # The layout at 1280x720 (panel_layout.c): plan 280..612, splitter 612..618, 3D 618..950.
    mark
    xdotool mousemove --window "$win" 446 375
    wait_for "tessera: status: Plan mode:" "the pointer over the plan did not make it active"
    mark
    xdotool mousemove --window "$win" 784 375
    wait_for "tessera: status: Orbit mode:" "the pointer over the 3D view did not make it active"
    mark
    xdotool key --window "$win" Tab
    wait_for "tessera: status: Walk mode:" "Tab did not switch to walk mode"
    # View > Plan only: the menu's second entry.
    mark
    click 113 9
    sleep 1
    click 150 50
    wait_for " 2d 280,53,670,645 splitter 0,0,0,0 3d 0,0,0,0 " "View > Plan only did not show the plan alone"
    # The toolbar's "Plan and 3D side by side" (the sixth button).
    mark
    click 216 36
    wait_for " 2d 280,53,332,645 splitter 612,53,6,645 3d 618,53,332,645 " \
        "the toolbar did not bring the 3D view back beside the plan"
    # The splitter dragged from its middle to x 700: the plan 700 - 3 - 280 = 417 px wide.
    mark
    # Each position is held for seconds: the window samples the pointer once a frame, and a
    # loaded machine's frames take that long.
    xdotool mousemove --window "$win" 615 375
    sleep 1
    xdotool mousedown 1
    sleep 2
    for x in 640 660 680 700; do
        xdotool mousemove --window "$win" $x 375
        sleep 0.5
    done
    sleep 3
    xdotool mouseup 1
    wait_for " 2d 280,53,417,645 splitter 697,53,6,645 3d 703,53,247,645 " \
        "the splitter did not follow the drag"
    # File > Quit (the last entry, below two separators: nine entries above it).
    click 25 9
    sleep 1
    click 60 194
    i=0
    while kill -0 $pid 2>/dev/null && [ $i -lt 40 ]; do
        i=$((i + 1))
        sleep 0.5
    done
    if kill -0 $pid 2>/dev/null; then
        kill $pid
        echo "FAIL: File > Quit did not close the window"
        exit 1
    fi
    wait $pid || { echo "FAIL: the window exited $?"; exit 1; }
    echo "menu session: ok"
    exit 0
fi
. "$(dirname "$0")/session_lib.sh"
session_start "$@"
command -v xdotool >/dev/null || { echo "SKIP: no xdotool"; exit 77; }
cp "$4" "$out/demo.json" # a copy: no autosave next to the shipped demo
session_xvfb "$0" --inside "$tessera" "$out"
