#!/bin/sh
# tessera print on a flat: each room's part list and quotation carries its consumables and
# labour (and the trims billed by the metre), as the room's own print does, and --xlsx writes
# the flat's one quotation.
# usage: flat_print_quotation.sh TESSERA FLAT OUT_DIR ROOM:ARTICLE...
set -u
tessera=$1 flat=$2 out=$3
shift 3
status=0
fail() { echo "FAIL: $*"; status=1; }
rm -rf "$out" && mkdir -p "$out" || exit 1
"$tessera" print "$flat" -o "$out/flat.pdf" --renders none --date 2026-12-04 \
    --xlsx "$out/flat.xlsx" || fail "tessera print exit $?"
[ -s "$out/flat.xlsx" ] || fail "no spreadsheet written"
pages=$(pdfinfo "$out/flat.pdf" | awk '/^Pages:/ {print $2}')
# The text of each room's part-list pages (their title block starts with the room's name).
for page in $(seq 1 "${pages:-0}"); do
    pdftotext -layout -f "$page" -l "$page" "$out/flat.pdf" "$out/page.txt"
    room=$(grep -E 'Part list and quotation' "$out/page.txt" | awk '{print $1}' | head -n 1)
    [ -n "$room" ] && cat "$out/page.txt" >>"$out/partlist-$room.txt"
done
for want in "$@"; do
    room=${want%%:*} text=${want#*:}
    grep -q -F -- "$text" "$out/partlist-$room.txt" 2>/dev/null ||
        fail "the part list of room $room lacks \"$text\""
done
[ $status -eq 0 ] && echo "flat_print_quotation: PASS: $# texts in $pages pages"
exit $status
