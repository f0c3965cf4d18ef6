#!/usr/bin/env bash
# The main demo. Until the truck lane-change model lands (issue 7), it runs
# Andrews' squeezer (IFToMM A03) and the two-loop four-bar (A02) through the
# command line and prints their summaries.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/demo}
bin=build/release/bin/flexmb
mkdir -p "$out"
for ex in andrews_squeezer four_bar_2; do
  if [ -f "examples/$ex/model.yaml" ]; then
    echo "== $ex"
    "$bin" run "examples/$ex/model.yaml" --out "$out/$ex"
    cat "$out/$ex/summary.json"; echo
  fi
done
echo "results in $out (results.csv, summary.json, anim.pvd for ParaView)"
