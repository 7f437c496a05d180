#!/bin/sh
# Renders a flat's room by its camera, and the same room written out as a single-room project
# (the room's keys with the flat's shared ones), and compares the images (check_image_file.c):
# the camera's room is what the render shows, and the other rooms add nothing.
# usage: flat_render_room.sh TESSERA CHECK_IMAGE_FILE FLAT ROOM CAMERA OUT_PREFIX
set -e
tessera=$1 check=$2 flat=$3 room=$4 camera=$5 out=$6
rm -f "$out-flat.png" "$out-room.png" "$out-room.json"
python3 - "$flat" "$room" "$out-room.json" <<'PY'
import json, sys
flat = json.load(open(sys.argv[1]))
room = next(r for r in flat["rooms"] if r["name"] == sys.argv[2])
single = {k: v for k, v in flat.items() if k != "rooms"}
single.update({k: v for k, v in room.items() if k != "offset"})
json.dump(single, open(sys.argv[3], "w"), indent=1)
PY
"$tessera" render "$flat" --camera "$camera" --size 160x90 -o "$out-flat.png"
"$tessera" render "$out-room.json" --camera "$camera" --size 160x90 -o "$out-room.png"
"$check" "$out-flat.png" "$out-room.png" 160x90 --max-diff 2 --mean-diff 0.1 --black-excess 0.02
