#!/bin/sh
# Writing into a folder the user may not write: every writer exits non-zero with a message that
# names the file (or folder) and the reason, and leaves nothing in the folder; an existing file
# there keeps its bytes. The catalog in such a folder is still searched (read-only).
# Root writes into any folder, so under root the commands run as user 65534 (nobody) through
# setpriv (util-linux), in a folder root owns (mode 0755); any other user runs them itself in
# a folder of mode 0555. A broken expectation exits 99 with the reason; under root, a machine
# without setpriv or that user, or whose build tree that user cannot read, exits 77 (ctest:
# skipped).
# usage: read_only_folder.sh TESSERA DATA DIR
tessera=$1 data=$2 dir=$3
fail() { echo "read_only_folder.sh: $*" >&2; exit 99; }
skip() { echo "read_only_folder.sh: skipped: $*"; exit 77; }
uid=$(id -u)
if [ "$uid" -eq 0 ]; then
    uid=65534
    command -v setpriv >/dev/null 2>&1 || skip "no setpriv (util-linux) to run as an unprivileged user"
    getent passwd $uid >/dev/null 2>&1 || skip "no user $uid"
    run_as() { setpriv --reuid=$uid --regid=$uid --clear-groups "$@"; }
    ro_mode=0755
else
    run_as() { "$@"; }
    ro_mode=0555
fi
[ -d "$dir" ] && chmod -R u+w "$dir" 2>/dev/null
rm -rf "$dir" && mkdir -p "$dir/ro" "$dir/home" || fail "cannot make $dir"
as_user() {
    run_as env HOME="$dir/home" XDG_CACHE_HOME="$dir/home" XDG_STATE_HOME="$dir/home" \
        XDG_CONFIG_HOME="$dir/home" TESSERA_CATALOG="$dir/home/catalog.sqlite" "$@"
}
as_user test -x "$tessera" -a -r "$data/minimal.json" ||
    skip "user $uid cannot run $tessera or read $data (a private build tree)"
# Inputs the user can read: the projects, and a catalog of its own built beforehand.
cp "$data/minimal.json" "$data/edit-room.json" "$data/edit-script.txt" "$dir/home/" ||
    fail "cannot copy the inputs"
TESSERA_CATALOG="$dir/home/catalog.sqlite" "$tessera" catalog info >/dev/null 2>&1 ||
    fail "cannot build the catalog"
cp "$dir/home/catalog.sqlite" "$dir/ro/catalog.sqlite" || fail "cannot copy the catalog"
cp "$data/edit-room.json" "$dir/ro/project.json" && cp "$dir/ro/project.json" "$dir/good.json" ||
    fail "cannot copy the project"
{ [ "$(id -u)" -ne 0 ] || chown -R $uid:$uid "$dir/home"; } && chmod 0644 "$dir/ro/"* &&
    chmod $ro_mode "$dir/ro" ||
    fail "cannot set the owners"
p="$dir/home/minimal.json"

# expect_refused NAME OUT COMMAND...: COMMAND fails naming OUT and the reason.
expect_refused() {
    name=$1 out=$2
    shift 2
    as_user "$@" >"$dir/out.txt" 2>&1
    rc=$?
    cat "$dir/out.txt"
    grep -q 'runtime error\|Sanitizer' "$dir/out.txt" && fail "$name: a sanitizer report"
    [ $rc -ne 0 ] || fail "$name exited 0 writing into a read-only folder"
    [ $rc -lt 128 ] || fail "$name died of a signal ($rc)"
    grep -F "$out" "$dir/out.txt" | grep -q 'Permission denied\|not writable\|Read-only' ||
        fail "$name: no message naming $out and the reason"
    echo "read_only_folder.sh: $name refused, exit $rc"
}
expect_refused render "$dir/ro/x.png" "$tessera" render "$p" --size 32x24 -o "$dir/ro/x.png"
expect_refused print "$dir/ro/x.pdf" "$tessera" print "$p" --renders none -o "$dir/ro/x.pdf"
expect_refused print-svg "$dir/ro/svg" \
    "$tessera" print "$p" --renders none -o "$dir/home/x.pdf" --svg "$dir/ro/svg"
expect_refused quantities-xlsx "$dir/ro/q.xlsx" "$tessera" quantities "$p" --xlsx "$dir/ro/q.xlsx"
expect_refused bench-csv "$dir/ro/b.csv" \
    "$tessera" bench "$p" --frames 2 --warmup 0 --size 32x24 --csv "$dir/ro/b.csv"
expect_refused catalog-export "$dir/ro/c.csv" "$tessera" catalog export -o "$dir/ro/c.csv"
expect_refused export-glb "$dir/ro/x.glb" "$tessera" export-glb "$p" -o "$dir/ro/x.glb"
expect_refused share "$dir/ro/share" \
    "$tessera" share "$p" -o "$dir/ro/share" --size 32x24 --panorama-size 64x32
expect_refused edit "$dir/ro/project.json" \
    "$tessera" edit "$dir/ro/project.json" "$dir/home/edit-script.txt" -o "$dir/ro/project.json"
left=$(ls -A "$dir/ro" | grep -v '^catalog.sqlite$\|^project.json$')
[ -z "$left" ] || fail "left in the read-only folder: $left"
cmp -s "$dir/good.json" "$dir/ro/project.json" || fail "project.json changed"

# The catalog in the read-only folder is searched, read-only.
as_user "$tessera" catalog search basin --db "$dir/ro/catalog.sqlite" >"$dir/out.txt" 2>&1
rc=$?
cat "$dir/out.txt"
[ $rc -eq 0 ] || fail "catalog search in a read-only folder: exit $rc"
grep -q 'EUR' "$dir/out.txt" || fail "catalog search found no product"
grep -q 'opened read-only' "$dir/out.txt" || fail "catalog search does not say it is read-only"
as_user "$tessera" catalog import "$dir/home/edit-room.json" --db "$dir/ro/catalog.sqlite" \
    >"$dir/out.txt" 2>&1
rc=$?
cat "$dir/out.txt"
[ $rc -ne 0 ] && grep -q 'cannot import: the catalog could only be opened read-only' "$dir/out.txt" ||
    fail "an import into the read-only catalog was not refused clearly (exit $rc)"
left=$(ls -A "$dir/ro" | grep -v '^catalog.sqlite$\|^project.json$')
[ -z "$left" ] || fail "left in the read-only folder: $left"
echo "read_only_folder.sh: every writer refused, nothing left behind, the catalog searched"
