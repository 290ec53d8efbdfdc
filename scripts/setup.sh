#!/usr/bin/env bash
# One command for a new user on Debian 12: installs the dependencies (Debian packages only),
# builds bpmkit in Release, and runs the main job (Chen's cantilever verification suite).
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install-deps.sh

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build

if [ "${1:-}" != "--no-run" ]; then
  echo
  ./build/src/bpmkit verify cantilever --out out/cantilever --overwrite  # replaces an earlier setup's results
fi
