# The monkey of the window's soak (sourced by soak_session.sh, inside the X server): random but
# seeded actions sent as real X events with xdotool, as a hand sends them: clicks and drags in
# the plan and the 3D view, the wheel, shortcut keys, undo and redo, saves (Ctrl+S), text typed
# into the catalog search, products dragged from the catalog into a view, tile changes in the
# elevation's tile panel, clicks and drags in the panel columns, the menus and the toolbar.
# The seed fixes the sequence of choices (positions, keys, words); how many of them fit in the
# time depends on the machine. Each action is one line of $out/actions.txt.
#
# Needs: $log (the window's stderr), $out, $random (one integer 0..999999 a line, from the
# seed) open on descriptor 3. Reads where things are from the window's log: its last layout
# line (window_panes.c) and its last "locate widget search" (the session's script).

# R: the next random integer; pick N: R in 0..N-1.
pick() {
    read -r R <&3 || R=0
    R=$((R % $1))
}

# Where the window's panes and columns are now (names: menu toolbar left p2 splitter p3 right
# status); a hidden one, or all but p3 while presenting, has width 0.
read_layout() {
    for n in menu toolbar left p2 splitter p3 right status; do
        eval "${n}_x=0 ${n}_y=0 ${n}_w=0 ${n}_h=0"
    done
    eval "$(grep '^tessera: layout' "$log" | tail -n 1 | awk '{
        for (i = 4; i < NF; i += 2) {
            n = $i; if (n == "2d") n = "p2"; if (n == "3d") n = "p3"
            split($(i + 1), r, ",")
            printf "%s_x=%d %s_y=%d %s_w=%d %s_h=%d\n", n, r[1], n, r[2], n, r[3], n, r[4]
        }}')"
    search_x=0 search_y=0
    line=$(grep '^tessera: locate widget "search" ' "$log" | tail -n 1)
    case "$line" in
    *visible*) set -- $line
        search_x=$6 search_y=$7 ;;
    esac
}

# point NAME: PX PY a random point inside rectangle NAME, 8 px from its edges.
point() {
    eval "x=\$${1}_x y=\$${1}_y w=\$${1}_w h=\$${1}_h"
    pick $((w > 16 ? w - 16 : 1))
    PX=$((x + 8 + R))
    pick $((h > 16 ? h - 16 : 1))
    PY=$((y + 8 + R))
}

# pane: PANE a shown view pane (p2 or p3), chosen at random when both show.
pane() {
    pick 2
    if [ "$p2_w" -gt 0 ] && { [ "$R" -eq 0 ] || [ "$p3_w" -eq 0 ]; }; then PANE=p2; else PANE=p3; fi
}

note() {
    actions=$((actions + 1))
    echo "$(($(date +%s) - soak_start)) $*" >>"$out/actions.txt"
}

# drag BUTTON NAME: a drag with BUTTON from one random point of NAME to another, in 3 steps.
drag() {
    point "$2"
    set -- "$1" "$2" "$PX" "$PY"
    point "$2"
    mx=$((($3 + PX) / 2)) my=$((($4 + PY) / 2))
    xdotool mousemove "$3" "$4" sleep 0.1 mousedown "$1" sleep 0.15 mousemove "$mx" "$my" \
        sleep 0.15 mousemove "$PX" "$PY" sleep 0.15 mouseup "$1"
    note "drag $1 $2 $3,$4 -> $PX,$PY"
}

click_in() {
    point "$1"
    xdotool mousemove "$PX" "$PY" sleep 0.05 click 1
    note "click $1 $PX,$PY"
}

# The qualities are draft and interactive (1, 2): final and print are for stills, and their
# probes and shadow maps are a step of some 170 MB in the working set that would hide a leak.
act_key() {
    set -- v Tab 1 2 F1 F2 F3 F4 F5 Delete r t p Escape Return w a s d
    pick $#
    shift "$R"
    case "$1" in
    w | a | s | d) xdotool keydown "$1" sleep 0.4 keyup "$1" ;; # walking holds the key
    *) xdotool key "$1" ;;
    esac
    note "key $1"
}

act_undo() {
    set -- ctrl+z ctrl+z ctrl+y ctrl+shift+z
    pick $#
    shift "$R"
    pick 3
    n=$((R + 1))
    xdotool key --repeat "$n" --delay 80 "$1"
    note "key $1 x$n"
}

act_search() {
    set -- basin tile wc mirror tap metro shower white 300 zzzq Kensington "wall hung" ö
    pick $#
    shift "$R"
    xdotool mousemove "$search_x" "$search_y" sleep 0.05 click 1 sleep 0.1 key ctrl+a \
        type --delay 30 "$1"
    pick 2
    if [ "$R" -eq 0 ]; then xdotool key Return; fi
    note "search \"$1\""
}

# A product dragged from one of the catalog's first six rows into a view (its drop places it).
act_drop() {
    pick 200
    sx=$((search_x - 90 + R))
    pick 6
    sy=$((search_y + 104 + R * 44))
    pane
    point "$PANE"
    xdotool mousemove "$sx" "$sy" sleep 0.1 mousedown 1 sleep 0.2 mousemove $((sx - 40)) "$sy" \
        sleep 0.2 mousemove "$PX" "$PY" sleep 0.3 mouseup 1
    note "drop $sx,$sy -> $PANE $PX,$PY"
}

