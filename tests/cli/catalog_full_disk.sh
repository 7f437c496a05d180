#!/bin/sh
# A catalog search on a full disk: a reader of a WAL database makes or grows the -shm index by
# writing, which a full disk refuses; the search then reads the catalog read-only and finds
# what it finds with room to spare. Only a -wal file holding changes not yet in the catalog file
# stops it, with a message naming that file. A full disk is a file size limit of 4 KiB
# (fsize_limit.c). A broken expectation exits 99 with the reason.
# usage: catalog_full_disk.sh TESSERA FSIZE_LIMIT DIR
tessera=$1 limit=$2 dir=$3
fail() { echo "catalog_full_disk.sh: $*" >&2; exit 99; }
rm -rf "$dir" && mkdir -p "$dir" || fail "cannot make $dir"
db=$dir/catalog.sqlite
"$tessera" catalog search basin --db "$db" >"$dir/room.txt" 2>&1 || fail "the search with room failed"
[ ! -e "$db-wal" ] || fail "the catalog's -wal file stayed after its last connection closed"
rm -f "$db-shm"

"$limit" 4096 "$tessera" catalog search basin --db "$db" >"$dir/full.txt" 2>"$dir/full-err.txt"
rc=$?
cat "$dir/full.txt" "$dir/full-err.txt"
[ $rc -eq 0 ] || fail "the search on a full disk: exit $rc"
grep -q 'opened read-only' "$dir/full-err.txt" || fail "the search does not say it read the catalog read-only"
grep 'EUR' "$dir/room.txt" >"$dir/room-rows.txt"
grep 'EUR' "$dir/full.txt" >"$dir/full-rows.txt"
[ -s "$dir/room-rows.txt" ] || fail "the search with room found nothing"
cmp -s "$dir/room-rows.txt" "$dir/full-rows.txt" || fail "the search on a full disk found other products"

# A -wal file with frames in it: the read-only reader cannot read them without -shm.
cp "$db" "$dir/changed.sqlite" && head -c 8192 /dev/urandom >"$dir/changed.sqlite-wal" ||
    fail "cannot make the -wal file"
rm -f "$dir/changed.sqlite-shm"
"$limit" 4096 "$tessera" catalog search basin --db "$dir/changed.sqlite" >"$dir/wal.txt" 2>&1
rc=$?
cat "$dir/wal.txt"
[ $rc -eq 1 ] || fail "the search with an unreadable -wal file: exit $rc, not 1"
grep -q "changed.sqlite-wal holds changes not yet in the catalog file" "$dir/wal.txt" ||
    fail "no message naming the -wal file"
echo "catalog_full_disk.sh: searched on a full disk, refused only an unreadable -wal file"
