#!/bin/sh
# The whole-flat benchmark (docs/benchmarks.md "A whole flat"): generates flats of 1, 2, 4 and
# 8 rooms and runs check, quantities, render (640 x 360, default and print preset) and print on
# each under /usr/bin/time -v, one CSV row a step: rooms, step, wall s, user s, sys s, peak RSS
# MB, the load average before the step. The bake cache is warmed first (one render of every
# room), so that the renders time rendering, not the first-time light bake.
# usage: flat_bench.sh TESSERA OUT_DIR [ROOMS...]   (default rooms: 1 2 4 8)
set -e
tessera=$1 out=$2
shift 2
rooms=${*:-1 2 4 8}
mkdir -p "$out"
export TESSERA_CATALOG="$out/catalog.sqlite" XDG_CACHE_HOME="$out/cache" XDG_STATE_HOME="$out/state"
csv="$out/flat-bench.csv"
echo "rooms,step,wall_s,user_s,sys_s,peak_mb,load_before" > "$csv"

timed() { # timed ROOMS STEP COMMAND...
  n=$1 step=$2
  shift 2
  load=$(cut -d' ' -f1 /proc/loadavg)
  /usr/bin/time -v -o "$out/time.txt" "$@" > "$out/$n-$step.out" 2> "$out/$n-$step.err" || {
    echo "$step failed for $n rooms: see $out/$n-$step.err" >&2
    exit 1
  }
  wall=$(sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$out/time.txt" |
         awk -F: '{ s = 0; for (i = 1; i <= NF; i++) s = s * 60 + $i; print s }')
  user=$(sed -n 's/.*User time (seconds): //p' "$out/time.txt")
  sys=$(sed -n 's/.*System time (seconds): //p' "$out/time.txt")
  rss=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$out/time.txt")
  echo "$n,$step,$wall,$user,$sys,$((rss / 1024)),$load" | tee -a "$csv"
}

for n in $rooms; do
  flat="$out/flat$n.json"
  "$tessera" generate-flat --rooms "$n" --seed 1 -o "$flat" > /dev/null
  for r in $(seq 1 "$n"); do # warm the bake cache
    "$tessera" render "$flat" --room "$r" --size 64x36 -o "$out/warm.png" 2> /dev/null
  done
  timed "$n" check "$tessera" check "$flat"
  grep -o 'read [0-9]* rooms* in [0-9.]* ms' "$out/$n-check.err" | sed "s/^/$n rooms: /"
  timed "$n" quantities "$tessera" quantities "$flat"
  timed "$n" render-640x360 "$tessera" render "$flat" --size 640x360 -o "$out/render$n.png"
  timed "$n" render-print "$tessera" render "$flat" --quality print --size 640x360 \
    -o "$out/render$n-print.png"
  timed "$n" print "$tessera" print "$flat" -o "$out/flat$n.pdf"
done
