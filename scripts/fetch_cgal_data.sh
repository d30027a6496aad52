#!/usr/bin/env bash
# Puts CGAL's public test meshes (anchor.off, elephant.off, mech-holes-shark.off, ...) under
# .cache/cgal-data/data, from Debian's libcgal-demo package. Only the package file is downloaded
# and unpacked (installing it would pull in Qt); nothing is done when the data is already there.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
destination="$root/.cache/cgal-data"
if [ -f "$destination/data/meshes/anchor.off" ]; then
  echo "CGAL data meshes: present in $destination/data"
  exit 0
fi

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
if ! apt-get download libcgal-demo >/dev/null 2>&1; then
  # The package lists may be missing on a fresh machine.
  if [ "$(id -u)" -eq 0 ]; then apt-get update -qq; else sudo apt-get update -qq; fi
  apt-get download libcgal-demo >/dev/null
fi
dpkg-deb -x libcgal-demo_*.deb unpacked
mkdir -p "$work/data"
tar -xzf unpacked/usr/share/doc/libcgal-dev/data.tar.gz -C "$work/data"
rm -rf "$destination"
mkdir -p "$(dirname "$destination")"
mv "$work/data" "$destination"
echo "CGAL data meshes: unpacked into $destination/data"
