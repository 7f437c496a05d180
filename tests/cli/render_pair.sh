#!/bin/sh
# Renders two projects with the same camera and compares the images (check_image_file.c): a
# project with an object far outside the room must render as the room without it.
# usage: render_pair.sh TESSERA CHECK_IMAGE_FILE SIZE PROJECT FILE BASE_PROJECT BASE_FILE [OPTIONS...]
set -e
tessera=$1 check=$2 size=$3 project=$4 file=$5 base=$6 base_file=$7
shift 7
rm -f "$file" "$base_file"
"$tessera" render "$project" --size "$size" -o "$file"
"$tessera" render "$base" --size "$size" -o "$base_file"
"$check" "$file" "$base_file" "$size" "$@"
