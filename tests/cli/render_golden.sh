#!/bin/sh
# Renders a project view with the CLI and compares it with its golden image.
# usage: render_golden.sh TESSERA GOLDEN_TOOL NAME PROJECT CAMERA SIZE GOLDEN ARTIFACT_DIR
set -e
tessera=$1 tool=$2 name=$3 project=$4 camera=$5 size=$6 golden=$7 artifacts=$8
mkdir -p "$artifacts"
"$tessera" render "$project" --camera "$camera" --size "$size" --supersample 2 -o "$artifacts/$name.render.png"
"$tool" "$name" "$artifacts/$name.render.png" "$golden" "$artifacts"
