#!/bin/sh
# The catalog's drag and drop, the live quantities panel and the file panel under Xvfb:
# search "basin", drag the first hit into the plan and let go, check the object
# count and that the quantities panel's total is plausible, save as, start a new project (an
# empty room), open the saved file again (its objects are back), drop a vanity unit whose
# catalog row names companions (it comes with its basin, mixer and mirror: 4 objects, one
# undo step), and exit 0. A second run opens
# a broken file: it must fail, with a message that names the file and the problem.
#   usage: session_catalog.sh TESSERA OUTDIR SCREENSHOT_CHECK SOURCE_DIR
set -e
. "$(dirname "$0")/session_lib.sh"
session_start "$@"
src=$4
# A copy: the session edits it, and an autosave must not land beside the shipped demo.
cp "$src/assets/projects/designed-bathroom.json" "$out/demo.json"
cat >"$out/session.txt" <<SCRIPT
wait 2
search basin
expect-hits 5
select 1
view plan
wait 8
screenshot $out/browser.png
drag-selected plan 420 330 frames 6
wait 1
screenshot $out/dragging.png
drop-selected plan 420 330
expect-added 1
expect-objects 21
wait 1
screenshot $out/dropped.png
expect-total 5000 20000
save-as $out/saved.json
new
expect-objects 0
expect-total 0 5000
wait 1
screenshot $out/new.png
open $out/saved.json
expect-objects 21
expect-total 5000 20000
view 3d
camera door
search hand basin
select 2
wait 2
drop-selected 3d 640 500
expect-objects 22
undo
expect-objects 21
search CE419501
select 1
wait 2
drop-selected 3d 640 500
expect-objects 25
wait 1
screenshot $out/companions.png
undo
expect-objects 21
wait 1
screenshot $out/reopened.png
quit
SCRIPT
session_window "$out/demo.json" 1280x720 "$out/session.txt" "$out/stderr.txt"
session_shots browser dragging dropped new companions reopened
# Each screenshot shows a room or a plan, and each step changed the picture.
"$check" "$out/browser.png" "$out/dragging.png" "$out/dropped.png" "$out/new.png" \
    "$out/reopened.png"
# The drop went through the place command and was saved; the saved file passes the checks'
# reader.
grep -q 'place "Cerana"' "$out/stderr.txt" || { echo "FAIL: no place edit"; exit 1; }
grep -q 'place "Cerana" "CE419501" .* with-companions$' "$out/stderr.txt" ||
    { echo "FAIL: the vanity was not dropped with its companions"; exit 1; }
grep -q '"CE41' "$out/saved.json" || { echo "FAIL: the dropped basin was not saved"; exit 1; }
# It landed at its mounting height (docs/editing.md "Mounting heights"), not on the floor: its
# name is its article (the demo's own basin is named "basin").
article=$(sed -n 's/.*place "Cerana" "\(CE4[0-9]*\)".*/\1/p' "$out/stderr.txt" | head -1)
z=$(awk -v name="$article" 'index($0, "\"name\":\t\"" name "\"") { found = 1 }
    found && /"position":/ { sub(/.*\[/, ""); sub(/\].*/, ""); split($0, v, ", "); print v[3]; exit }' \
    "$out/saved.json")
echo "dropped $article at z = $z mm"
awk -v z="$z" 'BEGIN { exit !(z + 0 >= 500) }' ||
    { echo "FAIL: the dropped basin $article is at z = '$z' mm, not at its mounting height"; exit 1; }
set +e
"$tessera" check "$out/saved.json" >/dev/null
rc=$?
set -e
test "$rc" -le 1 || { echo "FAIL: tessera check exit $rc"; exit 1; }

# A broken file: the script fails at the open, the message names the file and the problem.
printf '{ "version": 2, "name": ' >"$out/broken.json"
printf 'wait 1\nopen %s\nquit\n' "$out/broken.json" >"$out/broken.txt"
set +e
session_xvfb "$tessera" open --size 640x360 --script "$out/broken.txt" 2>"$out/broken-stderr.txt"
rc=$?
set -e
cat "$out/broken-stderr.txt"
# (xvfb-run may add its own exit code when it cleans up: the script's failure is in the log.)
test "$rc" -ne 0 || { echo "FAIL: opening a broken file exited 0"; exit 1; }
grep -q "script line 2: cannot open" "$out/broken-stderr.txt" ||
    { echo "FAIL: the script did not fail at the open"; exit 1; }
grep "cannot open" "$out/broken-stderr.txt" | grep -q "broken.json" ||
    { echo "FAIL: the message does not name the broken file"; exit 1; }
grep "cannot open" "$out/broken-stderr.txt" | grep -q "the document is unchanged" ||
    { echo "FAIL: the message does not say the document stays"; exit 1; }
echo "session_catalog: ok"
