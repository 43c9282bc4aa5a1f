#!/usr/bin/env bash
# Batch grading: four students (the reference; an empty folder; a zip that does not compile; a corrupt zip)
# graded with two jobs into a CSV, each with one clear status; a second run grades nobody again; a student whose
# results are incomplete, or whose submission changed since, is graded again (resume by content, not by name);
# one submission that does not exist gives one status line and no "0 / ?".
# Usage: grade_all_test.sh GEOLAB SOURCE_DIR SCRATCH_DIR
set -euo pipefail
geolab=$1; src=$2; scratch=$3
rm -rf "$scratch"; mkdir -p "$scratch/subs/alice" "$scratch/subs/bob" "$scratch/zip/carol"
fail() { echo "FAIL: $*"; exit 1; }
cp "$src"/solutions/01_halfedge/src/*.cpp "$scratch/subs/alice/"
cp "$src"/solutions/01_halfedge/src/smoothing.cpp "$scratch/zip/carol/"
echo "this is not C++;" >>"$scratch/zip/carol/smoothing.cpp"
(cd "$scratch/zip" && zip -qr "$scratch/subs/carol.zip" carol)
head -c 300 "$scratch/subs/carol.zip" >"$scratch/subs/dave.zip"   # cut short: not a zip unzip can read
run() { "$geolab" grade-all "$scratch/subs" --lab 01 --csv "$scratch/grades.csv" --jobs 2 --no-course-build \
          --work-dir "$scratch/work" --results "$scratch/results"; }
run
cat "$scratch/grades.csv"
head -1 "$scratch/grades.csv" | grep -q "^student,score,max_score,.*,status$" || fail "bad CSV header"
grep -q "^alice,100,100,.*,ok$" "$scratch/grades.csv" || fail "alice (the reference) is not 100 ok"
grep -q "^bob,0,100,.*,empty submission$" "$scratch/grades.csv" || fail "bob (an empty folder) is not 0 empty submission"
grep -q "^carol,0,100,.*,compile error$" "$scratch/grades.csv" || fail "carol is not 0 compile error"
grep -q "^dave,0,100,.*,unreadable submission$" "$scratch/grades.csv" || fail "dave (a corrupt zip) is not 0 unreadable"
grep -q "^status: unreadable submission: .*dave.zip is not a zip file that can be unpacked" "$scratch/results/dave/log.txt" \
  || fail "dave's log lacks the one status line: $(head -3 "$scratch/results/dave/log.txt")"
grep -q "^status: empty submission: none of the lab's files (build_mesh.cpp, " "$scratch/results/bob/log.txt" \
  || fail "bob's log lacks the one status line: $(head -3 "$scratch/results/bob/log.txt")"
for s in alice bob carol dave; do
  for f in results.json junit.xml log.txt done.json; do [ -s "$scratch/results/$s/$f" ] || fail "$s: no $f"; done
done
grep -q "error" "$scratch/results/carol/results.json" || fail "carol's results.json lacks the compiler's message"
# Resume: nothing to do; then an interrupted student (no done.json) is graded again, alone.
run 2>"$scratch/second.err"
grep -q "4 already graded, 0 to grade" "$scratch/second.err" || fail "the second run graded again: $(cat "$scratch/second.err")"
rm "$scratch/results/bob/done.json"
run 2>"$scratch/third.err"
grep -q "3 already graded, 1 to grade" "$scratch/third.err" || fail "resuming did not grade exactly bob again"
grep -q "^bob,0,100,.*,empty submission$" "$scratch/grades.csv" || fail "bob lost his row after resuming"
# Bob hands in (the reference's) files under the same name: graded again, by content.
cp "$src"/solutions/01_halfedge/src/*.cpp "$scratch/subs/bob/"
run 2>"$scratch/fourth.err"
grep -q "3 already graded, 1 to grade (1 changed since the last run)" "$scratch/fourth.err" \
  || fail "a changed submission was not graded again: $(cat "$scratch/fourth.err")"
grep -q "^bob,100,100,.*,ok$" "$scratch/grades.csv" || fail "bob's new submission is not 100 ok: $(grep ^bob "$scratch/grades.csv")"
# One submission that is not there: one status line, no table, no "0 / ?", exit status 1.
set +e
"$geolab" grade --submission "$scratch/subs/nobody" --lab 01 --no-course-build --work-dir "$scratch/work" \
  >"$scratch/missing.out" 2>&1
rc=$?
set -e
[ $rc -eq 1 ] || fail "a missing submission exits $rc, not 1"
grep -q "^status: not found: .*nobody: no such folder or zip file$" "$scratch/missing.out" || fail "$(cat "$scratch/missing.out")"
grep -q "0 / ?" "$scratch/missing.out" && fail "a missing submission printed 0 / ?"
grep -q "status: ok" "$scratch/missing.out" && fail "a missing submission printed status: ok"
[ "$(grep -c '^status:' "$scratch/missing.out")" -eq 1 ] || fail "more than one status line: $(cat "$scratch/missing.out")"
echo "grade-all: CSV, per-student results, statuses, resuming by content work"
