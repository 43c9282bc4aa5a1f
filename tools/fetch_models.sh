#!/usr/bin/env bash
# Fetch the classic meshes that Debian's libcgal-demo package ships (bunny00, cow, lion, head, armadillo,
# elephant, ChineseDragon-10kv, ...) into data/models/ without installing the package system-wide.
# Usage: tools/fetch_models.sh [DEST]   (default: <repo>/data/models)
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
dest=${1:-$here/data/models}
# Tetrahedral meshes of closed models (lab 02): Debian's tetgen (TetGen 1.5), constrained Delaunay without
# quality refinement (-pQ: the surface is kept exactly, so the boundary equals the model), plus Medit (-g).
# Each run's command line goes to $dest/tetgen.txt. Skipped, with a message, when tetgen is not installed.
tetrahedralize() {
  command -v tetgen >/dev/null 2>&1 || { echo "fetch_models: tetgen not installed (apt-get install tetgen): no tet meshes" >&2; return 0; }
  local tmp; tmp=$(mktemp -d)
  for m in bunny00 elephant knot1 sphere; do
    [ -f "$dest/$m.1.ele" ] && continue
    [ -f "$dest/$m.off" ] || { echo "fetch_models: $m.off missing: no tet mesh of it" >&2; continue; }
    cp "$dest/$m.off" "$tmp/"
    if (cd "$tmp" && tetgen -pQg "$m.off" >/dev/null 2>&1); then
      for e in node ele face mesh; do cp "$tmp/$m.1.$e" "$dest/"; done
      echo "$m.1.{node,ele,face,mesh}: tetgen -pQg $m.off   ($(dpkg-query -W -f='tetgen ${Version}' tetgen 2>/dev/null))" >> "$dest/tetgen.txt"
    else
      echo "fetch_models: tetgen failed on $m.off" >&2
    fi
  done
  rm -rf "$tmp"
}
if [ -f "$dest/bunny00.off" ]; then echo "models already in $dest"; tetrahedralize; exit 0; fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
if ! apt-get download libcgal-demo >/dev/null 2>&1; then
  echo "fetch_models: 'apt-get download libcgal-demo' failed (run 'apt-get update' first?); tests that need real models will skip" >&2
  exit 1
fi
dpkg -x libcgal-demo_*.deb pkg
tarball=$(find pkg -name data.tar.gz -path '*libcgal-dev*' | head -1)
[ -n "$tarball" ] || { echo "fetch_models: data.tar.gz not found in libcgal-demo" >&2; exit 1; }
mkdir -p "$dest"
tar -xzf "$tarball" -C "$work" data/meshes
cp "$work"/data/meshes/*.off "$dest"/
echo "fetched $(ls "$dest" | wc -l) models into $dest"
tetrahedralize
