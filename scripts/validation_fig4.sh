#!/usr/bin/env bash
# The fast methods against the quasi-static DEM (docs/validation.md): the README's small cylinder
# and the samples of docs/validation/samples (generated here from their structure.yml; case
# 3's pores carved as scripts/validation_study.py does), each with the DEM with platens, the linear
# and the nonlinear DSM (bond axes current and initial), the paper's DSM (nonlinear, 3 DOF, no
# slip, initial axes) and the same with 6 DOF, the STE, the kinematic DSM, and `calibrate --no-dem` aimed at the DEM's
# K. Prints the table, writes OUT/samples.csv and, with Debian's python3-matplotlib, OUT/fig4.png
# and .svg (Jarolin Fig. 4). A method whose result is in OUT already is not run again (delete its
# folder to rerun it). About 25 minutes on 2 cores.
#   bash scripts/validation_fig4.sh [OUT]        (default out/validation; BPMKIT=path overrides)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bpmkit=${BPMKIT:-$root/build/src/bpmkit}
out=${1:-out/validation}
export OMP_NUM_THREADS=1
mkdir -p "$out"

stiffness() {  # stiffness FOLDER ARGS...: bpmkit stiffness into $dir/FOLDER unless done before
  local name=$1
  shift
  [[ -f $dir/$name/stiffness.json ]] ||
    "$bpmkit" stiffness "$y" "$@" --threads 1 --out "$dir/$name" --overwrite > "$dir/$name.log"
}

samples=(small_cylinder case1_00 case1_01 case2_2000 case2_2005 case1_02 case2_2001 case3_3002)
for s in "${samples[@]}"; do
  dir=$out/$s
  if [[ $s == small_cylinder ]]; then
    mkdir -p "$dir" && cp -r "$root/examples/04_compression/small_cylinder/." "$dir/"
  else
    mkdir -p "$dir" && cp "$root/docs/validation/samples/$s/"*.y*ml "$dir/"
    if [[ ! -f $dir/structure/particles.csv ]]; then
      "$bpmkit" generate "$dir/structure.yml" --out "$dir/structure" --overwrite > "$dir/generate.log"
      if [[ $s == case3_3002 ]]; then  # 2 x 2 x 2 pore cells, seed 3002
        python3 -c "import sys; sys.path.insert(0, sys.argv[1]); import validation_study as v
_, _, _, pores = v.case3_files(3002, 2); v.carve(sys.argv[2], *pores)" "$root/scripts" "$dir/structure"
      fi
    fi
  fi
  y=$dir/compression.yaml
  echo "== $s"
  stiffness dem --method dem
  for m in dsm dsm-nonlinear; do
    for axes in current initial; do stiffness "$m-$axes" --method $m --axes $axes; done
  done
  for dofs in 3 6; do
    stiffness "paper-$dofs" --method dsm-nonlinear --dofs $dofs --slip off --axes initial
  done
  stiffness ste --method ste
  stiffness dsm-kinematic --method dsm-kinematic
  k=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['stiffness_N_per_m'])" "$dir/dem/stiffness.json")
  [[ -f $dir/calibrate/calibration.json ]] ||
    "$bpmkit" calibrate "$y" --no-dem --target-K "$k" --out "$dir/calibrate" --overwrite > "$dir/calibrate.log"
done

python=python3
/usr/bin/python3 -c "import matplotlib" 2> /dev/null && python=/usr/bin/python3
"$python" "$root/scripts/validation_fig4.py" "$out" "${samples[@]}"
