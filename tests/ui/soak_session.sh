#!/bin/sh
# The window's soak: the planner on a copy of PROJECT under Xvfb, worked for SOAK_SECONDS
# (default 60) by a seeded monkey of real X events (soak_monkey.sh, xdotool), with every GL
# error counted (TESSERA_GL_CHECK=1). It passes when:
# - the window exits 0 after the script's final save, screenshot and quit (no crash);
# - the window counted 0 GL errors (KHR_debug callback, render/gl_check.h);
# - its log has no sanitizer report (an ASan/UBSan build of tessera may be given);
# - the resident memory (VmRSS, sampled every 2 s into $OUT/rss.csv) grew by less than
#   SOAK_MAX_GROWTH_MB (default 50) from the end of the warm-up (SOAK_WARMUP seconds of the
#   monkey, default 60, or a third of a run shorter than 3 minutes) to the end; the script
#   shows every view and quality once before the monkey starts;
# - the final save and the project the monkey saved with Ctrl+S read back and validate in
#   `tessera check` (exit 0 or 1: design findings such as collisions the monkey made are
#   reported, not failed; exit 2 fails).
# The script holds the window in segments of 10 s (wait-file), between which it logs where the
# catalog search is and, every sixth, takes a screenshot ($OUT/shot-N.png; $OUT/end.png last).
# It writes $OUT/summary.txt: the figures docs/benchmarks.md quotes.
#   usage: soak_session.sh TESSERA OUTDIR SCREENSHOT_CHECK PROJECT
#   environment: SOAK_SECONDS, SOAK_SEED (default 1), SOAK_WARMUP, SOAK_MAX_GROWTH_MB
# Exit 77 (skipped) without xdotool (.ci/setup installs it).
set -e
if [ -z "$SOAK_DISPLAY" ]; then
    command -v xdotool >/dev/null || { echo "SKIP: xdotool is not installed"; exit 77; }
    . "$(dirname "$0")/session_lib.sh"
    session_start "$@"
    SOAK_DISPLAY=1 session_xvfb sh "$0" "$@"
    exit $?
fi
# The window runs in $out: the programs by absolute paths.
absolute() { echo "$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"; }
tessera=$(absolute "$1") out=$(absolute "$2") check=$(absolute "$3") project=$4
here=$(cd "$(dirname "$0")" && pwd)
seconds=${SOAK_SECONDS:-60} seed=${SOAK_SEED:-1}
warm=${SOAK_WARMUP:-$((seconds >= 180 ? 60 : seconds / 3))}
max_growth_mb=${SOAK_MAX_GROWTH_MB:-50}
segment=10
log="$out/stderr.txt"
: >"$out/actions.txt"

cp "$project" "$out/soak.json"
segments=$(((seconds + segment - 1) / segment))
{
    # Every view and quality the monkey reaches, once, before it starts: their first use
    # (the elevation and its tile panel, walking, the interactive preset) belongs to the
    # warm-up, not to the growth.
    echo "quality draft"
    echo "wait 2"
    echo "view elevation"
    echo "wait 10"
    echo "view plan"
    echo "wait 10"
    echo "mode walk"
    echo "view 3d"
    echo "wait 10"
    echo "mode orbit"
    echo "quality interactive"
    echo "wait 10"
    echo "quality draft"
    echo "wait 5"
    i=1
    while [ $i -le $segments ]; do
        echo "locate widget-if-drawn search"
        if [ $((i % 6)) -eq 0 ]; then echo "screenshot $out/shot-$i.png"; fi
        echo "wait-file $out/seg-$i"
        i=$((i + 1))
    done
    echo "quality draft" # the quality it started with: the end's memory is like for like
    echo "wait 30"
    echo "save $out/final.json"
    echo "screenshot $out/end.png"
    echo "quit"
} >"$out/session.txt"
awk -v seed="$seed" 'BEGIN { srand(seed); for (i = 0; i < 400000; i++) print int(rand() * 1000000) }' \
    >"$out/random.txt"

# The window's folder is $out: a print-quality screenshot (F12) the monkey starts lands there.
cd "$out"
TESSERA_GL_CHECK=1 "$tessera" open soak.json --size 1280x720 --script "$out/session.txt" \
    2>"$log" &
pid=$!
soak_start=$(date +%s)

