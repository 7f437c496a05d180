#!/bin/sh
# A write that runs out of space must fail loudly and change nothing: tessera's exit code and
# messages are passed through (the test checks them), then this script checks what is on disk:
# the good file written before is byte-identical and no temporary file is left in the folder.
# A broken expectation exits 99 with the reason.
# usage: disk_full.sh TESSERA FSIZE_LIMIT DIR KIND PROJECT
#   KIND render-EXT: render -o DIR/out.EXT over a good out.EXT, files capped at 4 KiB
#   KIND panorama:   panorama -o DIR/pano.jpg over a good pano.jpg
#   KIND video:      video -o DIR/clip.mp4; frames go to DIR/clip_frames
tessera=$1 limit=$2 dir=$3 kind=$4 project=$5
fail() { echo "disk_full.sh: $*" >&2; exit 99; }
rm -rf "$dir" && mkdir -p "$dir" || fail "cannot make $dir"
cap=4096
case $kind in
render-*)
    out=$dir/out.${kind#render-}
    "$tessera" render "$project" --size 32x24 -o "$out" >/dev/null 2>&1 || fail "the good render failed"
    cp "$out" "$dir/good" || fail "cannot copy"
    "$limit" $cap "$tessera" render "$project" --size 320x240 -o "$out"
    rc=$?
    ;;
panorama)
    out=$dir/pano.jpg
    "$tessera" panorama "$project" --size 64x32 -o "$out" >/dev/null 2>&1 || fail "the good panorama failed"
    cp "$out" "$dir/good" || fail "cannot copy"
    "$limit" $cap "$tessera" panorama "$project" --size 512x256 -o "$out"
    rc=$?
    ;;
video)
    out=
    "$limit" $cap "$tessera" video "$project" --size 320x240 --seconds 0.2 --fps 10 -o "$dir/clip.mp4"
    rc=$?
    [ ! -e "$dir/clip.mp4" ] || fail "a video was made from failed frames"
    ;;
*) fail "unknown kind $kind" ;;
esac
[ "$rc" -ne 0 ] || fail "exit code 0 on a write past the size limit"
if [ -n "$out" ]; then
    cmp -s "$dir/good" "$out" || fail "$out changed: the good file was replaced"
fi
left=$(find "$dir" -name '*.tmp-*' -o -name '*.xmp-*')
[ -z "$left" ] || fail "temporary files left behind: $left"
exit $rc
