#!/bin/sh
# A project open in another window (docs/ui.md "Files"): the lock file beside it is held by a
# stand-in owner (flock(1) on ".demo.json.lock" with a live pid in it), so the window opens the
# project read-only: saving over it is refused, the status bar says READ-ONLY, and Save As to
# another file works and makes that window the owner of the new file. Then the owner dies: its
# lock file stays behind, stale, and the next window takes it over and saves. Every lock file is
# gone after its window closes.
#   usage: lock_session.sh TESSERA OUTDIR SCREENSHOT_CHECK PROJECT
set -e
. "$(dirname "$0")/session_lib.sh"
session_start "$@"
mkdir -p "$out/project"
cp "$4" "$out/project/demo.json"
cp "$4" "$out/original.json"
project=$out/project/demo.json
lock=$out/project/.demo.json.lock
fail() {
    echo "FAIL: $*"
    exit 1
}

# The stand-in owner: one process (the shell becomes sleep, keeping its pid and fd 9) that holds
# the flock and has written its pid and host as project_lock.c does, until it is killed.
sh -c 'exec 9<>"$1"; flock 9; echo "$$ $(hostname) 0" >"$1"; exec sleep 300' owner "$lock" \
    >/dev/null 2>&1 &
owner=$!
for _ in 1 2 3 4 5 6 7 8 9 10; do
    [ -s "$lock" ] && break
    sleep 0.2
done

cat >"$out/second.txt" <<SCRIPT
wait 2
expect-read-only yes
screenshot $out/read-only.png
edit remove "roll-holder"
expect-save-refused
save $out/project/copy.json
expect-read-only no
quit
SCRIPT
session_window "$project" 800x500 "$out/second.txt" "$out/second-stderr.txt"
session_shots read-only
"$check" "$out/read-only.png"
grep -q "is open in another window (pid $owner on $(hostname))" "$out/second-stderr.txt" ||
    fail "the window did not name the owner"
cmp -s "$project" "$out/original.json" || fail "the read-only window changed the project"
grep -q roll-holder "$out/project/copy.json" && fail "save as did not keep the edit"
[ -e "$out/project/.copy.json.lock" ] && fail "the save-as file's lock outlived the window"

kill "$owner"
wait "$owner" 2>/dev/null || true
[ -s "$lock" ] || fail "the dead owner's lock file is gone (nothing stale to take over)"

cat >"$out/third.txt" <<SCRIPT
wait 2
expect-read-only no
edit remove "roll-holder"
save -
quit
SCRIPT
session_window "$project" 800x500 "$out/third.txt" "$out/third-stderr.txt"
grep -q "took over the stale lock of .*pid $owner on $(hostname) is gone" "$out/third-stderr.txt" ||
    fail "the stale lock was not reported as taken over"
grep -q roll-holder "$project" && fail "the window that took over did not save"
[ -e "$lock" ] && fail "the lock file outlived its window"
echo "lock session: ok"
