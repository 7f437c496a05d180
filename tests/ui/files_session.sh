#!/bin/sh
# Files and jobs of the planner window under Xvfb (docs/ui.md "Files" and "Jobs"):
# 1. an edit autosaves into $XDG_STATE_HOME/tessera/autosave, nothing beside the project; the
#    project is a recent file; opening it again offers the recovery, which brings the edit
#    back; saving leaves only the project in its folder (its replaced version goes to the state
#    folder) and removes the autosave;
# 2. a print job writes a valid PDF while the window keeps drawing (the frame log has frames
#    marked "job"), the result goes to the opener ($TESSERA_OPENER); a cancelled print leaves
#    no file, partial or whole.
#   usage: files_session.sh TESSERA OUTDIR SCREENSHOT_CHECK PROJECT
set -e
. "$(dirname "$0")/session_lib.sh"
session_start "$@"
mkdir -p "$out/project"
cp "$4" "$out/project/demo.json"
project=$out/project/demo.json
fail() {
    echo "FAIL: $*"
    exit 1
}

cat >"$out/edit.txt" <<SCRIPT
wait 2
expect-recent $project
edit remove "roll-holder"
expect-objects 19
autosave-now
quit
SCRIPT
session_window "$project" 800x500 "$out/edit.txt" "$out/edit-stderr.txt"
autosave=$(ls "$XDG_STATE_HOME"/tessera/autosave/demo-*.json) || fail "no autosave in the state folder"
grep -q roll-holder "$autosave" && fail "the autosave does not hold the edit"
ls "$out/project"
[ "$(ls -A "$out/project")" = demo.json ] || fail "files beside the project: $(ls -A "$out/project")"
grep -qx "$(realpath "$project")" "$XDG_STATE_HOME/tessera/recent-files" ||
    fail "the project is not in the recent files"

cat >"$out/recover.txt" <<SCRIPT
wait 2
expect-recovery yes
screenshot $out/recovery.png
recover yes
expect-objects 19
save -
expect-recovery no
quit
SCRIPT
session_window "$project" 800x500 "$out/recover.txt" "$out/recover-stderr.txt"
session_shots recovery
"$check" "$out/recovery.png"
grep -q roll-holder "$project" && fail "the recovered edit was not saved"
[ "$(ls -A "$out/project")" = demo.json ] || fail "files beside the project: $(ls -A "$out/project")"
ls "$XDG_STATE_HOME"/tessera/autosave/demo-*.json 2>/dev/null && fail "the autosave outlived the save"
ls "$XDG_STATE_HOME"/tessera/previous/demo-*.json >/dev/null || fail "no replaced version kept"

# The opener stand-in notes what it was asked to open.
cat >"$out/opener.sh" <<SH
#!/bin/sh
echo "\$1" >>"$out/opened.txt"
SH
chmod +x "$out/opener.sh"
cat >"$out/print.txt" <<SCRIPT
wait 2
print-pdf $out/print.pdf
wait 20
screenshot $out/job.png
job-wait
print-pdf $out/cancel.pdf
wait 10
job-cancel
wait 2
screenshot $out/cancelled.png
quit
SCRIPT
TESSERA_OPENER=$out/opener.sh session_window "$project" 800x500 "$out/print.txt" \
    "$out/print-stderr.txt" --frame-log "$out/frames.csv"
session_shots job cancelled
"$check" "$out/job.png"
pdfinfo "$out/print.pdf" | grep -q '^Pages: *[1-9]' || fail "print.pdf is not a valid PDF"
job_frames=$(grep -c ',job,' "$out/frames.csv") || true
[ "$job_frames" -ge 20 ] || fail "only $job_frames frames while the jobs ran"
awk -F, '$3 == "job" && $4 > max { max = $4 } END { printf "longest frame during the jobs: %.0f ms over %d frames\n", max, NR }' "$out/frames.csv"
grep -q 'Print to PDF: .*print.pdf done in' "$out/print-stderr.txt" || fail "no done message"
grep -q 'Print to PDF: cancelled' "$out/print-stderr.txt" || fail "the cancel was not reported"
# The opener runs in the background: 10 s at most for its note.
i=0
until grep -qx "$out/print.pdf" "$out/opened.txt" 2>/dev/null || [ $i -ge 100 ]; do
    sleep 0.1
    i=$((i + 1))
done
grep -qx "$out/print.pdf" "$out/opened.txt" || fail "the PDF was not opened"
[ ! -e "$out/cancel.pdf" ] || fail "the cancelled print left cancel.pdf"
ls -A "$out" | grep -q partial && fail "a partial file was left: $(ls -A "$out" | grep partial)"
echo "PASS: autosave, recovery, recent files, print job and cancel"
