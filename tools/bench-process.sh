#!/usr/bin/env bash
# Whole-process comparison, interleaved: for each point file, ROUNDS rounds of
#   BEFORE reconstruct (optional, another sigdt binary), sigdt reconstruct on 1 thread and on
#   2 threads (RAYON_NUM_THREADS), and tools/cgal-delaunay (read + triangulate)
# under /usr/bin/time; prints the median wall seconds, CPU seconds (user + sys) and peak
# resident bytes per point of each, as Markdown rows.
#
# usage: tools/bench-process.sh SIGDT CGAL_TOOL ROUNDS FILE... [-- BEFORE]
# e.g.   tools/bench-process.sh target/release/sigdt target/cgal-delaunay 3 pts/*.xy
set -euo pipefail
sigdt=$1 cgal=$2 rounds=$3
shift 3
files=() before=""
while (($#)); do
  if [[ $1 == -- ]]; then before=$2; shift 2; else files+=("$1"); shift; fi
done
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
median() { sort -g | awk '{a[NR]=$1} END {print (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}'; }
run() { # label, then the command; appends "wall cpu rss" to $out/label
  local label=$1; shift
  /usr/bin/time -f "%e %U %S %M" -o "$out/t" "$@" >/dev/null 2>&1
  awk '{printf "%s %.3f %s\n", $1, $2 + $3, $4}' "$out/t" >> "$out/$label"
}
echo "| file | n | program | wall s | CPU s | peak RSS bytes/point |"
echo "|---|--:|---|--:|--:|--:|"
for f in "${files[@]}"; do
  n=$(wc -l < "$f")
  rm -f "$out"/{before,one,two,cgal}
  for _ in $(seq "$rounds"); do
    [[ -n $before ]] && run before "$before" reconstruct "$f" -o "$out/b.edges"
    RAYON_NUM_THREADS=1 run one "$sigdt" reconstruct "$f" -o "$out/1.edges"
    RAYON_NUM_THREADS=2 run two "$sigdt" reconstruct "$f" -o "$out/2.edges"
    run cgal "$cgal" "$f"
    cmp -s "$out/1.edges" "$out/2.edges" || { echo "outputs differ between 1 and 2 threads" >&2; exit 1; }
    if [[ -n $before ]]; then cmp -s "$out/1.edges" "$out/b.edges" || { echo "output differs from before" >&2; exit 1; }; fi
  done
  for label in before one two cgal; do
    [[ -f $out/$label ]] || continue
    wall=$(cut -d' ' -f1 "$out/$label" | median)
    cpu=$(cut -d' ' -f2 "$out/$label" | median)
    kb=$(cut -d' ' -f3 "$out/$label" | median)
    name=$label
    case $label in before) name="before";; one) name="sigdt, 1 thread";; two) name="sigdt, 2 threads";; cgal) name="cgal-delaunay";; esac
    echo "| $(basename "$f") | $n | $name | $wall | $cpu | $(awk -v k="$kb" -v n="$n" 'BEGIN {printf "%.0f", k * 1024 / n}') |"
  done
done
