#!/bin/sh
# Renders one camera of a project with the rasteriser into FILE and with the path tracer's
# direct light (`tessera reference --bounces 0`) into REFERENCE, then compares them
# (check_image_file.c: --black-excess counts pixels the render left black where the tracer
# shows the room).
# usage: render_vs_reference.sh TESSERA CHECK_IMAGE_FILE PROJECT SIZE CAMERA FILE REFERENCE [OPTIONS...]
set -e
tessera=$1 check=$2 project=$3 size=$4 camera=$5 file=$6 ref=$7
shift 7
rm -f "$file" "$ref"
"$tessera" render "$project" --size "$size" --camera "$camera" -o "$file"
"$tessera" reference "$project" --size "$size" --camera "$camera" --samples 4 --bounces 0 -o "$ref"
"$check" "$file" "$ref" "$size" "$@"
