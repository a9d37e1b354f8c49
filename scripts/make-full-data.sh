#!/usr/bin/env bash
# Computes the papers' full-resolution maps shipped under data/maps-K200 (Laskar & Vaillant's grid,
# --grid 200: 39,800 asymmetric bodies per family) and records how each was made.
#
#   scripts/make-full-data.sh [--binary PATH] [--ranks N] [--work DIR] FAMILY...   (N, R, P)
#
# Each family is computed by `rotlie map --family F --grid 200 --resume` into DIR (default
# build/full-data; resumable: a killed run continues where it stopped), then compressed with
# xz -9e into data/maps-K200/map-F.jsonl.xz. Beside it, map-F.source records the command, the commit
# of the source tree, the date, the map's own summary, the sizes and the sha256 of the map and of the
# compressed file; data/maps-K200/SHA256SUMS is rewritten for `sha256sum -c`.
# Cost on one core of the development machine: N 10 min, R about 11 h, P about 4 h (screened rows)
# and 29 min (the neighbour check).
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
binary=$root/build/release/bin/rotlie
ranks=1
work=$root/build/full-data
families=()
while [[ $# -gt 0 ]]; do
  case $1 in
    --binary) binary=$2; shift 2 ;;
    --ranks) ranks=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    N|R|P) families+=("$1"); shift ;;
    *) echo "make-full-data.sh: unknown argument '$1' (families N, R, P; --binary, --ranks, --work)" >&2; exit 2 ;;
  esac
done
[[ ${#families[@]} -gt 0 ]] || { echo "make-full-data.sh: name the families to compute (N, R, P)" >&2; exit 2; }
[[ -x $binary ]] || { echo "make-full-data.sh: no rotlie binary at $binary (build first, or --binary)" >&2; exit 2; }

out=$root/data/maps-K200
mkdir -p "$work" "$out"
commit=$(git -C "$root" rev-parse --short=12 HEAD 2>/dev/null || echo unknown)
[[ -z $(git -C "$root" status --porcelain -- apps runs solver bch lie 2>/dev/null) ]] || commit="$commit (with local changes)"

for f in "${families[@]}"; do
  command=(rotlie map --family "$f" --grid 200 --out "$work" --resume)
  launch=("$binary" "${command[@]:1}")
  [[ $ranks -gt 1 ]] && launch=(mpirun -n "$ranks" "${launch[@]}")
  echo "make-full-data.sh: ${command[*]} (ranks: $ranks)" >&2
  summary=$("${launch[@]}")
  map=$work/map-$f.jsonl
  xz -9e -T1 -c "$map" > "$out/map-$f.jsonl.xz.part"
  mv "$out/map-$f.jsonl.xz.part" "$out/map-$f.jsonl.xz"
  {
    echo "file: map-$f.jsonl.xz (xz -9e of map-$f.jsonl)"
    echo "command: rotlie map --family $f --grid 200 --out DIR --resume   (ranks: $ranks)"
    echo "source commit: $commit"
    echo "made: $(date -u +%Y-%m-%d)"
    echo "map-$f.jsonl: $(stat -c %s "$map") bytes, $(wc -l < "$map") lines, sha256 $(sha256sum "$map" | cut -d' ' -f1)"
    echo "map-$f.jsonl.xz: $(stat -c %s "$out/map-$f.jsonl.xz") bytes, sha256 $(sha256sum "$out/map-$f.jsonl.xz" | cut -d' ' -f1)"
    echo "summary of the last (resumed) run:"
    sed -e 's/^/  /' -e "s| in $work/| in DIR/|" <<< "$summary"
  } > "$out/map-$f.source"
done
(cd "$out" && sha256sum ./*.jsonl.xz > SHA256SUMS)
echo "make-full-data.sh: wrote $(ls "$out"/*.jsonl.xz | tr '\n' ' ')" >&2
