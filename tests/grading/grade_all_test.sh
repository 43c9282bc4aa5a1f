#!/usr/bin/env bash
# Batch grading: three students (the reference; an empty folder, i.e. untouched stubs; a zip that does not
# compile) graded with two jobs into a CSV; a second run grades nobody again; a student whose results are
# incomplete is graded again. Usage: grade_all_test.sh GEOLAB SOURCE_DIR SCRATCH_DIR
set -euo pipefail
geolab=$1; src=$2; scratch=$3
rm -rf "$scratch"; mkdir -p "$scratch/subs/alice" "$scratch/subs/bob" "$scratch/zip/carol"
fail() { echo "FAIL: $*"; exit 1; }
cp "$src"/solutions/01_halfedge/src/*.cpp "$scratch/subs/alice/"
cp "$src"/solutions/01_halfedge/src/smoothing.cpp "$scratch/zip/carol/"
echo "this is not C++;" >>"$scratch/zip/carol/smoothing.cpp"
(cd "$scratch/zip" && zip -qr "$scratch/subs/carol.zip" carol)
run() { "$geolab" grade-all "$scratch/subs" --lab 01 --csv "$scratch/grades.csv" --jobs 2 --no-course-build \
          --work-dir "$scratch/work" --results "$scratch/results"; }
run
cat "$scratch/grades.csv"
head -1 "$scratch/grades.csv" | grep -q "^student,score,max_score,.*,status$" || fail "bad CSV header"
grep -q "^alice,100,100,.*,ok$" "$scratch/grades.csv" || fail "alice (the reference) is not 100 ok"
grep -q "^bob,0,100,.*,ok$" "$scratch/grades.csv" || fail "bob (stubs) is not 0 ok"
grep -q "^carol,0,100,.*,compile error$" "$scratch/grades.csv" || fail "carol is not 0 compile error"
for s in alice bob carol; do
  for f in results.json junit.xml log.txt done.json; do [ -s "$scratch/results/$s/$f" ] || fail "$s: no $f"; done
done
grep -q "error" "$scratch/results/carol/results.json" || fail "carol's results.json lacks the compiler's message"
# Resume: nothing to do; then an interrupted student (no done.json) is graded again, alone.
run 2>"$scratch/second.err"
grep -q "3 already graded, 0 to grade" "$scratch/second.err" || fail "the second run graded again: $(cat "$scratch/second.err")"
rm "$scratch/results/bob/done.json"
run 2>"$scratch/third.err"
grep -q "2 already graded, 1 to grade" "$scratch/third.err" || fail "resuming did not grade exactly bob again"
grep -q "^bob,0,100,.*,ok$" "$scratch/grades.csv" || fail "bob lost his row after resuming"
echo "grade-all: CSV, per-student results and resuming work"
