#!/bin/sh
# A wooden product placed from the catalog renders with its grain (docs/catalog.md "pattern",
# docs/rendering.md "Wood grain"): `tessera edit` places the oak vanity HW1514 OK from a catalog
# built from the shipped data, the saved project's material says "pattern": "wood", and its
# render shows several times the local variation of the same render with the pattern taken off
# (check_grain.c) inside the vanity's front.
# usage: wood_from_catalog.sh TESSERA CHECK_GRAIN DATA_DIR OUT_DIR
set -u
tessera=$1
check=$2
data=$3
out=$4/wood-from-catalog
rm -rf "$out"
mkdir -p "$out"
export TESSERA_CATALOG="$out/catalog.sqlite"
status=0
fail() {
    echo "FAIL: $*"
    status=1
}
"$tessera" edit "$data/wood-room.json" "$data/wood-place.txt" -o "$out/wood.json" --quiet ||
    fail "placing the vanity"
grep -q -E '"pattern":[[:space:]]*"wood"' "$out/wood.json" || fail "no wood pattern in the saved project"
"$tessera" edit "$out/wood.json" "$data/wood-plain.txt" -o "$out/plain.json" --quiet ||
    fail "taking the pattern off"
for name in wood plain; do
    "$tessera" render "$out/$name.json" -o "$out/$name.png" --camera front --size 480x360 \
        --quality draft >"$out/$name.out" 2>&1 || { cat "$out/$name.out"; fail "render $name"; }
done
# The upper drawer front below its handle (looked at: wood.png, 1.3 mm a pixel there).
"$check" "$out/wood.png" "$out/plain.png" 40 90 440 220 3 || fail "no grain on the vanity"
[ $status -eq 0 ] && echo "wood_from_catalog: PASS"
exit $status