# The resident memory every 2 s while the window runs.
(
    echo "seconds,rss_kb"
    while kill -0 "$pid" 2>/dev/null; do
        rss=$(awk '/^VmRSS:/ { print $2 }' "/proc/$pid/status" 2>/dev/null || true)
        if [ -n "$rss" ]; then echo "$(($(date +%s) - soak_start)),$rss"; fi
        sleep 2
    done
) >"$out/rss.csv" &
sampler=$!

# wait_log PATTERN: until the window's log has a line matching PATTERN (grep -E), 10 minutes
# at most (a loaded machine may take long to empty the input queue).
wait_log() {
    i=0
    until grep -qE "$1" "$log"; do
        kill -0 "$pid" 2>/dev/null || { cat "$log"; echo "FAIL: the window exited early"; exit 1; }
        i=$((i + 1))
        test $i -le 3000 || { cat "$log"; echo "FAIL: no \"$1\" in the log within 10 min"; exit 1; }
        sleep 0.2
    done
}

. "$here/soak_monkey.sh"
exec 3<"$out/random.txt"
actions=0 monkey_t0=0
seg=1
while [ $seg -le $segments ]; do
    wait_log "waiting for $out/seg-$seg\$"
    if [ $seg -eq 1 ]; then monkey_t0=$(($(date +%s) - soak_start)); fi
    until_t=$(($(date +%s) + segment))
    while [ "$(date +%s)" -lt "$until_t" ]; do
        monkey_act
        close_dialogs
        sleep 0.25
    done
    if [ $seg -eq $segments ]; then # the final save and quit find the window at rest
        read_layout
        if [ "$left_w" -eq 0 ]; then xdotool key p; fi
        xdotool key Escape # cancels a job the monkey started (F12)
        close_dialogs
    fi
    touch "$out/seg-$seg"
    seg=$((seg + 1))
done
exec 3<&-

set +e
wait "$pid"
rc=$?
wait "$sampler"
set -e
soak_end=$(($(date +%s) - soak_start))
cat "$log" | grep -v '^tessera: \(script line\|locate\|catalog search\|selected\|selection\|view \)' || true

