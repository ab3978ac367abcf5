#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# sigdt's OPTIMALTRANSPORT against CGAL's Optimal_transportation_reconstruction_2 on the
# uniform-noise sweep of the data/curves manifold cases (README.md). Builds otr.cpp (GPL-3,
# links CGAL) outside the repository, writes the noisy sets, runs CGAL on each with
# `run_until(ceil(m / DIVISOR))` (m distinct points: sigdt's default stopping rule for
# DIVISOR=4), and prints the mean RMSE of both per noise level.
#
#   tools/cgal-otr/run.sh [OUT_DIR]        (environment: DIVISOR=4, LIMIT=N, TIME_LIMIT=120)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
out=${1:-$(mktemp -d /tmp/cgal-otr.XXXXXX)}
divisor=${DIVISOR:-4}
limit=${LIMIT:-1000000}
time_limit=${TIME_LIMIT:-120}
mkdir -p "$out"
otr="$out/otr"
if [ ! -x "$otr" ]; then
  echo "building $otr (CGAL, GPL-3) ..." >&2
  g++ -O2 -std=c++17 "$here/otr.cpp" -lgmp -lmpfr -o "$otr"
fi
(cd "$repo" && cargo build --quiet --release -p sigdt-lab --example ot_noise_sweep)
sweep="${CARGO_TARGET_DIR:-$repo/target}/release/examples/ot_noise_sweep"
"$sweep" --stop none --limit "$limit" --write "$out/input" > /dev/null
for level_dir in "$out"/input/*/; do
  level=$(basename "$level_dir")
  mkdir -p "$out/cgal/$level"
  start=$(date +%s.%N)
  for xy in "$level_dir"*.xy; do
    name=$(basename "$xy" .xy)
    m=$(cat "$level_dir/$name.n")
    keep=$(( (m + divisor - 1) / divisor ))
    if ! timeout "$time_limit" "$otr" --until "$keep" < "$xy" \
        > "$out/cgal/$level/$name.segments" 2> "$out/cgal/$level/$name.log"; then
      echo "$level $name: CGAL failed or ran past ${time_limit}s" >&2
      : > "$out/cgal/$level/$name.segments"
    fi
  done
  echo "CGAL, level $level: $(echo "$(date +%s.%N) - $start" | bc) s" >&2
done
"$sweep" --stop "v/$divisor" --limit "$limit" --score "cgal=$out/cgal" --csv "$out/rmse.csv"
echo "per-case RMSE: $out/rmse.csv" >&2
