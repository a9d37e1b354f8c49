#!/usr/bin/env bash
# Checks that a numeric-only build tree (ROTLIE_WITH_SYMBOLIC=OFF) never names GiNaC or CLN: not in
# its compile commands, not in any link line, not in the configure cache (configure did not look).
#   scripts/check-numeric-only.sh [BUILD_DIR]     (default build/numeric-only)
set -euo pipefail
build=${1:-build/numeric-only}

fail() { echo "check-numeric-only: $*" >&2; exit 1; }
[ -f "$build/CMakeCache.txt" ] || fail "$build is not a configured build tree"
grep -q '^ROTLIE_WITH_SYMBOLIC:BOOL=OFF$' "$build/CMakeCache.txt" || fail "$build is not configured with ROTLIE_WITH_SYMBOLIC=OFF"
[ -f "$build/compile_commands.json" ] || fail "$build/compile_commands.json is missing"

mapfile -t link_lines < <(find "$build" -name link.txt)
[ ${#link_lines[@]} -gt 0 ] || fail "no link lines under $build: build it first"

# ginac, cln as words: -lginac, libcln.so, /usr/include/cln/, PkgConfig::CLN, GINAC_FOUND …
pattern='(^|[^[:alnum:]]|lib)(ginac|cln)([^[:alnum:]]|$)'
status=0
names() {  # FILE: its lines naming GiNaC or CLN (the cache's help texts, lines starting with //, excepted)
  grep -v '^//' "$1" | grep -Eio ".{0,40}$pattern.{0,40}" | head -3
}
for f in "$build/compile_commands.json" "$build/CMakeCache.txt" "${link_lines[@]}"; do
  found=$(names "$f" || true)
  if [ -n "$found" ]; then
    printf 'check-numeric-only: %s names GiNaC or CLN:\n%s\n' "$f" "$found" >&2
    status=1
  fi
done
[ $status -eq 0 ] || exit 1
units=$(grep -c '"file"' "$build/compile_commands.json")
echo "check-numeric-only: $units compile commands, ${#link_lines[@]} link lines and the cache name neither GiNaC nor CLN"
