#!/usr/bin/env bash
# The LAMMPS headers the adapter needs and liblammps-dev does not install (fix_rigid_small.h,
# math_extra.h, rigid_const.h, the bundled fmt, ...), taken from Debian's source package of exactly
# the installed liblammps version. Idempotent: a stamp holding the version makes a second run instant.
#   lammps/fetch-headers.sh [DEST]    DEST defaults to build/lammps-headers in the repository
# Needs the Debian archive already configured for apt; a deb-src entry for it is added when missing.
set -euo pipefail

repo="$(cd "$(dirname "$0")/.." && pwd)"
dest="${1:-$repo/build/lammps-headers}"

if ! dpkg-query -W -f='${Status}' liblammps-dev 2>/dev/null | grep -q "install ok installed"; then
  echo "fetch-headers: liblammps-dev is not installed; nothing to do (lammps/ will not be built)"
  exit 0
fi
# the source version of the installed library (a binNMU suffix such as +b2 is not part of it)
version="$(dpkg-query -W -f='${source:Version}' liblammps-dev)"
if [ -f "$dest/.debian-source-version" ] && [ "$(cat "$dest/.debian-source-version")" = "$version" ]; then
  echo "fetch-headers: LAMMPS headers of $version already in $dest"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
# deb-src lines for the Debian archive apt already uses (deb822 or one-line form), once
if ! grep -rqs -E '^(Types:.*deb-src|deb-src )' /etc/apt/sources.list /etc/apt/sources.list.d/; then
  if [ -f /etc/apt/sources.list.d/debian.sources ]; then
    sed 's/^Types: deb$/Types: deb-src/' /etc/apt/sources.list.d/debian.sources |
      $sudo tee /etc/apt/sources.list.d/debian-src.sources > /dev/null
  elif [ -f /etc/apt/sources.list ]; then
    grep -E '^deb ' /etc/apt/sources.list | sed 's/^deb /deb-src /' | $sudo tee /etc/apt/sources.list.d/debian-src.list > /dev/null
  else
    echo "fetch-headers: error: no Debian archive configured for apt (no debian.sources, no sources.list)" >&2
    exit 1
  fi
  $sudo apt-get update -qq
fi

work="$(dirname "$dest")/lammps-source"
rm -rf "$work"
mkdir -p "$work"
echo "fetch-headers: apt-get source lammps=$version (unpacked in $work)"
(cd "$work" && apt-get source -qq "lammps=$version" > /dev/null)
src="$(find "$work" -mindepth 1 -maxdepth 1 -type d -name 'lammps-*' | head -n 1)"
if [ -z "$src" ] || [ ! -f "$src/src/RIGID/fix_rigid_small.h" ]; then
  echo "fetch-headers: error: the source package of lammps $version has no src/RIGID/fix_rigid_small.h" >&2
  exit 1
fi
rm -rf "$dest"
mkdir -p "$dest/fmt"
cp "$src"/src/*.h "$src"/src/RIGID/*.h "$dest/"
cp "$src"/src/fmt/*.h "$dest/fmt/"
printf '%s\n' "$version" > "$dest/.debian-source-version"
rm -rf "$work"
echo "fetch-headers: $(find "$dest" -name '*.h' | wc -l) headers of LAMMPS $version in $dest"
