#!/bin/sh
# Regenerate docs/labs/09_table1.md: Table 1 of J.-H. Kim (2023) (Cartesian vs spherical octree vertex counts) measured
# with lab 09, plus Hausdorff distances, times and mesh checks. Needs the fetched models (tools/fetch_models.sh).
# Usage: tools/table1.sh [BUILD_DIR] [geolab table1 options, e.g. --levels 4,6 --budget 600 --samples 50000]
set -e
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build"
case "$1" in
  ""|-*) ;;
  *) build=$1; shift ;;
esac
cmake --build "$build" --target geolab
exec "$build/bin/geolab" table1 --out "$root/docs/labs/09_table1.md" "$@"
