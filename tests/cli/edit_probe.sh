#!/bin/sh
# tessera edit with the `probe` word (docs/editing.md): a material's probe
# policy set, a step undone, the result saved and read back by `tessera check`; a bad value is
# named with its line and nothing is saved (exit 2).
# usage: edit_probe.sh TESSERA DATA_DIR OUT_DIR
set -u
tessera=$1
data=$2
out=$3/edit-probe
rm -rf "$out"
mkdir -p "$out"
status=0
fail() {
    echo "FAIL: $*"
    status=1
}
cat >"$out/probe.txt" <<'SCRIPT'
reflect default 0.5 gloss 0.9
probe default update time-sliced resolution 256 correction sphere
probe default every 8
undo
SCRIPT
"$tessera" edit "$data/edit-room.json" "$out/probe.txt" -o "$out/edited.json" >"$out/edit.out" 2>&1
rc=$?
cat "$out/edit.out"
[ $rc -eq 0 ] || fail "edit exit code $rc"
grep -q 'set the probe of "default"' "$out/edit.out" || fail "the probe command was not echoed"
grep -q -E '"update":[[:space:]]*"time-sliced"' "$out/edited.json" || fail "update not saved"
grep -q -E '"correction":[[:space:]]*"sphere"' "$out/edited.json" || fail "correction not saved"
grep -q -E '"resolution":[[:space:]]*256' "$out/edited.json" || fail "resolution not saved"
grep -q -E '"every"' "$out/edited.json" && fail "the undone every 8 was saved"
"$tessera" check "$out/edited.json" >"$out/check.out" 2>&1 || fail "check cannot read the result"

printf 'probe default update once\nprobe default resolution 100\n' >"$out/bad.txt"
"$tessera" edit "$data/edit-room.json" "$out/bad.txt" -o "$out/bad.json" >"$out/bad.out" 2>&1
rc=$?
cat "$out/bad.out"
[ $rc -eq 2 ] || fail "a bad value: exit code $rc, expected 2"
grep -q 'bad.txt:2: probe: resolution is auto or a power of two' "$out/bad.out" ||
    fail "the bad line is not named"
[ -e "$out/bad.json" ] && fail "something was saved after a bad line"
[ $status -eq 0 ] && echo "edit_probe: ok"
exit $status
