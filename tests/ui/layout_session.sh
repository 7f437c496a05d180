#!/bin/sh
# The window's layout under Xvfb at 1024x600, 1280x720 and 2560x1440: plan and 3D side by side,
# the splitter dragged to its limit, each view alone. Every layout the window logs ("tessera: layout ...")
# must have its menu bar, toolbar, columns, panes, splitter and status bar inside the window,
# overlapping nothing and covering it; in every screenshot the columns show the panels and the
# panes show a view with no panel over it (screenshot_check --panes); a change of mode is said
# in the status bar (and logged); each action changes the picture.
#   usage: layout_session.sh TESSERA OUTDIR SCREENSHOT_CHECK DEMO_PROJECT
set -e
. "$(dirname "$0")/session_lib.sh"
session_start "$@"
demo=$4
SESSION_SCREEN=2560x1440x24

# check_layout LINE: the rectangles of one "tessera: layout WxH NAME X,Y,W,H ..." line.
check_layout() {
    printf '%s\n' "$1" | awk '
        function lo(a, b) { return a < b ? a : b }
        function hi(a, b) { return a > b ? a : b }
        {
            split($3, wh, "x"); W = wh[1]; H = wh[2]; n = 0; total = 0; bad = 0
            for (i = 4; i < NF; i += 2) {
                name[n] = $i; split($(i + 1), r, ",")
                x[n] = r[1]; y[n] = r[2]; w[n] = r[3]; h[n] = r[4]; n++
            }
            for (i = 0; i < n; i++) {
                if (w[i] <= 0 || h[i] <= 0) continue
                total += w[i] * h[i]
                if (x[i] < 0 || y[i] < 0 || x[i] + w[i] > W || y[i] + h[i] > H) {
                    print "FAIL: " name[i] " is outside the " W "x" H " window"; bad = 1
                }
                for (k = i + 1; k < n; k++) {
                    if (w[k] <= 0 || h[k] <= 0) continue
                    ox = lo(x[i] + w[i], x[k] + w[k]) - hi(x[i], x[k])
                    oy = lo(y[i] + h[i], y[k] + h[k]) - hi(y[i], y[k])
                    if (ox > 0 && oy > 0) { print "FAIL: " name[i] " overlaps " name[k]; bad = 1 }
                }
            }
            if (total != W * H) { print "FAIL: the parts cover " total " of " W * H " pixels"; bad = 1 }
            exit bad
        }' || { echo "in: $1"; exit 1; }
}

# rect LINE NAME: the rectangle NAME of a layout line ("" when the part is hidden).
rect() {
    printf '%s\n' "$1" | awk -v want="$2" '{
        for (i = 4; i < NF; i += 2) if ($i == want) { split($(i + 1), r, ","); if (r[3] > 0) print $(i + 1) } }'
}

for size in 1024x600 1280x720 2560x1440; do
    cp "$demo" "$out/demo-$size.json" # a copy: no autosave next to the shipped demo
    cat >"$out/layout-$size.txt" <<SCRIPT
wait 3
screenshot $out/$size-both.png
view plan
mode walk
search basin
select 1
place-selected 1200 300
wait 2
screenshot $out/$size-plan-active.png
split 0
wait 2
screenshot $out/$size-split.png
panes one
wait 2
screenshot $out/$size-plan-alone.png
view 3d
wait 2
screenshot $out/$size-3d-alone.png
panes both
view elevation
wait 2
screenshot $out/$size-elevation.png
quit
SCRIPT
    session_window "$out/demo-$size.json" "$size" "$out/layout-$size.txt" "$out/log-$size.txt" \
        >/dev/null
    session_shots "$size-both" "$size-plan-active" "$size-split" "$size-plan-alone" \
        "$size-3d-alone" "$size-elevation"
    # Each screenshot against the layout logged before it.
    layout="" shots=0
    while IFS= read -r line; do
        case "$line" in
        "tessera: layout $size "*)
            check_layout "$line"
            layout=$line
            ;;
        "tessera: screenshot "*)
            test -n "$layout" || { echo "FAIL ($size): a screenshot before any layout line"; exit 1; }
            shot=${line#tessera: screenshot }
            shot=${shot% (*}
            # shellcheck disable=SC2046 # one argument per rectangle
            "$check" --panes "$shot" panel $(rect "$layout" left) $(rect "$layout" right) \
                view $(rect "$layout" 2d) $(rect "$layout" 3d)
            shots=$((shots + 1))
            ;;
        esac
    done <"$out/log-$size.txt"
    test "$shots" -eq 6 || { echo "FAIL ($size): $shots screenshots checked, not 6"; exit 1; }
    # Side by side first (both panes), then each view alone.
    grep "tessera: layout $size " "$out/log-$size.txt" >"$out/layouts-$size.txt"
    head -1 "$out/layouts-$size.txt" | grep -q ' splitter [0-9]*,[0-9]*,6,' || {
        echo "FAIL ($size): plan and 3D are not side by side at first"
        exit 1
    }
    grep -q ' 2d [0-9,]* splitter 0,0,0,0 3d 0,0,0,0 ' "$out/layouts-$size.txt" || {
        echo "FAIL ($size): the plan never showed alone"
        exit 1
    }
    grep -q ' 2d 0,0,0,0 splitter 0,0,0,0 3d [1-9]' "$out/layouts-$size.txt" || {
        echo "FAIL ($size): the 3D view never showed alone"
        exit 1
    }
    # The splitter dragged to the window's left edge stops where the plan keeps its least width
    # (UI_LAYOUT_MIN_PANE_W); tests/ui/test_panel_layout.c checks that it follows a drag.
    grep -q " 2d [0-9]*,[0-9]*,240,[0-9]* splitter " "$out/layouts-$size.txt" || {
        echo "FAIL ($size): the splitter did not follow the drag to the plan's least width"
        exit 1
    }
    # Mode changes are said in the status bar.
    for said in "Plan mode:" "Walk mode in the 3D view:" "Walk mode:" "Elevation mode:"; do
        grep -q "tessera: status: $said" "$out/log-$size.txt" || {
            echo "FAIL ($size): the status bar never said \"$said\""
            exit 1
        }
    done
    "$check" "$out/$size-both.png" "$out/$size-plan-active.png" "$out/$size-split.png" \
        "$out/$size-plan-alone.png" "$out/$size-3d-alone.png" "$out/$size-elevation.png"
done
echo "layout session: ok"
