#!/bin/sh
# The Selection panel's probe policy and the panel layout under Xvfb:
# the demo at 800 x 450, a basin placed (the Selection panel shows it), its material's
# probe policy and reflection changed through edit lines (the lines the panel's combos send,
# tests/ui/test_panel_layout.c), undone and redone (expect-probe after each step), saved;
# then the saved material is checked; the same at 1280 x 720. The app must exit 0 and the screenshots must show the room.
#   usage: probe_session.sh TESSERA OUTDIR SCREENSHOT_CHECK DEMO_PROJECT
set -e
. "$(dirname "$0")/session_lib.sh"
session_start "$@"
demo=$4
mat='"Cerana CE411001 BK"'
for size in 800x450 1280x720; do
    cp "$demo" "$out/demo-$size.json" # a copy: no autosave next to the shipped demo
    cat >"$out/probe-$size.txt" <<SCRIPT
wait 1
search basin
select 1
place-selected 1200 300
expect-added 1
expect-probe $mat default
edit probe $mat update time-sliced resolution 128 correction sphere
expect-probe $mat time-sliced
wait 1
screenshot $out/probe-$size.png
undo
expect-probe $mat default
redo
expect-probe $mat time-sliced
edit probe $mat every 4
expect-probe $mat every-frame
undo
expect-probe $mat time-sliced
edit reflect $mat 0.3 gloss 0.7 blend fresnel
wait 1
screenshot $out/reflect-$size.png
save $out/saved-$size.json
quit
SCRIPT
    session_window "$out/demo-$size.json" "$size" "$out/probe-$size.txt" "$out/stderr-$size.txt"
    "$check" "$out/probe-$size.png"
    "$check" "$out/reflect-$size.png"
    # The material's block in the saved file (two tabs of indentation, cJSON's layout).
    block=$(sed -n '/^		"Cerana CE411001 BK":	{/,/^		}/p' "$out/saved-$size.json")
    for want in '"update":	"time-sliced"' '"correction":	"sphere"' '"resolution":	128' \
        '"reflectivity":	0.3' '"glossiness":	0.7'; do
        printf '%s\n' "$block" | grep -q "$want" || {
            echo "FAIL ($size): $want not saved in the basin material:"
            printf '%s\n' "$block"
            exit 1
        }
    done
    # "every 4" was undone: no period stored.
    if printf '%s\n' "$block" | grep -q '"every"'; then
        echo "FAIL ($size): the undone every 4 was saved"
        exit 1
    fi
    "$tessera" check "$out/saved-$size.json" >/dev/null || test $? -le 1
done
echo "probe session: ok"