# The elevation of the tile panel's wall (View menu), the right column scrolled down to its
# Tiles section (below the catalog), then clicks and drags there (surface, pattern, rotation,
# grout, start, border) and a click on the elevation (the start of the grid).
act_tile() {
    xdotool mousemove 113 9 sleep 0.1 click 1 sleep 0.4 mousemove 180 84 sleep 0.1 click 1
    note "menu View > Elevation"
    pick 8
    xdotool sleep 0.3 mousemove $((right_x + right_w / 2)) $((right_y + right_h * 3 / 4)) \
        sleep 0.1 click --repeat $((R + 1)) --delay 60 5
    pick 4
    n=$((R + 2))
    while [ "$n" -gt 0 ]; do
        pick $((right_w > 40 ? right_w - 40 : 1))
        tx=$((right_x + 10 + R))
        pick $((right_h / 2))
        ty=$((right_y + right_h / 2 - 10 + R))
        pick 3
        if [ "$R" -eq 0 ]; then
            pick 120
            xdotool mousemove "$tx" "$ty" sleep 0.05 mousedown 1 sleep 0.15 \
                mousemove $((tx + R - 60)) "$ty" sleep 0.15 mouseup 1
            note "tile panel drag $tx,$ty"
        else
            xdotool mousemove "$tx" "$ty" sleep 0.05 click 1
            note "tile panel click $tx,$ty"
        fi
        sleep 0.2
        n=$((n - 1))
    done
    if [ "$p2_w" -gt 0 ]; then click_in p2; fi
}

act_column() {
    pick 2
    if [ "$R" -eq 0 ]; then col=left; else col=right; fi
    pick 4
    if [ "$R" -eq 0 ]; then drag 1 "$col"; else click_in "$col"; fi
}

# A menu of the bar, then one of its items or Escape (items are 17 px apart from y = 33). File
# is left out (its Quit would end the soak), and Render (its final and print qualities, see
# act_key, and its jobs, which run in other processes).
act_menu() {
    set -- 69 113 165 273
    pick $#
    shift "$R"
    mx=$1
    pick 12
    my=$((33 + R * 17))
    pick 5
    if [ "$R" -eq 0 ]; then
        xdotool mousemove "$mx" 9 sleep 0.05 click 1 sleep 0.4 key Escape
        note "menu $mx then Escape"
    else
        xdotool mousemove "$mx" 9 sleep 0.05 click 1 sleep 0.4 mousemove $((mx + 60)) "$my" \
            sleep 0.1 click 1
        note "menu $mx item at $my"
    fi
}

# Toolbar buttons from Save to Present (New and Open are the Project panel's business).
act_toolbar() {
    set -- 84 134 167 216 250 284 318 367 401 451
    pick $#
    shift "$R"
    xdotool mousemove "$1" 36 sleep 0.05 click 1
    note "toolbar $1"
}

# A native file dialog the monkey opened (Open..., Print PDF..., Share folder...) is answered
# with Escape, as a hand that clicked by mistake does.
close_dialogs() {
    for wid in $(xdotool search --onlyvisible --name \
        '^(Open project|Save project as|Export as GLB|Print to PDF|Render at print quality|Share folder|Save the video)$' \
        2>/dev/null); do
        xdotool windowfocus --sync "$wid" key Escape 2>/dev/null || true
        note "dialog $wid closed with Escape"
        sleep 0.3
    done
}

# monkey_act: one random action on the window as it is laid out now.
monkey_act() {
    read_layout
    if [ "$left_w" -eq 0 ]; then # presenting: the panels are hidden; P brings them back
        pick 3
        if [ "$R" -eq 0 ] && [ "$p3_w" -gt 0 ]; then drag 1 p3; else
            xdotool key p
            note "key p (presenting)"
        fi
        return
    fi
    if [ "$p2_w" -eq 0 ] || [ "$p3_w" -eq 0 ]; then # one pane: now and then both again
        pick 4
        if [ "$R" -eq 0 ]; then
            xdotool mousemove 216 36 sleep 0.05 click 1
            note "toolbar 216 (both panes)"
            return
        fi
    fi
    pick 100
    k=$R
    if [ "$k" -ge 61 ] && [ "$k" -lt 77 ] && [ "$search_x" -eq 0 ]; then
        # The catalog search is not showing (the tile action scrolled the column down to its
        # Tiles): the column back up, for the next segment's locate.
        xdotool mousemove $((right_x + right_w / 2)) $((right_y + 100)) sleep 0.1 \
            click --repeat 10 --delay 40 4
        note "wheel 4 x10 right (the catalog search hidden)"
        return
    fi
    pane
    if [ "$k" -lt 8 ]; then
        click_in "$PANE"
    elif [ "$k" -lt 18 ]; then
        drag 1 "$PANE"
    elif [ "$k" -lt 21 ]; then
        drag 3 "$PANE" # the right button pans the plan and the elevation
    elif [ "$k" -lt 27 ]; then
        point "$PANE"
        pick 2
        b=$((R + 4))
        pick 3
        xdotool mousemove "$PX" "$PY" sleep 0.1 click --repeat $((R + 1)) --delay 60 "$b"
        note "wheel $b x$((R + 1)) $PANE $PX,$PY"
    elif [ "$k" -lt 37 ]; then
        if [ "$p3_w" -gt 0 ]; then drag 1 p3; else drag 1 "$PANE"; fi
    elif [ "$k" -lt 49 ]; then
        act_key
    elif [ "$k" -lt 57 ]; then
        act_undo
    elif [ "$k" -lt 61 ]; then
        xdotool key ctrl+s
        note "key ctrl+s"
    elif [ "$k" -lt 67 ]; then
        act_search
    elif [ "$k" -lt 77 ]; then
        act_drop
    elif [ "$k" -lt 84 ]; then
        act_tile
    elif [ "$k" -lt 95 ]; then
        act_column
    elif [ "$k" -lt 98 ]; then
        act_menu
    else
        act_toolbar
    fi
}
