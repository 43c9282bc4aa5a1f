#!/usr/bin/env bash
# The student release, from scratch, as a student uses it.
#  1. A copy of the course tree's tracked files (a git repository) gets stray untracked files (a screenshot, notes,
#     a scratch solution file); `geolab release --root COPY --out REL` must ship none of them, and no solutions/,
#     hidden tests, adversarial cases or solution markers; one git commit; the student README.
#  2. The two commands of the release's README (its first ```sh block, run exactly as written, in the release):
#     set up and build (tools/bootstrap.sh: builds, grades the student's code, renders the student's figures into
#     out/), then rebuild and grade. Both must succeed on the untouched stubs, score 0, and leave docs/ and every
#     tracked file untouched.
#  3. The release's ctest passes on the stubs; `geolab grade --expect zero`: every graded test fails cleanly.
# To keep CI short the set-up builds without benchmarks (GEOLAB_CMAKE_ARGS, which tools/bootstrap.sh passes to the
# configure step) and with the course build's own flags, so that the compiler cache the course build filled (bootstrap
# uses ccache with paths relative to each tree) serves the release's identical files; the models come from
# SOURCE_DIR/data/models when fetched.
# Usage: release_test.sh GEOLAB SOURCE_DIR SCRATCH_DIR
set -euo pipefail
geolab=$1; src=$2; scratch=$3
rm -rf "$scratch"; mkdir -p "$scratch"
fail() { echo "FAIL: $*"; exit 1; }
step() { echo "== $* ($(date +%T))"; }

step "a copy of the course tree's tracked files, plus stray untracked files"
tree=$scratch/tree
mkdir -p "$tree"
(cd "$src" && git ls-files -z | while IFS= read -r -d '' f; do [ -f "$f" ] && printf '%s\0' "$f"; done |
  xargs -0 cp --parents -t "$tree")
git -C "$tree" init -q && git -C "$tree" add -A &&
  git -C "$tree" -c user.name=t -c user.email=t@localhost commit -q -m tree
echo "my notes: the answer to task 3 is ..." >"$tree/NOTES_instructor.txt"
cp "$tree/docs/labs/figures/01_halfedge/face.png" "$tree/docs/labs/figures/01_halfedge/geolab_screenshot_1.png"
echo "int scratch_answer() { return 42; }" >"$tree/solutions/01_halfedge/src/scratch_answer.cpp"

step "geolab release"
rel=$scratch/release
"$geolab" release --root "$tree" --out "$rel"
for stray in NOTES_instructor.txt docs/labs/figures/01_halfedge/geolab_screenshot_1.png \
             labs/01_halfedge/src/scratch_answer.cpp solutions; do
  [ ! -e "$rel/$stray" ] || fail "the release ships $stray (not tracked by git, or instructors only)"
done
[ -z "$(find "$rel" -path "$rel/.git" -prune -o -type d -name hidden -print)" ] || fail "the release has hidden tests"
[ ! -e "$rel/tests/grading/adversarial" ] || fail "the release has the adversarial cases (answers with twists)"
! grep -rIlE '^[[:space:]]*// (BEGIN|END) SOLUTION[[:space:]]*$' "$rel" --exclude-dir=.git --include='*.cpp' \
  --include='*.hpp' | grep . || fail "solution markers in the release"
[ "$(git -C "$rel" rev-list --count HEAD)" = 1 ] || fail "the release's git history is not one commit"
[ -z "$(git -C "$rel" status --porcelain)" ] || fail "the release's git tree is not clean"
cmp -s "$rel/README.md" "$src/README.md" && fail "the release's README is the instructor's"
grep -q 'docs/labs/01_halfedge.md' "$rel/README.md" || fail "the release's README does not point to the handouts"
[ -x "$rel/tools/bootstrap.sh" ] || fail "tools/bootstrap.sh is not executable in the release"

# The README's two commands: the lines of its first ```sh block.
mapfile -t commands < <(awk '/^```sh$/ { on = 1; next } on && /^```$/ { exit } on && NF' "$rel/README.md")
[ ${#commands[@]} -eq 2 ] || fail "the release's README should give two commands, its first sh block has ${#commands[@]}"
[ -d "$src/data/models" ] && [ ! -e "$rel/data/models" ] && ln -s "$(cd "$src/data/models" && pwd)" "$rel/data/models"
export GEOLAB_CMAKE_ARGS="-DGEOLAB_BENCHMARKS=OFF ${GEOLAB_CMAKE_ARGS:-}"

step "command 1: ${commands[0]}"
(cd "$rel" && bash -c "${commands[0]}") >"$scratch/command1.log" 2>&1 ||
  { tail -40 "$scratch/command1.log"; fail "command 1 failed: ${commands[0]} (log: $scratch/command1.log)"; }
grep -q -- '--solutions' "$scratch/command1.log" && { tail -20 "$scratch/command1.log"; fail "command 1 graded --solutions"; }
[ -s "$rel/out/grades/results.json" ] || fail "command 1 wrote no out/grades/results.json"
"$geolab" gradescope --validate "$rel/out/grades/results.json"
grep -qE '^  "score": 0(\.0)?,' "$rel/out/grades/results.json" || fail "the untouched stubs did not score 0"
for d in "$rel"/labs/[0-9][0-9]_*/; do
  lab=$(basename "$d")
  [ -f "$d/demo.cpp" ] || continue
  ls "$rel/out/figures/$lab"/*.png >/dev/null 2>&1 || fail "command 1 rendered no figure of $lab into out/figures/$lab"
done
# A student following an instructor's line must not overwrite the handouts' figures either.
rc=0; (cd "$rel" && build/bin/demo_01_halfedge --figures docs/labs/figures/01_halfedge) >"$scratch/figs.log" 2>&1 || rc=$?
[ $rc -ne 0 ] && grep -q "inside docs/" "$scratch/figs.log" ||
  { cat "$scratch/figs.log"; fail "the student's demo rendered over the handout's figures in docs/"; }
changed=$(git -C "$rel" status --porcelain --untracked-files=all | grep -v '^?? data/models$' || true)
[ -z "$changed" ] || fail "command 1 changed or added files outside out/ and build/: $changed"

step "command 2: ${commands[1]}"
(cd "$rel" && bash -c "${commands[1]}") >"$scratch/command2.log" 2>&1 ||
  { tail -40 "$scratch/command2.log"; fail "command 2 failed: ${commands[1]}"; }
grep -q 'not implemented' "$scratch/command2.log" || { tail -20 "$scratch/command2.log"; fail "command 2 graded nothing"; }
changed=$(git -C "$rel" status --porcelain --untracked-files=all | grep -v '^?? data/models$' || true)
[ -z "$changed" ] || fail "command 2 changed or added files outside out/ and build/: $changed"

step "the release's ctest, and every graded test failing cleanly on the stubs"
ctest --test-dir "$rel/build" --output-on-failure >"$scratch/ctest.log" 2>&1 ||
  { cat "$scratch/ctest.log"; fail "the release's ctest fails on the untouched stubs"; }
grep -E 'tests passed|tests failed' "$scratch/ctest.log"
"$rel/build/bin/geolab" grade --expect zero --quiet --json "$scratch/results.json" --student-view >/dev/null
! grep -q '"visibility": "after_published"' "$scratch/results.json" || fail "hidden tests were graded in the release"
"$geolab" gradescope --validate "$scratch/results.json"
step "student release: ships only tracked files; its README's two commands and its ctest pass on the stubs"
