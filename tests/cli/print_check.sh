#!/bin/sh
# tessera print on a tiled project: the PDF has the plan, the elevations, the render pages of
# a folder of PNG files (two a page) and the part list (pdfinfo), its text holds the article numbers, the
# headings and the total (pdftotext), and --svg writes one file per page.
# usage: print_check.sh TESSERA PROJECT RENDERS_DIR OUT_DIR ARTICLE...
set -u
tessera=$1 project=$2 renders=$3 out=$4
shift 4
status=0
fail() { echo "FAIL: $*"; status=1; }
rm -rf "$out" && mkdir -p "$out" || exit 1
"$tessera" print "$project" -o "$out/plan.pdf" --paper A3 --landscape --scale 1:20 \
    --svg "$out/svg" --renders none --customer "Test Customer" --date 2026-11-22 ||
    fail "tessera print exit $?"
pages=$(pdfinfo "$out/plan.pdf" | awk '/^Pages:/ {print $2}')
echo "pages: $pages"
# Plan, five elevations (on A3 two a page when both fit at 1:20), the part list.
[ "${pages:-0}" -ge 5 ] || fail "expected at least 5 pages, got ${pages:-none}"
svgs=$(ls "$out/svg" | grep -c '^page-[0-9]*\.svg$')
[ "$svgs" = "$pages" ] || fail "$svgs SVG pages for $pages PDF pages"
pdftotext "$out/plan.pdf" "$out/plan.txt" || fail "pdftotext"
for want in "$@" "Floor plan" "Elevation wall 1" "Part list and quotation" "Quotation" \
    "Tile part list" "1:20" "Test Customer" "2026-11-22" "$pages of $pages" "Total EUR"; do
    grep -q -F -- "$want" "$out/plan.txt" || fail "the PDF's text lacks \"$want\""
done
# Every page has content beyond its frame: the last part-list sheet too (a page count made
# before drawing must match what is drawn).
last=$(pdftotext -f "$pages" -l "$pages" "$out/plan.pdf" - | grep -c -E 'TZ6|FA-|CE4')
[ "$last" -gt 0 ] || fail "page $pages is empty"
# A folder of renders: two a page, in name order, each captioned "View: NAME".
pngs=$(ls "$renders"/*.png | wc -l)
"$tessera" print "$project" -o "$out/with-renders.pdf" --renders "$renders" ||
    fail "tessera print --renders exit $?"
with=$(pdfinfo "$out/with-renders.pdf" | awk '/^Pages:/ {print $2}')
echo "pages with $pngs renders: $with"
# Paper and scale differ (A4 fit), so the part list may take other pages: compare the
# render pages by their captions.
views=$(pdftotext "$out/with-renders.pdf" - | grep -o "View: " | wc -l)
[ "$views" = "$pngs" ] || fail "$views render captions for $pngs PNG files"
titles=$(pdftotext "$out/with-renders.pdf" - | grep -c "^Views: ")
[ "$titles" = "$(((pngs + 1) / 2))" ] || fail "$titles render pages for $pngs PNG files"
exit $status
