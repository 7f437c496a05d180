#!/usr/bin/env bash
# `tessera catalog search` as a fresh process (start, open, search, print, exit) over showroom
# queries in German and English: the median and p95 of the wall time and of the CPU time (user +
# system; on a loaded machine the wall time is mostly waiting for a core), in ms.
#   tests/catalog/bench_search_fresh.sh build/ui/tessera CATALOG.sqlite [ROUNDS]
set -euo pipefail
tessera=$1 db=$2 rounds=${3:-10}
queries=("Weiß" "weiss" "Waschtisch" "Badewanne" "Duschwanne" "Spiegel" "Armatur" "grau"
  "anthrazit" "tile grey" "Fliese grau" "basin mixer" "thermostatic" "mirror 600" "wc"
  "shower tray 900" "chrome" "washb" "towel radiator" "Waschtische")
TIMEFORMAT='%3R %3U %3S'
out=$(mktemp)
for ((r = 0; r < rounds; r++)); do
  for q in "${queries[@]}"; do
    # shellcheck disable=SC2086 # the words of the query are separate arguments
    { time "$tessera" catalog search $q --db "$db" >/dev/null 2>&1; } 2>>"$out" || true
  done
done
stats() { sort -g | awk -v what="$1" '{ v[NR] = $1 * 1000 } END {
  printf "%-5s %d runs: median %.1f ms, p95 %.1f ms, max %.1f ms\n", what, NR, v[int((NR + 1) / 2)],
         v[int(NR * 0.95 + 0.999)], v[NR] }'; }
awk '{ print $1 }' "$out" | stats wall
awk '{ print $2 + $3 }' "$out" | stats cpu
rm -f "$out"
