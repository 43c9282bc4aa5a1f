#!/usr/bin/env bash
# The student release, from scratch: `geolab release --out` writes it (no solutions/, no hidden tests, no
# adversarial cases, one git commit); it configures and builds on its own (only geolab and the labs' test
# programs, unoptimised to keep CI fast); `geolab grade --expect zero` then scores 0 with every graded test failing
# cleanly. Usage: release_test.sh GEOLAB SCRATCH_DIR
set -euo pipefail
geolab=$1; scratch=$2
rm -rf "$scratch"; mkdir -p "$scratch"
rel=$scratch/release
"$geolab" release --out "$rel"
fail() { echo "FAIL: $*"; exit 1; }
[ ! -e "$rel/solutions" ] || fail "the release has solutions/"
[ -z "$(find "$rel" -path "$rel/.git" -prune -o -type d -name hidden -print)" ] || fail "the release has hidden tests"
[ ! -e "$rel/tests/grading/adversarial" ] || fail "the release has the adversarial cases (answers with twists)"
! grep -rIlE '^[[:space:]]*// (BEGIN|END) SOLUTION[[:space:]]*$' "$rel" --exclude-dir=.git --include='*.cpp' \
  --include='*.hpp' | grep . || fail "solution markers in the release"
if command -v git >/dev/null; then
  [ "$(git -C "$rel" rev-list --count HEAD)" = 1 ] || fail "the release's git history is not one commit"
  [ -z "$(git -C "$rel" status --porcelain)" ] || fail "the release's git tree is not clean"
fi
labs=${GEOLAB_RELEASE_TEST_TARGETS:-$(cd "$rel/labs" && for d in [0-9][0-9]_*; do [ -d "$d/include" ] && echo "test_$d"; done)}
cmake -S "$rel" -B "$rel/build" -G Ninja -DGEOLAB_BENCHMARKS=OFF -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_FLAGS=-O0 >/dev/null
# shellcheck disable=SC2086
cmake --build "$rel/build" --target geolab $labs
"$rel/build/bin/geolab" grade ${GEOLAB_RELEASE_TEST_LABS:-} --expect zero --quiet --json "$scratch/results.json" --student-view
! grep -q '"visibility": "after_published"' "$scratch/results.json" || fail "hidden tests were graded in the release"
"$geolab" gradescope --validate "$scratch/results.json"
echo "student release: builds from scratch, stubs score 0 with clean failures"
