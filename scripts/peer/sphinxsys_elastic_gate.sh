#!/bin/bash
# Builds and runs the peer, SPHinXsys, on its own elastic gate (Antoci 2007 with
# E = 7.8 MPa, nu = 0.47, water 2.5 mm, gate 1.25 mm), from a pinned commit.
#
#   scripts/peer/sphinxsys_elastic_gate.sh [--checkout DIR] [--build DIR] [--vacuum] OUT
#
# --checkout  a SPHinXsys checkout (default $COSPH_PEER_DIR/SPHinXsys, cloned from GitHub
#             at PINNED if absent; an existing checkout is used at whatever commit it is,
#             and the commit is written to OUT/commit.txt)
# --build     the build folder (default $COSPH_PEER_DIR/build): 2-D library, Release, -j2, ccache;
#             only the gate's two programs (scripts/peer/CMakeLists.txt) are built
# --vacuum    run the gate alone in vacuum (elastic_gate_in_vacuum.cpp) instead of the
#             elastic-gate test
# Writes OUT/tip.csv (t_s, tip_dx_m, tip_dy_m: the free end's displacement, x positive
# downstream like cosph's) or, with --vacuum, OUT/vacuum.csv (t_s, mid_dx_m, corner_dx_m),
# and OUT/wall_time.txt (seconds, the program's run alone, not the build).
# COSPH_PEER_DIR defaults to the repository's out/peer (not tracked).
# Installs nothing: prints the apt-get line when a package is missing.
set -euo pipefail

PINNED=9f33297dc609355dfe36f55426c8a64c35cb80d5  # master of 24 Jul 2026
HERE="$(cd "$(dirname "$0")" && pwd)"
PEER_DIR="${COSPH_PEER_DIR:-$(cd "$HERE/../.." && pwd)/out/peer}"
CHECKOUT="$PEER_DIR/SPHinXsys"
BUILD="$PEER_DIR/build"
PROGRAM=test_2d_elastic_gate
while [[ $# -gt 1 ]]; do
  case "$1" in
    --checkout) CHECKOUT="$2"; shift 2 ;;
    --build) BUILD="$2"; shift 2 ;;
    --vacuum) PROGRAM=elastic_gate_in_vacuum; shift ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
[[ $# -eq 1 ]] || { sed -n '5,18p' "$0" >&2; exit 2; }
OUT="$(mkdir -p "$1" && cd "$1" && pwd)"

# Boost headers, Eigen and GTest's CMake files are needed too, but come with
# libboost-dev, libeigen3-dev and libgtest-dev; program_options reads the test's options.
missing=()
for package in libsimbody-dev libspdlog-dev libtbb-dev libeigen3-dev libboost-dev \
               libboost-program-options-dev cmake ninja-build ccache g++; do
  dpkg -s "$package" >/dev/null 2>&1 || missing+=("$package")
done
if [[ ${#missing[@]} -gt 0 ]]; then
  echo "missing packages; install them with:" >&2
  echo "  sudo apt-get install ${missing[*]}" >&2
  exit 1
fi

if [[ ! -d "$CHECKOUT/src" ]]; then
  git clone https://github.com/Xiangyu-Hu/SPHinXsys.git "$CHECKOUT"
  git -C "$CHECKOUT" checkout "$PINNED"
fi
git -C "$CHECKOUT" rev-parse HEAD > "$OUT/commit.txt"
[[ "$(cat "$OUT/commit.txt")" == "$PINNED" ]] ||
  echo "note: $CHECKOUT is at $(cat "$OUT/commit.txt"), not the pinned $PINNED" >&2

if [[ ! -f "$BUILD/build.ninja" ]]; then
  cmake -S "$HERE" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DSPHINXSYS_DIR="$CHECKOUT" -DCMAKE_CXX_COMPILER_LAUNCHER=ccache >/dev/null
fi
cmake --build "$BUILD" --target "$PROGRAM" -j2 >"$OUT/build.log" 2>&1 ||
  { tail -30 "$OUT/build.log" >&2; exit 1; }

# The program writes into ./output; the test compares itself with its regression
# data in ./input at the end (its verdict is not ours: see the log).
RUN="$OUT/run"
rm -rf "$RUN" && mkdir -p "$RUN/input"
cp -r "$CHECKOUT/tests/2d_examples/test_2d_elastic_gate/regression_test_tool/." "$RUN/input/"
start=$(date +%s.%N)
if [[ $PROGRAM == test_2d_elastic_gate ]]; then
  # No VTP snapshots: the comparison is of the computation (the test itself also leaves
  # them out of its own timing).
  (cd "$RUN" && "$BUILD/$PROGRAM" --state_recording=0 >"$OUT/run.log" 2>&1) || true
else
  (cd "$RUN" && "$BUILD/$PROGRAM" >"$OUT/run.log" 2>&1)
fi
end=$(date +%s.%N)
/usr/bin/python3 -c "print(round($end - $start, 2))" > "$OUT/wall_time.txt"

# Observer_Position.dat: run_time (ms) then the observers' positions (mm), one row per step.
/usr/bin/python3 - "$RUN/output/Observer_Position.dat" "$OUT" "$PROGRAM" <<'EOF'
import sys
import numpy as np
rows = np.loadtxt(sys.argv[1], skiprows=1, ndmin=2)
t, positions = rows[:, 0] * 1e-3, (rows[:, 1:] - rows[0, 1:]) * 1e-3
if sys.argv[3] == "test_2d_elastic_gate":
    # The peer's water is on the gate's right and flows to -x: flip x to cosph's sense.
    np.savetxt(f"{sys.argv[2]}/tip.csv", np.column_stack([t, -positions[:, 0], positions[:, 1]]),
               delimiter=",", header="t_s,tip_dx_m,tip_dy_m", comments="", fmt="%.7g")
else:
    np.savetxt(f"{sys.argv[2]}/vacuum.csv", np.column_stack([t, positions[:, 0], positions[:, 2]]),
               delimiter=",", header="t_s,mid_dx_m,corner_dx_m", comments="", fmt="%.7g")
EOF
echo "$PROGRAM: $(cat "$OUT/wall_time.txt") s wall, results in $OUT"
