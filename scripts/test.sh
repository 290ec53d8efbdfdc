#!/usr/bin/env bash
# The test command: checks the formatting, builds with warnings as errors, runs the whole CTest
# suite (fast and slow labels) and builds a program against the installed package; then runs the
# suite again in an AddressSanitizer + UndefinedBehaviorSanitizer build, then the libFuzzer targets
# of the input readers (clang) for a fixed number of inputs.
# Options: --fast (only the fast label, Release build only).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh

jobs=$(nproc)
# ccache: paths relative to the checkout, so that another clone on this machine hits the cache.
export CCACHE_BASEDIR="$(pwd)" CCACHE_NOHASHDIR=1
fast=0
[ "${1:-}" = "--fast" ] && fast=1

run_suite() {  # build dir, extra cmake args...
  local dir=$1; shift
  cmake -S . -B "$dir" -G Ninja -DBPMKIT_WARNINGS_AS_ERRORS=ON "$@" >/dev/null
  cmake --build "$dir"
  if [ $fast -eq 1 ]; then
    ctest --test-dir "$dir" --output-on-failure -j "$jobs" -LE slow
  else
    ctest --test-dir "$dir" --output-on-failure -j "$jobs"
  fi
}

# The installed package: `cmake --install` into a prefix, then a program outside the tree
# (tests/install_consumer) found it with find_package(bpmkit), runs Chen's case 1 cantilever (PBM:
# tip 8.508 mm down) and `bpmkit plot` from the prefix draws its probe.
install_check() {
  rm -rf build/install build/consumer
  cmake --install build --prefix build/install >/dev/null
  cmake -S tests/install_consumer -B build/consumer -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_PREFIX_PATH="$(pwd)/build/install" >/dev/null
  cmake --build build/consumer
  build/consumer/run_cantilever examples/01_cantilever/case1_pbm.yaml build/consumer/out 10 -8.508e-3 0.002
  build/install/bin/bpmkit plot build/consumer/out --out build/consumer/plots
  test -s build/consumer/plots/probes.png
}

echo "== Formatter (scripts/check-format.sh) =="
bash scripts/check-format.sh
echo "== Layers (scripts/check_layers.py) =="
python3 scripts/check_layers.py

echo "== Release build, warnings as errors =="
run_suite build -DCMAKE_BUILD_TYPE=Release
echo "== Installed package: an out-of-tree program with find_package(bpmkit) =="
install_check
if [ $fast -eq 0 ]; then
  echo "== ASan + UBSan build =="
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  export LSAN_OPTIONS=suppressions=$(pwd)/scripts/lsan.supp
  run_suite build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBPMKIT_SANITIZE=ON -DBPMKIT_ENABLE_BENCH=OFF
  echo "== libFuzzer (clang, ASan + UBSan): the scenario, CSV, binary table, MUSEN and LAMMPS readers, a fixed number of inputs each =="
  cmake -S . -B build-fuzz -G Ninja -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
    -DBPMKIT_ENABLE_LIBFUZZER=ON -DBPMKIT_ENABLE_TESTS=OFF -DBPMKIT_ENABLE_BENCH=OFF -DBPMKIT_PYTHON=OFF \
    -DBPMKIT_WARNINGS_AS_ERRORS=ON >/dev/null
  cmake --build build-fuzz --target scenario_fuzzer csv_fuzzer structure_table_fuzzer exchange_fuzzer
  ctest --test-dir build-fuzz --output-on-failure -j "$jobs" -L fuzz
fi
