#!/usr/bin/env bash
# Wall time of the whole P family for water on two cores: the 90 systems are independent, so the 15
# schemes run as separate `rotlie solve` processes, two at a time (GiNaC and CLN are not thread-safe,
# so one process solves its systems in sequence). Then the same family in one process, for the ratio.
# Usage: bench/solve_two_cores.sh [path/to/rotlie] [family P|R|N]
set -euo pipefail
rotlie=${1:-./build/release/bin/rotlie}
family=${2:-P}
case "$family" in
  P) schemes=$(printf 'P%d\n' 15 14 13 12 11 10 9 8 7 6 5 4 3 2 1) ;;
  N) schemes=$(printf 'N%d\n' 7 6 5 4 3 2 1) ;;
  R) schemes=R ;;
  *) echo "family must be N, R or P" >&2; exit 2 ;;
esac
[ -x "$rotlie" ] || { echo "no rotlie binary at $rotlie (build the release preset first)" >&2; exit 2; }
start=$(date +%s.%N)
echo "$schemes" | xargs -P 2 -I{} "$rotlie" solve --family "$family" --scheme {} --inertia water > /dev/null
two=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')
start=$(date +%s.%N)
"$rotlie" solve --family "$family" --inertia water > /dev/null
one=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')
awk -v f="$family" -v two="$two" -v one="$one" \
  'BEGIN { printf "%s family, water: two processes %.2f s wall, one process %.2f s (ratio %.2f)\n", f, two, one, one / two }'
