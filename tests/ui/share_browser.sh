#!/bin/sh
# The share export in a browser: `tessera share` writes a folder; headless Chromium
# (Debian's chromium) opens its index.html from the file system with every network request
# refused, the panorama viewer reports it is ready, and the screenshot shows a page with
# pictures, not a blank one.  usage: share_browser.sh TESSERA PROJECT OUTDIR SCREENSHOT_CHECK
set -e
tessera=$1
project=$2
out=$3
check=$4
rm -rf "$out"
"$tessera" share "$project" -o "$out" --size 320x180 --panorama-size 512x256
for f in index.html panorama.js pano-viewer.js print.pdf; do
    test -s "$out/$f" || { echo "FAIL: $out/$f missing"; exit 1; }
done
# Self-contained: nothing on the page is fetched from anywhere.
if grep -n -E '(src|href)="(https?:)?//' "$out/index.html"; then
    echo "FAIL: the page refers to the network"
    exit 1
fi
browser=$(command -v chromium || command -v chromium-browser || true)
test -n "$browser" || { echo "FAIL: chromium is not installed (.ci/setup installs it)"; exit 1; }
offline="--headless --no-sandbox --disable-gpu --enable-unsafe-swiftshader \
--proxy-server=127.0.0.1:9 --host-resolver-rules=MAP_*_~NOTFOUND --virtual-time-budget=8000"
offline=$(echo "$offline" | sed 's/MAP_\*_~NOTFOUND/"MAP * ~NOTFOUND"/')
dom=$(eval timeout 120 "$browser" $offline --dump-dom "file://$(realpath "$out")/index.html" 2>/dev/null)
echo "$dom" | grep -q 'data-pano="ready"' || { echo "FAIL: the panorama viewer did not start"; \
    echo "$dom" | grep -o 'pano-status">[^<]*'; exit 1; }
eval timeout 120 "$browser" $offline --window-size=1024,700 \
    --screenshot="$(realpath "$out")/browser.png" "file://$(realpath "$out")/index.html" 2>/dev/null
"$check" "$out/browser.png"
