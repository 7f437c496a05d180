#!/bin/sh
# Renders a project into FILE and again into REFERENCE (another format), then reads both back
# and compares them (check_image_file.c; its options give the format's loss).
# usage: render_readback.sh TESSERA CHECK_IMAGE_FILE PROJECT SIZE FILE REFERENCE [OPTIONS...]
set -e
tessera=$1 check=$2 project=$3 size=$4 file=$5 ref=$6
shift 6
rm -f "$file" "$ref"
"$tessera" render "$project" --size "$size" -o "$file"
"$tessera" render "$project" --size "$size" -o "$ref"
"$check" "$file" "$ref" "$size" "$@"
