#!/usr/bin/env bash
# The Gradescope autograder of lab 01, simulated locally: `geolab gradescope` writes the zip; it is unpacked into
# $AUTOGRADER_ROOT/source as Gradescope would, the reference is put in $AUTOGRADER_ROOT/submission, run_autograder
# runs (with GEOLAB pointing at this build's program instead of a build made by setup.sh), and results.json is
# checked against Gradescope's format. Usage: gradescope_test.sh GEOLAB SOURCE_DIR SCRATCH_DIR
set -euo pipefail
geolab=$1; src=$2; scratch=$3
rm -rf "$scratch"; mkdir -p "$scratch"
fail() { echo "FAIL: $*"; exit 1; }
"$geolab" gradescope --lab 01 --out "$scratch/autograder.zip"
root=$scratch/autograder
mkdir -p "$root/source" "$root/submission" "$root/results"
(cd "$root/source" && unzip -qq "$scratch/autograder.zip")
for f in setup.sh run_autograder; do
  [ -x "$root/source/$f" ] || fail "$f is missing or not executable at the root of the zip"
  bash -n "$root/source/$f" || fail "$f has a syntax error"
done
[ -d "$root/source/tests/01_halfedge/hidden" ] || fail "the autograder lacks the hidden tests"
grep -q "apt-get install" "$root/source/setup.sh" || fail "setup.sh installs no packages"
cp "$src"/solutions/01_halfedge/src/*.cpp "$root/submission/"
AUTOGRADER_ROOT=$root GEOLAB=$geolab "$root/source/run_autograder" >"$scratch/stdout" 2>&1 || fail "run_autograder failed"
"$geolab" gradescope --validate "$root/results/results.json"
score=$(grep -m1 '^  "score"' "$root/results/results.json" | sed 's/[^0-9.]//g')
max=$(grep -m1 '^  "max_score"' "$root/results/results.json" | sed 's/[^0-9.]//g')
awk -v a="$score" -v b="$max" 'BEGIN { exit !(a > 0 && a == b) }' || fail "the reference scored $score / $max"
grep -q '"visibility": "after_published"' "$root/results/results.json" || fail "no hidden test in results.json"
echo "gradescope: the autograder zip grades the reference $score / $max; results.json is valid"
