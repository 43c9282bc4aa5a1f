#!/usr/bin/env bash
# The Gradescope autograder of lab 01, simulated locally. `geolab gradescope` writes the zip; it is unpacked into
# $AUTOGRADER_ROOT/source as Gradescope would. Checks:
#  - the zip carries the models the tests load (data/models/) and setup.sh fetches nothing; setup.sh names only
#    the apt packages checked for Ubuntu 22.04, 24.04 and Debian 12 (docs/instructor.md); every CMakeLists asks
#    for CMake 3.22 at most (Ubuntu 22.04's);
#  - setup.sh's build steps (its apt step skipped: the packages are installed here) build the unpacked tree, which
#    then finds the models in the zip's data/models (GEOLAB_MODELS unset);
#  - run_autograder grades the reference with that build: full score, hidden tests, a valid results.json;
#  - a model missing is a set-up error (setup.sh stops; run_autograder says so and writes no results.json, so
#    no score at all), never a failing test; `geolab gradescope` refuses to write a zip without the models.
# Usage: gradescope_test.sh GEOLAB SOURCE_DIR SCRATCH_DIR
set -euo pipefail
geolab=$1; src=$2; scratch=$3
rm -rf "$scratch"; mkdir -p "$scratch"
fail() { echo "FAIL: $*"; exit 1; }
unset GEOLAB_MODELS GEOLAB

# The packages checked on all three distributions (see docs/instructor.md, "Gradescope").
checked="libeigen3-dev libgmp-dev clang-tools build-essential cmake ninja-build pkg-config git unzip zip libglm-dev libglfw3-dev libosmesa6-dev libgl-dev
         doctest-dev libstb-dev nlohmann-json3-dev libcli11-dev libfreetype-dev fonts-dejavu-core"

"$geolab" gradescope --lab 01 --out "$scratch/autograder.zip"
root=$scratch/autograder
mkdir -p "$root/source" "$root/submission" "$root/results"
(cd "$root/source" && unzip -qq "$scratch/autograder.zip")
for f in setup.sh run_autograder; do
  [ -x "$root/source/$f" ] || fail "$f is missing or not executable at the root of the zip"
  bash -n "$root/source/$f" || fail "$f has a syntax error"
done
[ -d "$root/source/tests/01_halfedge/hidden" ] || fail "the autograder lacks the hidden tests"

echo "== the models travel in the zip; setup.sh fetches none and names only checked packages"
needed=$(grep -rhoE 'load_model\("[^"]+"\)' "$src/tests/01_halfedge" | sed -E 's/.*\("([^"]+)"\)/\1/' | sort -u)
[ -n "$needed" ] || fail "found no load_model(\"...\") in lab 01's tests (the check would be empty)"
for m in $needed; do
  [ -s "$root/source/data/models/$m.off" ] || fail "the zip lacks data/models/$m.off, which lab 01's tests load"
done
! grep -vE '^[[:space:]]*(#|echo)' "$root/source/setup.sh" | grep -qE 'fetch_models|libcgal|apt-get download' ||
  fail "setup.sh fetches models"
pkgs=$(sed -n 's/.*apt-get install -y -qq \(.*\) >\/dev\/null.*/\1/p' "$root/source/setup.sh")
[ -n "$pkgs" ] || fail "setup.sh installs no packages"
for p in $pkgs; do
  grep -qw -- "$p" <<<"$checked" || fail "setup.sh installs $p, which is not among the packages checked on Ubuntu 22.04/24.04 and Debian 12"
done

echo "== every CMakeLists asks for CMake 3.22 at most"
while IFS= read -r f; do
  v=$(sed -n 's/.*cmake_minimum_required(VERSION \([0-9.]*\).*/\1/p' "$f" | head -1)
  [ -z "$v" ] && continue
  [ "$(printf '%s\n3.22\n' "$v" | sort -V | tail -1)" = 3.22 ] || fail "$f needs CMake $v; Ubuntu 22.04 has 3.22"
