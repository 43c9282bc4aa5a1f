#!/bin/sh
# Lab 09's measure of done (issue 21): `geolab contour --json` on models and named implicits, both octrees, and lib's
# check_surface counts: boundary edges, non-manifold edges, non-manifold vertices, self-intersecting face pairs
# (exact), plus vertices, faces, components and χ. One line per run; the exit status is 1 when a run fails or a
# closed-manifold count (boundary, non-manifold edges or vertices) is not 0, or when a smooth closed shape (--smooth
# list) has self-intersecting pairs.
# Usage: tools/contour_manifold.sh [BUILD_DIR] [--levels "4 6"] [--inputs "bunny00 cow ..."] [--smooth "sphere ..."]
# Models need tools/fetch_models.sh. CI (ctest contour_manifold_09) runs levels 4 and 6; level 8 by hand.
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build"
case "${1:-}" in
  ""|-*) ;;
  *) build=$1; shift ;;
esac
levels="4 6"
inputs="bunny00 cow armadillo lion head ChineseDragon-10kv sphere torus box cube rounded_box cylinder box_minus_sphere csg rounded_union blob"
smooth="sphere torus rounded_box cylinder blob bunny00 cow armadillo"
while [ $# -gt 0 ]; do
  case "$1" in
    --levels) levels=$2; shift 2 ;;
    --inputs) inputs=$2; shift 2 ;;
    --smooth) smooth=$2; shift 2 ;;
    *) echo "contour_manifold.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
geolab="$build/bin/geolab"
[ -x "$geolab" ] || { echo "contour_manifold.sh: $geolab not built" >&2; exit 2; }
field() { sed -n "s/^ *\"$1\": \([-0-9.e]*\),*$/\1/p" "$2" | head -n 1; }
status=0
out=$(mktemp)
trap 'rm -f "$out"' EXIT
printf '%-18s %-9s %2s %8s %8s %8s %6s %6s %6s %5s %4s %8s\n' input octree L vertices faces boundary nm_edge nm_vert selfx comps chi seconds
for name in $inputs; do
  for octree in cartesian spherical; do
    for level in $levels; do
      if ! "$geolab" contour "$name" --octree "$octree" --level "$level" --json >"$out" 2>/dev/null; then
        printf '%-18s %-9s %2s  FAILED\n' "$name" "$octree" "$level"
        status=1
        continue
      fi
      b=$(field boundary_edges "$out"); e=$(field non_manifold_edges "$out"); v=$(field non_manifold_vertices "$out")
      x=$(field self_intersecting_pairs "$out")
      secs=$(sed -n 's/^ *"contour": \([0-9.e-]*\),*$/\1/p' "$out" | head -n 1)
      printf '%-18s %-9s %2s %8s %8s %8s %6s %6s %6s %5s %4s %8.3f\n' "$name" "$octree" "$level" \
        "$(sed -n 's/^  "vertices": \([0-9]*\),*$/\1/p' "$out")" "$(sed -n 's/^  "faces": \([0-9]*\),*$/\1/p' "$out")" \
        "$b" "$e" "$v" "$x" "$(field components "$out")" "$(field euler_characteristic "$out")" "$secs"
      [ "$b" = 0 ] && [ "$e" = 0 ] && [ "$v" = 0 ] || status=1
      case " $smooth " in *" $name "*) [ "$x" = 0 ] || status=1 ;; esac
    done
  done
done
exit $status