fail=0
fail() {
    echo "FAIL: $*"
    fail=1
}
test "$rc" -eq 0 || fail "the window exited $rc"
frames=$(sed -n 's/^tessera: gl-check: \([0-9]*\) frames, .*/\1/p' "$log")
gl_errors=$(sed -n 's/^tessera: gl-check: [0-9]* frames, \([0-9]*\) GL errors/\1/p' "$log")
test -n "$gl_errors" || fail "the window did not report its GL error count"
test "${gl_errors:-1}" -eq 0 || fail "$gl_errors GL errors"
# A leak report whose every frame is in "<unknown module>" is a library unloaded before the
# report (Mesa's driver, dlclosed at exit: 240 bytes in 3 allocations on this machine, the same
# in every run); it is noted, not failed. Any other sanitizer report fails.
foreign_leaks=$(awk '/ERROR: LeakSanitizer/ { on = 1 } on && /^ *#[1-9][0-9]* / && !/<unknown module>/ { n++ }
    END { print n + 0 }' "$log")
if grep -qE 'ERROR: AddressSanitizer|runtime error:|SUMMARY: UndefinedBehavior' "$log" ||
    { grep -q 'ERROR: LeakSanitizer' "$log" && [ "$foreign_leaks" -gt 0 ]; }; then
    fail "a sanitizer report in $log"
elif grep -q 'ERROR: LeakSanitizer' "$log"; then
    echo "note: LeakSanitizer reports leaks only in unloaded libraries: $(grep 'SUMMARY: AddressSanitizer' "$log")"
fi

# Memory: the sample at the end of the warm-up against the last one.
rss_warm=$(awk -F, -v t="$((monkey_t0 + warm))" 'NR > 1 && $1 >= t { print $2; exit }' "$out/rss.csv")
rss_end=$(awk -F, 'NR > 1 { v = $2 } END { print v }' "$out/rss.csv")
rss_max=$(awk -F, 'NR > 1 && $2 > m { m = $2 } END { print m + 0 }' "$out/rss.csv")
rss_minute=$(awk -F, -v t="$((monkey_t0 + 60))" 'NR > 1 && $1 >= t { print $2; exit }' "$out/rss.csv")
if [ -z "$rss_warm" ] || [ -z "$rss_end" ]; then
    fail "too few memory samples in $out/rss.csv"
    rss_warm=0 rss_end=0
fi
growth_kb=$((rss_end - rss_warm))
# AddressSanitizer keeps freed memory in quarantine (256 MB by default): its build's memory is
# reported, not judged.
if grep -q __asan_init "$tessera"; then
    echo "note: a sanitizer build: memory growth of $((growth_kb / 1024)) MB not judged"
elif [ "$growth_kb" -ge $((max_growth_mb * 1024)) ]; then
    fail "resident memory grew by $((growth_kb / 1024)) MB after ${warm} s (limit $max_growth_mb MB)"
fi

# The saved projects read back and validate in `tessera check`: exit 2 (unreadable or invalid)
# fails. Exit 1 is accepted: the monkey moves fixtures into each other and into door swings, and
# the window lets a planner do so, showing those findings (errors of the design, not of the
# file); their count goes into the summary.
test -s "$out/final.json" || fail "the final save wrote nothing"
check_file() {
    set +e
    "$tessera" check "$1" >"$2" 2>&1
    check_rc=$?
    set -e
    if [ "$check_rc" -ge 2 ]; then
        cat "$2"
        fail "$1 does not pass tessera check (exit $check_rc)"
    fi
}
check_file "$out/final.json" "$out/check-final.txt"
final_errors=$(grep -c '^error' "$out/check-final.txt" || true)
saves=$(grep -c 'key ctrl+s' "$out/actions.txt" || true)
check_file "$out/soak.json" "$out/check-soak.txt"
test -s "$out/end.png" || fail "no final screenshot"

# The monkey acted on the window: the end differs from the first screenshot the script took
# (the first is taken a minute in; a short run compares the end with nothing).
first_shot=$(ls "$out"/shot-*.png 2>/dev/null | head -n 1)
if [ -n "$first_shot" ]; then "$check" "$first_shot" "$out/end.png" || fail "the screenshots do not differ"; fi
selections=$(grep -c '^tessera: selected' "$log" || true)

# Every screenshot taken with the panels showing (the layout line before it has a left
# column; presenting has none) shows them: the columns their background, each view pane a
# drawing (screenshot_check --panes). The window logs each frame whose panels found an
# off-screen target bound (and binds the window again).
for shot in "$out"/shot-*.png "$out/end.png"; do
    test -s "$shot" || continue
    name=$(basename "$shot")
    layout=$(awk -v s="screenshot $out/$name " '/^tessera: layout/ { l = $0 } index($0, s) { print l; exit }' "$log")
    case "$layout" in *" left "*) ;; *) continue ;; esac
    rects=$(echo "$layout" | awk '{ for (i = 4; i < NF; i += 2) { split($(i + 1), r, ",")
        if (r[3] <= 0 || r[4] <= 0) continue
        if ($i == "left" || $i == "right") printf " panel %s", $(i + 1)
        if ($i == "2d" || $i == "3d") printf " view %s", $(i + 1) } }')
    # shellcheck disable=SC2086 # the rectangles are separate arguments
    "$check" --panes "$shot" $rects >"$out/panes-${name%.png}.txt" 2>&1 ||
        fail "$name does not show the panels and views: $(grep FAIL "$out/panes-${name%.png}.txt" | head -n 1)"
done
stray=$(sed -n 's/^tessera: gui: \([0-9]*\) times a frame found an off-screen target bound/\1/p' "$log")

{
    echo "seed $seed, $seconds s asked, $soak_end s run"
    echo "actions $actions ($(cut -d' ' -f2 "$out/actions.txt" | sort | uniq -c | sort -rn |
        awk '{ printf "%s%s %s", (NR > 1 ? ", " : ""), $2, $1 }'))"
    echo "frames ${frames:-?}"
    echo "gl_errors ${gl_errors:-?}"
    echo "frames whose panels found an off-screen target bound: ${stray:-?}"
    echo "monkey from ${monkey_t0} s; rss_kb ${warm} s into it: $rss_warm; 60 s into it: ${rss_minute:-n/a}; at the end: $rss_end; peak: $rss_max"
    echo "growth_kb after warm-up: $growth_kb"
    echo "ctrl+s presses $saves; selections logged $selections"
    echo "tessera check of the final save: $final_errors design errors ($(grep '^error' "$out/check-final.txt" |
        awk '{ print $2 }' | sort | uniq -c | awk '{ printf "%s%s %s", (NR > 1 ? ", " : ""), $2, $1 }'))"
} >"$out/summary.txt"
cat "$out/summary.txt"
test $fail -eq 0 || exit 1
echo "soak_session: ok"
