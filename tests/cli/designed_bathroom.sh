#!/bin/sh
# The designed bathroom (assets/projects/designed-bathroom*, docs/project-format.md "The demo
# bathroom"), with a catalog built from the shipped data:
#   replay  - the edit script applied to the base file gives exactly the committed
#             designed-bathroom.json, so the script and the project cannot drift apart;
#   check   - `tessera check` on it: exit 0 and no error finding;
#   group_move - moving the vanity by an edit script moves the basin, mixer, mirror and lamp
#             mounted on it by the same offset, and `tessera check` stays clean;
#   basin_alone - moving the basin alone off the vanity into the room is a floating-basin
#             error in `tessera check` (exit 1);
#   quantities - `tessera quantities` on it: exit 0, the field tiles, the border row and the
#             floor tiles in the part list, the products in the bill of materials.
# usage: designed_bathroom.sh TESSERA PROJECTS_DIR OUT_DIR replay|check|group_move|basin_alone|quantities
set -u
tessera=$1
projects=$2
what=$4
out=$3/designed-bathroom-$what
rm -rf "$out"
mkdir -p "$out"
export TESSERA_CATALOG="$out/catalog.sqlite"
status=0
fail() {
    echo "FAIL: $*"
    status=1
}
# The position line of object NAME in project FILE: "[x, y, z]".
position_of() {
    awk -v name="$1" 'index($0, "\"name\":\t\"" name "\"") { found = 1 }
        found && /"position":/ { sub(/.*"position":[ \t]*/, ""); sub(/,$/, ""); print; exit }' "$2"
}

case "$what" in
replay)
    "$tessera" edit "$projects/designed-bathroom-base.json" "$projects/designed-bathroom.edit" \
        -o "$out/replayed.json" --quiet >"$out/edit.out" 2>&1
    rc=$?
    cat "$out/edit.out"
    [ $rc -eq 0 ] || fail "edit exit code $rc"
    if ! cmp -s "$out/replayed.json" "$projects/designed-bathroom.json"; then
        diff "$out/replayed.json" "$projects/designed-bathroom.json" | head -40
        fail "the replayed script differs from assets/projects/designed-bathroom.json;" \
            "regenerate it with: tessera edit designed-bathroom-base.json designed-bathroom.edit" \
            "-o designed-bathroom.json"
    fi
    ;;
check)
    "$tessera" check "$projects/designed-bathroom.json" >"$out/check.out" 2>&1
    rc=$?
    cat "$out/check.out"
    [ $rc -eq 0 ] || fail "check exit code $rc (expected 0)"
    grep -q "fixtures checked; .* 0 errors" "$out/check.out" || fail "check summary"
    if grep -q -E '^ *error' "$out/check.out"; then
        fail "an error finding"
    fi
    ;;
group_move)
    printf 'move vanity 2600 1750 160\n' >"$out/move.edit"
    "$tessera" edit "$projects/designed-bathroom.json" "$out/move.edit" -o "$out/moved.json" \
        >"$out/edit.out" 2>&1 || fail "edit exit code $?"
    cat "$out/edit.out"
    for pair in "vanity [2600, 1750, 160]" "basin [2600, 1750, 680]" \
        "basin-mixer [2550, 1750, 850]" "mirror [2600, 1750, 1150]" \
        "mirror-lamp [2600, 1750, 1880]"; do
        name=${pair%% *}
        want=${pair#* }
        got=$(position_of "$name" "$out/moved.json")
        [ "$got" = "$want" ] || fail "$name at $got, expected $want"
    done
    "$tessera" check "$out/moved.json" >"$out/check.out" 2>&1
    rc=$?
    cat "$out/check.out"
    [ $rc -eq 0 ] || fail "check exit code $rc (expected 0)"
    grep -q "fixtures checked; .* 0 errors" "$out/check.out" || fail "check summary"
    ;;
basin_alone)
    printf 'move basin 1300 1500 680\n' >"$out/move.edit"
    "$tessera" edit "$projects/designed-bathroom.json" "$out/move.edit" -o "$out/moved.json" \
        >"$out/edit.out" 2>&1 || fail "edit exit code $?"
    cat "$out/edit.out"
    [ "$(position_of vanity "$out/moved.json")" = "[2600, 1850, 160]" ] || fail "the vanity moved"
    [ "$(position_of basin-mixer "$out/moved.json")" = "[1250, 1500, 850]" ] ||
        fail "the mixer did not follow its basin"
    "$tessera" check "$out/moved.json" >"$out/check.out" 2>&1
    rc=$?
    cat "$out/check.out"
    [ $rc -eq 1 ] || fail "check exit code $rc (expected 1)"
    grep -q -E 'error +floating .*"basin" floats' "$out/check.out" || fail "no floating-basin error"
    ;;
quantities)
    "$tessera" quantities "$projects/designed-bathroom.json" >"$out/qty.out" 2>&1
    rc=$?
    cat "$out/qty.out"
    [ $rc -eq 0 ] || fail "quantities exit code $rc (expected 0)"
    grep -q -E '^UNI +Fliesenwerk Altena +FA-10110 ' "$out/qty.out" || fail "no wall field tile"
    grep -q -E '^BOR +Fliesenwerk Altena +FA-10132 ' "$out/qty.out" || fail "no border row"
    grep -q -E '^UNI +Terrazza Ceramiche +TZ61009 ' "$out/qty.out" || fail "no floor tile"
    for article in CE415701 CE410401 NK-51258.00 VX20013 31060000 CX7107-0 LU-322.10; do
        # a numbered position: "  5 Cerana   CE415701 ..."
        grep -q -E "^ *[0-9]+ [A-Za-z ]+ +$article " "$out/qty.out" || fail "$article not in the bill"
    done
    grep -q -E '^Total net [0-9.]+ EUR' "$out/qty.out" || fail "no bill total"
    ;;
*)
    fail "unknown test \"$what\""
    ;;
esac
if grep -q -E 'AddressSanitizer|runtime error:|LeakSanitizer' "$out"/*.out; then
    fail "sanitizer report"
fi
exit $status