done < <(find "$root/source" -name CMakeLists.txt -o -name '*.cmake')

echo "== a missing model is a set-up error"
mv "$root/source/data/models/bunny00.off" "$scratch/bunny00.off"
rc=0; AUTOGRADER_ROOT=$root GEOLAB_SKIP_PACKAGES=1 "$root/source/setup.sh" >"$scratch/setup-missing.log" 2>&1 || rc=$?
[ $rc -ne 0 ] && grep -q "SETUP ERROR.*bunny00.off" "$scratch/setup-missing.log" ||
  { cat "$scratch/setup-missing.log"; fail "setup.sh went on without bunny00.off (status $rc)"; }
[ ! -e "$root/source/build" ] || fail "setup.sh built the tree although a model is missing"
cp "$src"/solutions/01_halfedge/src/*.cpp "$root/submission/"
rc=0; AUTOGRADER_ROOT=$root GEOLAB=$geolab "$root/source/run_autograder" >"$scratch/run-missing.log" 2>&1 || rc=$?
[ $rc -ne 0 ] && grep -q "SETUP ERROR" "$scratch/run-missing.log" && grep -q "bunny00.off" "$scratch/run-missing.log" ||
  { cat "$scratch/run-missing.log"; fail "run_autograder graded without bunny00.off (status $rc)"; }
[ ! -e "$root/results/results.json" ] || fail "run_autograder wrote a score although the set-up is broken"
mv "$scratch/bunny00.off" "$root/source/data/models/bunny00.off"
rc=0; GEOLAB_MODELS=$scratch/no-models "$geolab" gradescope --lab 01 --out "$scratch/no-models.zip" >"$scratch/zip-missing.log" 2>&1 || rc=$?
[ $rc -ne 0 ] && grep -q "fetch_models" "$scratch/zip-missing.log" ||
  { cat "$scratch/zip-missing.log"; fail "geolab gradescope wrote a zip without the models the tests load"; }

echo "== setup.sh's build steps in the unpacked tree ($(date +%T))"
# With the course build's flags and ccache (when installed) with paths relative to the unpacked tree, so that the
# objects the course build compiled (tools/bootstrap.sh: ccache relative to its tree) serve the same files here.
if command -v ccache >/dev/null; then
  export CMAKE_C_COMPILER_LAUNCHER=ccache CMAKE_CXX_COMPILER_LAUNCHER=ccache CCACHE_BASEDIR=$root/source
fi
AUTOGRADER_ROOT=$root GEOLAB_SKIP_PACKAGES=1 \
  "$root/source/setup.sh" >"$scratch/setup.log" 2>&1 ||
  { tail -30 "$scratch/setup.log"; fail "setup.sh failed (log: $scratch/setup.log)"; }
[ -x "$root/source/build/bin/geolab" ] || fail "setup.sh did not build geolab"
echo "   built ($(date +%T))"

echo "== run_autograder grades the reference with that build and the zip's models"
AUTOGRADER_ROOT=$root "$root/source/run_autograder" >"$scratch/stdout" 2>&1 || { cat "$scratch/stdout"; fail "run_autograder failed"; }
"$geolab" gradescope --validate "$root/results/results.json"
score=$(grep -m1 '^  "score"' "$root/results/results.json" | sed 's/[^0-9.]//g')
max=$(grep -m1 '^  "max_score"' "$root/results/results.json" | sed 's/[^0-9.]//g')
awk -v a="$score" -v b="$max" 'BEGIN { exit !(a > 0 && a == b) }' ||
  { grep -B2 -A8 '"status": "failed"' "$root/results/results.json" | head -40; fail "the reference scored $score / $max"; }
grep -q '"visibility": "after_published"' "$root/results/results.json" || fail "no hidden test in results.json"
echo "gradescope: the zip carries its models, builds with setup.sh's steps and grades the reference $score / $max;" \
     "a missing model is a set-up error"
