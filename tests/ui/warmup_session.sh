#!/bin/sh
# The shader warm-up under Xvfb (docs/ui.md, "Shader warm-up"), from a cold Mesa shader cache:
# the window draws the document's moving frame at interactive, then renders it at interactive,
# final and print, every object drawn in view or not, in background processes once its scene
# is up, the window's own (moving, interactive) in a hidden window's kind of context
# (--backend window: Mesa's cache entries of an EGL context do not serve a window's). Checked:
# the four stages report compiled; the renders filled the session's Mesa cache (the folder the
# window reads); their copy of the document is gone afterwards; after an orbit the still view
# reaches final (the climb goes on once the warm-up is done); `--backend window` renders what
# EGL renders, within one 8-bit step, and without a display is refused with the reason.
#   usage: warmup_session.sh TESSERA OUTDIR SCREENSHOT_CHECK PROJECT
set -e
. "$(dirname "$0")/session_lib.sh"
session_start "$@"
export XDG_CACHE_HOME="$out/cache" TMPDIR="$out/tmp" TESSERA_SHADER_WARMUP=on
mkdir -p "$TMPDIR"
cat >"$out/warmup.txt" <<SCRIPT
quality final
camera door
wait-warmup
wait 10
orbit 30 0 frames 5
wait 600
screenshot $out/final.png
quit
SCRIPT
session_window "$4" 640x400 "$out/warmup.txt" "$out/window.log" --frame-log "$out/frames.csv"
status=0
fail() {
    echo "FAIL: $*"
    status=1
}
for stage in moving interactive final print; do
    grep -q "shader warm-up: $stage compiled" "$out/window.log" ||
        fail "no '$stage compiled' line from the warm-up"
done
[ -n "$(ls -A "$XDG_CACHE_HOME/mesa_shader_cache" 2>/dev/null)" ] ||
    fail "the Mesa shader cache in $XDG_CACHE_HOME is empty"
[ -z "$(ls -A "$TMPDIR")" ] || fail "the warm-up left files in TMPDIR: $(ls "$TMPDIR")"
# The last frame is the still view at its preset: the climb went on after the warm-up.
last=$(tail -n 1 "$out/frames.csv" | cut -d, -f9)
[ "$last" = still ] || fail "the still view did not reach final (last frame: $last)"
"$check" "$out/final.png" || fail "the final view is blank"
session_xvfb "$tessera" render "$4" --backend window --quality interactive --size 160x90 \
    -o "$out/window.png" 2>"$out/backend.log" || fail "--backend window: $(cat "$out/backend.log")"
"$tessera" render "$4" --backend egl --quality interactive --size 160x90 -o "$out/egl.png" \
    2>>"$out/backend.log" || fail "--backend egl: $(cat "$out/backend.log")"
oiiotool "$out/window.png" "$out/egl.png" --diff --fail 0.004 --failpercent 0 >"$out/diff.txt" ||
    fail "--backend window differs from egl: $(cat "$out/diff.txt")"
if DISPLAY= WAYLAND_DISPLAY= "$tessera" render "$4" --backend window --size 32x18 \
    -o "$out/none.png" 2>"$out/nodisplay.log"; then
    fail "--backend window rendered without a display"
fi
grep -q "backend window: no display" "$out/nodisplay.log" ||
    fail "no reason given without a display: $(cat "$out/nodisplay.log")"
exit $status
