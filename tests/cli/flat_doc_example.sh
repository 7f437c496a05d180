#!/bin/sh
# The example under "## Flats" in docs/project-format.md is a flat that passes `check`, so the
# documented form stays the one the reader takes.
# usage: flat_doc_example.sh TESSERA DOC OUT.json
set -e
tessera=$1 doc=$2 out=$3
awk '/^## Flats/ { in_section = 1 } in_section && /^```json/ { grab = 1; next }
     grab && /^```/ { exit } grab { print }' "$doc" > "$out"
"$tessera" check "$out"
