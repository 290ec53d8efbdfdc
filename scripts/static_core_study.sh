#!/usr/bin/env bash
# The static core against the quasi-static DEM (docs/validation.md, "The static core against the
# quasi-static DEM"): the README's small cylinder and the samples of docs/validation/static_core
# (generated here from their structure.yml; case 3's pores carved as scripts/validation_study.py
# does), each with the DEM with platens, the linear and the
# nonlinear DSM (bond axes current and initial), the paper's DSM (nonlinear, 3 DOF, no slip,
# initial axes) and the same with 6 DOF, and `calibrate --no-dem` aimed at the DEM's K.
# Prints one table. About 25 minutes on 2 cores.
#   bash scripts/static_core_study.sh [OUT]        (default out/static_core; BPMKIT=path overrides)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bpmkit=${BPMKIT:-$root/build/src/bpmkit}
out=${1:-out/static_core}
export OMP_NUM_THREADS=1
mkdir -p "$out"

samples=(small_cylinder case1_00 case1_01 case2_2000 case2_2005 case1_02 case2_2001 case3_3002)
for s in "${samples[@]}"; do
  dir=$out/$s
  if [[ $s == small_cylinder ]]; then
    mkdir -p "$dir" && cp -r "$root/examples/04_compression/small_cylinder/." "$dir/"
  else
    mkdir -p "$dir" && cp "$root/docs/validation/static_core/$s/"*.y*ml "$dir/"
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
  [[ -f $dir/dem/stiffness.json ]] ||
    "$bpmkit" stiffness "$y" --method dem --threads 1 --out "$dir/dem" --overwrite > "$dir/dem.log"
  for m in dsm dsm-nonlinear; do
    for axes in current initial; do
      "$bpmkit" stiffness "$y" --method $m --axes $axes --threads 1 --out "$dir/$m-$axes" \
        --overwrite > "$dir/$m-$axes.log"
    done
  done
  for dofs in 3 6; do
    "$bpmkit" stiffness "$y" --method dsm-nonlinear --dofs $dofs --slip off --axes initial \
      --threads 1 --out "$dir/paper-$dofs" --overwrite > "$dir/paper-$dofs.log"
  done
  k=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['stiffness_N_per_m'])" "$dir/dem/stiffness.json")
  "$bpmkit" calibrate "$y" --no-dem --target-K "$k" --out "$dir/calibrate" --overwrite > "$dir/calibrate.log"
done

python3 - "$out" "${samples[@]}" <<'PY'
import json, re, sys
out, samples = sys.argv[1], sys.argv[2:]
def read(path): return json.load(open(path))
print("| sample | K_DEM [N/m] | platen imbalance | kinetic/elastic | dsm | dsm (initial axes) "
      "| dsm-nonlinear | dsm-nonlinear (initial axes) | paper's DSM: 3 DOF, no slip, initial axes "
      "| the same with 6 DOF | calibrate --no-dem: E_b error |")
print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
for s in samples:
    d = f"{out}/{s}"
    dem = read(f"{d}/dem/stiffness.json")
    k = dem["stiffness_N_per_m"]
    err = lambda m: 100 * (read(f"{d}/{m}/stiffness.json")["stiffness_N_per_m"] / k - 1)
    text = open(f"{d}/compression.yaml").read()
    true_e = float(re.search(r"bond_materials:\s*\n\s*\w+:\s*\{[^}]*youngs_modulus:\s*([0-9.eE+-]+)", text).group(1))
    answer = read(f"{d}/calibrate/calibration.json")["stages"][-1]["bond_youngs_modulus_Pa"]
    e_err = 100 * (next(iter(answer.values())) / true_e - 1)
    det = dem["details"]
    print(f"| {s} | {k:,.1f} | {100 * det['max_platen_force_imbalance']:.2f} % | "
          f"{det['max_kinetic_to_elastic_energy']:.1e} | {err('dsm-current'):+.2f} % | {err('dsm-initial'):+.2f} % | "
          f"{err('dsm-nonlinear-current'):+.2f} % | {err('dsm-nonlinear-initial'):+.2f} % | "
          f"{err('paper-3'):+.2f} % | {err('paper-6'):+.2f} % | {e_err:+.2f} % |")
PY
