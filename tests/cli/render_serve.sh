#!/bin/sh
# tessera render --serve (app/src/cli/cli_render_serve.c), the planner window's still-view
# renderer: a view asked on standard input is rendered as `tessera render --camera` renders the
# same camera (within one 8-bit step: the served view's camera goes through a text line); the
# same view asked again, from the kept probes and shadow maps, is the same picture; a line that
# is no view, or a view with a field of view out of range, is answered "failed" and the server
# goes on; each answer is one line.
#   usage: render_serve.sh TESSERA PROJECT OUTDIR
set -e
tessera=$1 project=$2 out=$3
rm -rf "$out"
mkdir -p "$out"
camera=door
view=$(python3 -c "
import json, sys
c = [c for c in json.load(open(sys.argv[1]))['cameras'] if c['name'] == sys.argv[2]][0]
print(*c['position'], *c['target'], c['fov'])" "$project" "$camera")
cat >"$out/requests.txt" <<REQ
$view final 160 90 $out/served1.png
not a view at all
$view final 160 90 $out/served2.png
0 0 0 1 1 1 400 final 160 90 $out/bad-fov.png
REQ
"$tessera" render "$project" --serve --quality final <"$out/requests.txt" >"$out/answers.txt" \
    2>"$out/server.log"
cat "$out/answers.txt"
"$tessera" render "$project" --camera "$camera" --quality final --size 160x90 -o "$out/once.png"
status=0
fail() {
    echo "FAIL: $*"
    status=1
}
[ "$(wc -l <"$out/answers.txt")" -eq 4 ] || fail "not one answer a request"
[ "$(sed -n 1p "$out/answers.txt")" = "done $out/served1.png" ] || fail "the first view not done"
sed -n 2p "$out/answers.txt" | grep -q "^failed not a view" || fail "a line that is no view was not refused"
[ "$(sed -n 3p "$out/answers.txt")" = "done $out/served2.png" ] || fail "the second view not done"
sed -n 4p "$out/answers.txt" | grep -q "^failed not a view" || fail "a field of view of 400 was not refused"
[ ! -e "$out/bad-fov.png" ] || fail "the refused view wrote a picture"
idiff -fail 0.0040 -failpercent 0 "$out/once.png" "$out/served1.png" ||
    fail "the served view differs from tessera render's"
idiff -fail 0 "$out/served1.png" "$out/served2.png" ||
    fail "the same view asked again gave another picture"
exit $status
