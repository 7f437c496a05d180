#!/bin/sh
# Saving through a symbolic link updates the file the link names and keeps the link a link:
# an edited project saved to link.json (-> real/project.json) and a render to link.png
# (-> real/picture.png). A broken expectation exits 99 with the reason.
# usage: symlink_save.sh TESSERA DATA DIR
tessera=$1 data=$2 dir=$3
export TESSERA_CATALOG="$dir/catalog.sqlite"
fail() { echo "symlink_save.sh: $*" >&2; exit 99; }
rm -rf "$dir" && mkdir -p "$dir/real" || fail "cannot make $dir"
cp "$data/edit-room.json" "$dir/real/project.json" || fail "cannot copy"
ln -s real/project.json "$dir/link.json" && ln -s real/picture.png "$dir/link.png" ||
    fail "cannot make links"
"$tessera" edit "$data/edit-room.json" "$data/edit-script.txt" -o "$dir/link.json" >/dev/null ||
    fail "edit failed"
[ -L "$dir/link.json" ] || fail "link.json is no longer a symbolic link"
cmp -s "$data/edit-room.json" "$dir/real/project.json" && fail "the link's target was not updated"
"$tessera" check "$dir/real/project.json" >/dev/null || fail "the saved target does not check"
"$tessera" render "$data/minimal.json" --size 32x24 -o "$dir/link.png" || fail "render failed"
[ -L "$dir/link.png" ] || fail "link.png is no longer a symbolic link"
[ -s "$dir/real/picture.png" ] || fail "the render did not reach the link's target"
left=$(find "$dir" -name '*.tmp-*')
[ -z "$left" ] || fail "temporary files left behind: $left"
echo "symlink_save.sh: links kept, targets updated"
