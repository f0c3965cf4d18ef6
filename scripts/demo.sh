#!/usr/bin/env bash
# The main demo: the truck lane change ("perestavka", issue 7) at 55 km/h,
# once with the rigid and once with the elastic (Craig-Bampton) ladder frame,
# and the seed's comparison plots (rigid against elastic, frame deflection
# and stress); a three-axle 6x4 with a balancer bogie; the handling tests (step steer, constant steering-wheel angle,
# braking in a turn) and the truck with its frame from a Nastran deck; then
# Andrews' squeezer (IFToMM A03) and the two-loop four-bar (A02) through the
# command line; then the crane example's work cycle
# (examples/crane: boom FE model written as Nastran, reduced, run, plotted).
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/demo}
bin=${FLEXMB_BIN:-build/release/bin/flexmb}
mkdir -p "$out"
start=$(date +%s%N)
for frame in rigid elastic; do
  echo "== truck lane change, 55 km/h, $frame frame"
  # the elastic run also writes the ParaView animation (truck_elastic/animation/anim.pvd),
  # 10 frames per second of simulated time to keep the demo short (the default is 25)
  anim=()
  if [ "$frame" = elastic ]; then anim=(--animation-fps 10); fi
  "$bin" run examples/truck_lane_change/truck.yaml --out "$out/truck_$frame" --speed 55 --frame "$frame" "${anim[@]}"
  cat "$out/truck_$frame/summary.json"; echo
done
/usr/bin/python3 examples/truck_lane_change/plot.py "$out/truck_rigid" "$out/truck_elastic" --out "$out/truck_plots"
if command -v pvbatch > /dev/null && command -v xvfb-run > /dev/null; then
  echo "== the animation in ParaView: the camera follows the truck, the frame seen through the cargo box"
  xvfb-run -a pvbatch examples/truck_lane_change/view_animation.py "$out/truck_elastic/animation/anim.pvd" \
    --png "$out/truck_elastic/views" --stride 10 || echo "(ParaView render skipped: no virtual display)"
fi
echo "truck demo: $(( ($(date +%s%N) - start) / 1000000 )) ms wall time (two runs, the frame's reduction and plots)"
echo "== a three-axle 6x4 with a balancer bogie (examples/truck_6x4): the same lane change at 40 km/h, rigid frame"
"$bin" run examples/truck_6x4/truck.yaml --out "$out/truck_6x4" --speed 40
cat "$out/truck_6x4/summary.json"; echo
echo "== truck handling: step steer at 60 km/h (ISO 14793), constant steering-wheel angle (ISO 14792), braking in a turn"
for t in step-steer constant-steer brake-in-turn; do
  speed=(--speed 60)  # constant steer: from 10 km/h up
  if [ "$t" = constant-steer ]; then speed=(); fi
  "$bin" truck handling examples/truck_lane_change/truck.yaml --test "$t" "${speed[@]}" --out "$out/truck_$t"
done
/usr/bin/python3 examples/truck_lane_change/plot_handling.py "$out/truck_step-steer"
echo "== truck handling: sine steer (ISO 14793) at 0.2, 0.5 and 1 Hz, 60 km/h, against the single-track model"
for fq in 0.2 0.5 1.0; do
  "$bin" truck handling examples/truck_lane_change/truck.yaml --test sine-steer --speed 60 --ay 0.5 --frequency "$fq" \
    --out "$out/truck_sine-steer_$fq"
done
/usr/bin/python3 examples/truck_lane_change/plot_handling.py "$out"/truck_sine-steer_* --out "$out/truck_sine-steer"
/usr/bin/python3 examples/truck_lane_change/plot_handling.py "$out/truck_constant-steer"
echo "== truck with its frame from an FE deck: frame-deck, flexmb reduce, frame: {body, mounts}"
/usr/bin/python3 examples/truck_lane_change/own_frame.py --out "$out/own_frame" --flexmb "$bin"
"$bin" run "$out/own_frame/truck_own_frame.yaml" --frame elastic --speed 55 --out "$out/truck_own_frame"
for ex in andrews_squeezer four_bar_2; do
  if [ -f "examples/$ex/model.yaml" ]; then
    echo "== $ex"
    "$bin" run "examples/$ex/model.yaml" --out "$out/$ex"
    cat "$out/$ex/summary.json"; echo
  fi
done
echo "== crane: lift-off of a grounded load by the winch and a 90 degree slew (examples/crane)"
crane="$out/crane"
mkdir -p "$crane"
cp examples/crane/crane.yaml "$crane/"
/usr/bin/python3 examples/crane/make_boom.py --out "$crane/boom.bdf"
"$bin" reduce "$crane/boom.bdf" --fix 1 --interface 1,2,3 --modes 20 --deformation-stiffening -o "$crane/boom.h5" > "$crane/reduce.txt"
sed -n 1,3p "$crane/reduce.txt"
"$bin" run "$crane/crane.yaml" --out "$crane/run" --animation
/usr/bin/python3 examples/crane/plot.py "$crane/run" --out "$crane/plots" > "$crane/plots.txt"
cat "$crane/plots/crane_metrics.json"; echo
echo "== crane: the hoisting rope two ways, massless and an ANCF rope of changing length, hoisting during the slew"
/usr/bin/python3 examples/crane/rope_methods.py --flexmb "$bin" --body "$crane/boom.h5" --out "$crane/rope_methods" --animation
echo "results in $out: truck_step-steer/, truck_sine-steer/ (frequency_response.png), truck_constant-steer/, truck_brake-in-turn/ (handling tests: summary.json"
echo "with the single-track model beside the truck, PNGs), own_frame/ (frame.bdf, frame.h5, truck_own_frame.yaml) and"
echo "truck_own_frame/ (the lane change with that frame), truck_rigid/, truck_elastic/ (results.csv, summary.json; frame.h5, the reduced"
echo "frame; animation/anim.pvd, the whole truck with the deformed, stress-coloured frame for ParaView; views/, renders following the truck), truck_plots/ (PNG: rigid against elastic, frame deflection and stress), and the examples'"
echo "folders (results.csv, summary.json, anim.pvd for ParaView); crane/run (results.csv, anim.pvd: boom deformed 20x and stress-coloured, platform, drum, luffing cylinder, load)"
echo "and crane/plots (crane_metrics.json: phi_2, swing, slewing torque, winch torque, cylinder force, boom deflection and stress; PNGs)"
echo "and crane/rope_methods (rope_methods.md; ancf/anim.pvd: the rope as a line of changing length, hook, load, boom)"
