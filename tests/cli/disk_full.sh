#!/bin/sh
# A write that runs out of space must fail loudly and change nothing: tessera's exit code and
# messages are passed through (the test checks them), then this script checks what is on disk:
# the good file written before is byte-identical and no temporary file is left in the folder.
# A broken expectation exits 99 with the reason.
# usage: disk_full.sh TESSERA FSIZE_LIMIT DIR KIND PROJECT
#   KIND render-EXT: render -o DIR/out.EXT over a good out.EXT, files capped at 4 KiB
#   KIND panorama:   panorama -o DIR/pano.jpg over a good pano.jpg
#   KIND video:      video -o DIR/clip.mp4; frames go to DIR/clip_frames
#   KIND print-pdf:  print -o DIR/plan.pdf over a good plan.pdf
#   KIND print-svg:  print --svg DIR/svg over good SVG pages (the PDF goes elsewhere, uncapped
#                    by being small: only the SVG pages pass the limit)
#   KIND export-glb: export-glb -o DIR/room.glb over a good room.glb
#   KIND quantities-csv: quantities --csv > /dev/full (standard output on a full device: no
#                    file to keep, the exit code and the message are the test; a file-size
#                    limit would also stop the catalog's WAL index, which is not what is tested)
#   KIND bench-csv:  bench --csv DIR/bench.csv over a good bench.csv
#   KIND share:      share -o DIR/share over a good share folder, the limit between the
#                    panorama and its copy in panorama.js: the folder is the old one, byte for
#                    byte, with no file added or removed
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
print-pdf)
    out=$dir/plan.pdf
    "$tessera" print "$project" -o "$out" --renders none --date today >/dev/null 2>&1 || fail "the good print failed"
    cp "$out" "$dir/good" || fail "cannot copy"
    "$limit" $cap "$tessera" print "$project" -o "$out" --renders none --date tomorrow
    rc=$?
    ;;
print-svg)
    out=$dir/svg/page-01.svg
    "$tessera" print "$project" -o "$dir/plan.pdf" --svg "$dir/svg" --renders none --date today >/dev/null 2>&1 || fail "the good print failed"
    cp "$out" "$dir/good" || fail "cannot copy"
    cap=$(($(wc -c < "$dir/plan.pdf") + 1024))
    [ "$(wc -c < "$out")" -gt "$cap" ] || fail "the SVG page is not larger than the PDF: no test"
    "$limit" $cap "$tessera" print "$project" -o "$dir/plan.pdf" --svg "$dir/svg" --renders none --date tomorrow
    rc=$?
    ;;
export-glb)
    out=$dir/room.glb
    "$tessera" export-glb "$project" -o "$out" >/dev/null 2>&1 || fail "the good export failed"
    cp "$out" "$dir/good" || fail "cannot copy"
    "$limit" 1024 "$tessera" export-glb "$project" -o "$out"
    rc=$?
    ;;
quantities-csv)
    out=
    "$tessera" quantities "$project" --csv > /dev/full
    rc=$?
    ;;
bench-csv)
    out=$dir/bench.csv
    "$tessera" bench "$project" --frames 3 --warmup 1 --size 64x48 --csv "$out" >/dev/null 2>&1 || fail "the good bench failed"
    cp "$out" "$dir/good" || fail "cannot copy"
    "$limit" 100 "$tessera" bench "$project" --frames 3 --warmup 1 --size 64x48 --csv "$out"
    rc=$?
    ;;
share)
    out=
    "$tessera" share "$project" -o "$dir/share" --size 64x48 --panorama-size 1024x512 >/dev/null 2>&1 || fail "the good share failed"
    cp -r "$dir/share" "$dir/good-share" || fail "cannot copy"
    # Room for the panorama JPEG but not for its base64 copy in panorama.js (4/3 of it): the
    # share page's own writer meets the full disk.
    cap=$(($(wc -c < "$dir/share/panorama.jpg") + 512))
    # Renders of another size: written before the failure, they differ from the old ones.
    "$limit" $cap "$tessera" share "$project" -o "$dir/share" --size 80x60 --panorama-size 1024x512
    rc=$?
    diff -r "$dir/good-share" "$dir/share" >&2 || fail "the share folder changed: old and new files mixed"
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
