#!/bin/sh
# The still view's final and print pictures from the background render (docs/ui.md, "The live
# view"; ui/src/still_render.c) under Xvfb. At final: the view stops, moves again while the
# server is still on its first request (paused, its answer discarded), stops, and the still
# view reaches final from the server; a second stop after an orbit is answered by the same
# server. Then, with the server unable to start (TMPDIR a file), the window refines to final
# in its own strips. Checked: the log lines, the frame log's last frame still at final, the
# shots show the room, and no folder is left in TMPDIR. (Print's step is the same code with a
# second background step: tests/ui/test_live_view.c; its times in docs/benchmarks.md.)
#   usage: still_render_session.sh TESSERA OUTDIR SCREENSHOT_CHECK PROJECT
set -e
. "$(dirname "$0")/session_lib.sh"
session_start "$@"
export TMPDIR="$out/tmp"
mkdir -p "$TMPDIR"
status=0
fail() {
    echo "FAIL: $*"
    status=1
}
cat >"$out/final.txt" <<SCRIPT
quality final
camera door
wait 2
orbit 40 0 frames 4
wait-still
screenshot $out/final.png
orbit 40 0 frames 4
wait-still
screenshot $out/final2.png
quit
SCRIPT
session_window "$4" 800x450 "$out/final.txt" "$out/window.log" --frame-log "$out/frames.csv"
[ "$(grep -c "still view at final: rendered beside the window" "$out/window.log")" -eq 2 ] ||
    fail "not two final stills from the background render (one a stop)"
last=$(tail -n 1 "$out/frames.csv" | cut -d, -f2,9)
[ "$last" = final,still ] || fail "the last frame is not the still view at final ($last)"
"$check" "$out/final.png" "$out/final2.png" || fail "a still shot is blank"
[ -z "$(ls -A "$TMPDIR")" ] || fail "the background render left files in TMPDIR: $(ls "$TMPDIR")"

# The server failing to start: the window climbs in its own strips.
cat >"$out/fallback.txt" <<SCRIPT
quality final
camera door
wait-still
screenshot $out/fallback.png
quit
SCRIPT
: >"$out/not-a-folder"
TMPDIR="$out/not-a-folder" session_window "$4" 800x450 "$out/fallback.txt" "$out/fallback.log" \
    --frame-log "$out/fallback.csv"
grep -q "the window renders it itself" "$out/fallback.log" ||
    fail "no word of the failed background render"
last=$(tail -n 1 "$out/fallback.csv" | cut -d, -f2,9)
[ "$last" = final,still ] || fail "the window did not refine to final itself ($last)"
"$check" "$out/fallback.png" || fail "the fallback's still is blank"
exit $status
