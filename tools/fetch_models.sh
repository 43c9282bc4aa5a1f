#!/usr/bin/env bash
# Fetch the classic meshes that Debian's libcgal-demo package ships (bunny00, cow, lion, head, armadillo,
# elephant, ChineseDragon-10kv, ...) into data/models/ without installing the package system-wide.
# Usage: tools/fetch_models.sh [DEST]   (default: <repo>/data/models)
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
dest=${1:-$here/data/models}
if [ -f "$dest/bunny00.off" ]; then echo "models already in $dest"; exit 0; fi
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
