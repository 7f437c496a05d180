#!/bin/sh
# The moving frame's programs made beside a still frame's (render/src/draw.c: a still frame
# that compiles a lit variant anew, in a context that has drawn moving frames, builds the
# variant's fixed-light program too and draws one scissored-out triangle with it), under Xvfb
# on the demo bathroom with every GL error counted (TESSERA_GL_CHECK=1): moving frames, then the
# baked light arrives (its variants are compiled anew by the still view's strips, and primed),
# moving frames again, a still view again. Checked: no GL error (a priming draw whose program
# had samplers of two types on one unit failed with GL_INVALID_OPERATION: with the units left
# at 0 this session fails so, on the demo bathroom's baked light), and the shots show the room.
#   usage: priming_session.sh TESSERA OUTDIR SCREENSHOT_CHECK PROJECT
set -e
. "$(dirname "$0")/session_lib.sh"
session_start "$@"
export TESSERA_BAKE=on XDG_CACHE_HOME="$out/cache"
cat >"$out/priming.txt" <<SCRIPT
quality interactive
camera door
orbit 30 0 frames 6
wait-bake
wait-still
orbit 90 -10 frames 12
screenshot $out/moved.png
wait-still
screenshot $out/still.png
quit
SCRIPT
TESSERA_GL_CHECK=1 session_window "$4" 800x450 "$out/priming.txt" "$out/window.log"
status=0
grep -q "gl-check: counting GL errors (KHR_debug callback)" "$out/window.log" ||
    { echo "FAIL: GL errors were not counted by the debug callback"; status=1; }
grep -q "gl-check: [0-9]* frames, 0 GL errors" "$out/window.log" ||
    { echo "FAIL: GL errors: $(grep 'gl-check:' "$out/window.log" | tail -n 1)"; status=1; }
"$check" "$out/moved.png" || status=1 # the still view differs in sharpness only: each alone
"$check" "$out/still.png" || status=1
exit $status
