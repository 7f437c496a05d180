#!/bin/sh
# The native file dialogs (GTK 3) driven as a person would, with xdotool under Xvfb: the window
# opens "Save project as", a path is typed and Enter pressed, and the project is saved there
# (and is the newest recent file); then "Open project" with Ctrl+L, a path and Enter opens
# another project; then Ctrl+Shift+S pressed in the window opens "Save project as" again.
# Skipped (exit 77) without xdotool.
#   usage: dialog_session.sh TESSERA OUTDIR SCREENSHOT_CHECK PROJECT
set -e
. "$(dirname "$0")/session_lib.sh"
session_start "$@"
command -v xdotool >/dev/null || { echo "SKIP: no xdotool"; exit 77; }
cp "$4" "$out/demo.json"
cp "$4" "$out/other.json"
cat >"$out/dialog.txt" <<SCRIPT
wait 2
dialog save-as
expect-recent $out/saved-by-dialog.json
dialog open
expect-recent $out/other.json
screenshot $out/opened.png
wait 100000
SCRIPT
# answer TITLE KEYS...: waits for the dialog TITLE, focuses it, sends KEYS, types the path
# (the last argument) and presses Enter.
cat >"$out/drive.sh" <<'SH'
#!/bin/sh
out=$1
"$2" open "$out/demo.json" --size 800x500 --script "$out/dialog.txt" 2>"$out/stderr.txt" &
pid=$!
answer() {
    title=$1 keys=$2 path=$3
    for i in $(seq 1 120); do
        wid=$(xdotool search --name "^$title\$" 2>/dev/null | head -1)
        [ -n "$wid" ] && break
        kill -0 $pid 2>/dev/null || return 1
        sleep 0.5
    done
    [ -n "$wid" ] || { echo "no dialog \"$title\""; return 1; }
    sleep 1 # mapped and drawn
    xdotool windowfocus --sync "$wid"
    xdotool key "$keys"
    xdotool type --delay 10 "$path"
    xdotool key Return
}
answer "Save project as" ctrl+a "$out/saved-by-dialog.json" || kill $pid
answer "Open project" ctrl+l "$out/other.json" || kill $pid
# The key: the script is waiting; Ctrl+Shift+S goes to the planner's window.
for i in $(seq 1 120); do
    grep -q "screenshot .*opened.png" "$out/stderr.txt" && break
    sleep 0.5
done
xdotool search --name "^Tessera\$" windowfocus --sync key ctrl+shift+s
answer "Save project as" ctrl+a "$out/saved-by-key.json" || kill $pid
for i in $(seq 1 60); do
    [ -s "$out/saved-by-key.json" ] && break
    sleep 0.5
done
kill $pid # the script waits on: it is stopped once the file is there
wait $pid
[ $? -eq 143 ] # ended by the kill above, not by a failure
SH
chmod +x "$out/drive.sh"
session_xvfb "$out/drive.sh" "$out" "$tessera" || {
    cat "$out/stderr.txt"
    echo "FAIL: the dialog session did not exit 0"
    exit 1
}
cat "$out/stderr.txt"
test -s "$out/saved-by-dialog.json" || { echo "FAIL: the dialog did not save"; exit 1; }
grep -q "opened $out/other.json" "$out/stderr.txt" || { echo "FAIL: the dialog did not open"; exit 1; }
test -s "$out/saved-by-key.json" || { echo "FAIL: Ctrl+Shift+S did not save as"; exit 1; }
session_shots opened
echo "PASS: save as and open through the native dialogs"
