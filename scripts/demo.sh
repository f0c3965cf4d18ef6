#!/usr/bin/env bash
# The main demo: the truck lane change ("perestavka", issue 7) at 55 km/h
# with the rigid frame, with PNG plots; then Andrews' squeezer (IFToMM A03)
# and the two-loop four-bar (A02) through the command line.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/demo}
bin=${FLEXMB_BIN:-build/release/bin/flexmb}
mkdir -p "$out"
echo "== truck lane change, 55 km/h, rigid frame"
start=$(date +%s%N)
"$bin" run examples/truck_lane_change/truck.yaml --out "$out/truck_lane_change" --speed 55 --frame rigid
cat "$out/truck_lane_change/summary.json"
/usr/bin/python3 examples/truck_lane_change/plot.py "$out/truck_lane_change"
echo "truck demo: $(( ($(date +%s%N) - start) / 1000000 )) ms wall time (simulation and plots)"
for ex in andrews_squeezer four_bar_2; do
  if [ -f "examples/$ex/model.yaml" ]; then
    echo "== $ex"
    "$bin" run "examples/$ex/model.yaml" --out "$out/$ex"
    cat "$out/$ex/summary.json"; echo
  fi
done
echo "results in $out (results.csv, summary.json, PNG plots, anim.pvd for ParaView)"
