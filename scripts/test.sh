#!/usr/bin/env bash
# The test command of the README (and of .ci/run): installs what is missing,
# builds the release preset, and runs the whole test suite.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install_deps.sh
cmake --preset release
cmake --build --preset release -j2
ctest --preset release -j2 --timeout 600
