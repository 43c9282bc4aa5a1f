#!/usr/bin/env bash
# The grader's adversarial suite: each case is lab 01's smoothing.cpp with a twist (tests/grading/adversarial/
# <case>/smoothing.cpp), submitted with the reference for every other file and graded through the real
# `geolab grade --submission` path. A case folder holds the files it replaces (*.cpp; *.cpp.in with @SRC@, @BUILD@
# and @OUT@ filled in), and optionally: `base` ("stub": start from the untouched stubs instead of the reference),
# `forbidden.txt` (graded with --forbidden), `leak` (a string results.json must not contain), `honest/` (the honest
# twin's files). `expect` says what its honest behaviour earns:
#   full           the attack is harmless and the code is right: the full score
#   stub           the code does not do its job: exactly the score of the reference with smoothing.cpp left a stub
#   honest         exactly the score of the reference with the files of honest/ (e.g. given code left alone)
#   zero           0: the submission is rejected (a symbol outside the lab's API, an early section, a raw system call)
#   zero_task T    the full score less the points of task T (a forbidden call zeroes that task)
#   compile_error  score 0, status "compile error", the compiler's message in results.json
#   only_task_N    an honest bug in Task N's file (the case may replace any lab file): it loses points in Task N
#                  and nowhere else (DESIGN.md rule 6: tasks are graded independently)
# Then: a class graded with grade-all (one student includes another's files), the uid lease folder made by another
# user (root only: grading is refused), the wall-clock cap of a whole submission.
# The forge_* cases try to forge the verdict from inside the process that runs the student's code (issue 12):
# record and replay (and the object checks) must leave each exactly its honest score.
# Afterwards: no process of the sandbox uids is left, nothing was written into the course tree, the build or /tmp.
# Usage: run.sh GEOLAB SOURCE_DIR BUILD_DIR
set -uo pipefail
geolab=$1; src=$2; build=$3
here=$(cd "$(dirname "$0")" && pwd)
out=${ADVERSARIAL_OUT:-$build/adversarial}  # ADVERSARIAL_OUT: elsewhere (a non-root run, which cannot write the build)
rm -rf "$out"; mkdir -p "$out"
work=$out-work  # kept between runs: its object cache makes re-runs faster
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }
score_of() { grep -m1 '^  "score"' "$1" | sed 's/[^0-9.]//g'; }
max_of() { grep -m1 '^  "max_score"' "$1" | sed 's/[^0-9.]//g'; }
# lost_by_task FILE N: "points lost in Task N" "points lost in the other tasks" (results.json: each test's
# max_score and score come before its tags, whose last entry is its task)
lost_by_task() {
  awk -v t="\"Task $2:" '/^      "max_score":/ { m = $2 + 0 } /^      "score":/ { s = $2 + 0 }
    /^        "Task [0-9]+:/ { if (index($0, t)) lt += m - s; else lo += m - s } END { printf "%g %g\n", lt, lo }' "$1"
}
same() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a != "" && b != "" && a + 0 == b + 0) }'; }
export GEOLAB_ADVERSARIAL_CANARY=the-graders-environment  # a test that can read it has the grader's environment
rm -f /tmp/geolab_adv_planted.cpp /var/tmp/geolab_adv_planted.cpp /dev/shm/geolab_adv_planted.cpp
task_max() {  # task_max RESULTS TASK: the points of TASK's tests in a results.json (written by nlohmann, sorted keys)
  awk -v task="\"$2\"" '/"max_score":/ { m = $2 + 0 } /"tags": \[/ { t = 1 } t && index($0, task) { s += m } /\]/ { t = 0 }
                        END { print s + 0 }' "$1"
}
grade() {  # grade DIR NAME [extra args]: writes $out/NAME.json and NAME.log
  local dir=$1 name=$2; shift 2
  # A wall-clock cap of its own: a submission that makes the grader run on (per-test limits taken from the
  # student's process, forge_timeout) fails here instead of hanging CI.
  timeout -s KILL 600 "$geolab" grade --submission "$dir" --lab 01 --json "$out/$name.json" --work-dir "$work" --no-course-build \
    --timeout 5 --memory-mb 512 -q "$@" >"$out/$name.log" 2>&1
}
sum_before=$(md5sum "$build/bin/test_01_halfedge" | cut -d' ' -f1)

# The honest twins.
mkdir -p "$out/full" "$out/stub"
cp "$src"/solutions/01_halfedge/src/*.cpp "$out/full/"
cp "$src"/solutions/01_halfedge/src/*.cpp "$out/stub/"; rm "$out/stub/smoothing.cpp"
grade "$out/full" twin_full || fail "grading the reference failed (see $out/twin_full.log)"
grade "$out/stub" twin_stub || fail "grading the reference without smoothing.cpp failed"
full=$(score_of "$out/twin_full.json"); max=$(max_of "$out/twin_full.json"); stub=$(score_of "$out/twin_stub.json")
echo "reference: $full / $max; reference with smoothing.cpp a stub: $stub"
same "$full" "$max" || fail "the reference does not score full marks ($full / $max)"
awk -v a="$stub" -v b="$full" 'BEGIN { exit !(a + 0 < b + 0) }' || fail "stubbing smoothing.cpp costs nothing?"

for case_dir in "$here"/*/; do
  name=$(basename "$case_dir"); expect=$(head -1 "$case_dir/expect" | sed 's/[[:space:]]*$//')
  [[ $name =~ ${ADVERSARIAL_ONLY:-.} ]] || continue  # ADVERSARIAL_ONLY=regex: only those cases (while developing)
  if [ -e "$case_dir/needs_root" ] && [ "$(id -u)" -ne 0 ]; then
    echo "skip $name: the sandbox (own uid, hidden folders) needs the grader to run as root"; continue
  fi
  sub=$out/sub_$name; mkdir -p "$sub"
  if [ "$(cat "$case_dir/base" 2>/dev/null)" = stub ]; then cp "$src"/labs/01_halfedge/src/*.cpp "$sub/"
  else cp "$src"/solutions/01_halfedge/src/*.cpp "$sub/"; fi
  for f in "$case_dir"/*.cpp; do [ -e "$f" ] && cp "$f" "$sub/"; done
  for f in "$case_dir"/*.cpp.in; do
    [ -e "$f" ] && sed -e "s|@SRC@|$src|g" -e "s|@BUILD@|$build|g" -e "s|@OUT@|$out|g" "$f" >"$sub/$(basename "$f" .in)"
  done
  extra=(); [ -e "$case_dir/forbidden.txt" ] && extra=(--forbidden "$case_dir/forbidden.txt")
  start=$(date +%s.%N)
  grade "$sub" "$name" "${extra[@]}"; rc=$?
  took=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.1f", e - s }')
  got=$(score_of "$out/$name.json" 2>/dev/null)
  case $expect in
    full) want=$full ;;
    stub) want=$stub ;;
    only_task_*) task=${expect#only_task_}
      read -r lost_task lost_other < <(lost_by_task "$out/$name.json" "$task")
      echo "     $name: loses $lost_task points in Task $task and $lost_other in the other tasks"
      [ "$lost_other" = 0 ] || fail "$name: a bug in Task $task costs $lost_other points in other tasks"
      [ "$lost_task" != 0 ] || fail "$name: the bug in Task $task costs nothing (no test sees it?)"
      want=$(awk -v f="$full" -v l="$lost_task" 'BEGIN { print f - l }') ;;
    zero) want=0
      grep -q 'rejected: ' "$out/$name.json" || fail "$name: the report does not say why the submission was rejected" ;;
    zero_task\ *) task=${expect#zero_task }; want=$(awk -v f="$full" -v t="$(task_max "$out/twin_full.json" "$task")" 'BEGIN { print f - t }')
      grep -q 'forbidden call: ' "$out/$name.json" || fail "$name: the forbidden call is not named" ;;
    honest)
      mkdir -p "$out/honest_$name"; cp "$src"/solutions/01_halfedge/src/*.cpp "$out/honest_$name/"
      cp "$case_dir"/honest/*.cpp "$out/honest_$name/"
      grade "$out/honest_$name" "honest_$name" "${extra[@]}"; want=$(score_of "$out/honest_$name.json") ;;
    compile_error) want=0
      grep -q '"output": "status: compile error' "$out/$name.json" || fail "$name: status is not 'compile error'"
      grep -q 'smoothing.cpp:[0-9]*:[0-9]*: error' "$out/$name.json" || fail "$name: the compiler's message is not in results.json" ;;
    *) fail "$name: unknown expectation '$expect'"; continue ;;
  esac
  [ $rc -eq 0 ] || fail "$name: geolab exited with $rc (see $out/$name.log)"
  if [ -e "$case_dir/leak" ] && grep -q "$(cat "$case_dir/leak")" "$out/$name.json"; then
    fail "$name: results.json holds what the submission must not see: $(grep -o "$(cat "$case_dir/leak")[^\\\"]*" "$out/$name.json" | head -5 | tr '\n' ';')"
  fi
  if same "$got" "$want"; then echo "ok   $name: $got (expected $expect = $want) in ${took}s"
  else fail "$name: scored '$got', its honest behaviour earns $want ($expect); see $out/$name.log"; fi
done

if [ -n "${ADVERSARIAL_ONLY:-}" ]; then echo "(ADVERSARIAL_ONLY: the class, uid folder and cap checks skipped)"
else
# A class: one student includes another's files by path (grade-all grades them side by side). Root only.
if [ "$(id -u)" -eq 0 ]; then
mkdir -p "$out/class/alice" "$out/class/mallory"
cp "$src"/solutions/01_halfedge/src/*.cpp "$out/class/alice/"
cp "$src"/solutions/01_halfedge/src/*.cpp "$out/class/mallory/"
cat >"$out/class/mallory/smoothing.cpp" <<EOF
// mallory's smoothing.cpp: alice's, by path, when the compiler can see it
#if __has_include("$out/class/alice/smoothing.cpp")
#include "$out/class/alice/smoothing.cpp"
#else
#include "geolab/halfedge.hpp"
void geolab::halfedge::laplacian_smoothing(Mesh&, double, int) { throw geolab::NotImplemented(__func__); }
#endif
EOF
"$geolab" grade-all "$out/class" --lab 01 --csv "$out/class.csv" --jobs 2 --no-course-build --work-dir "$work" \
  --results "$out/class-results" --timeout 5 --memory-mb 512 >"$out/class.log" 2>&1 || fail "grade-all failed (see $out/class.log)"
got=$(awk -F, '$1 == "mallory" { print $2 }' "$out/class.csv"); alice=$(awk -F, '$1 == "alice" { print $2 }' "$out/class.csv")
if same "$got" "$stub" && same "$alice" "$full"; then echo "ok   other_student: mallory $got (expected stub = $stub), alice $alice"
else fail "other_student: mallory scored '$got' (expected $stub), alice '$alice' (expected $full)"; fi
fi

# The uid lease folder made first by another user: never grade as root silently (root only: a private /tmp).
if [ "$(id -u)" -eq 0 ] && command -v unshare >/dev/null; then
  mkdir -p "$out/sub_uid_dir"; cp "$src"/solutions/01_halfedge/src/*.cpp "$out/sub_uid_dir/"
  cat >"$out/sub_uid_dir/smoothing.cpp" <<EOF
// A stub whose static initializer (every test program start) writes into the build: as root it could.
#include <fstream>
#include "geolab/halfedge.hpp"
static const int vandal = [] { std::ofstream("$build/ADV_UID_PWNED") << "written by a submission\n"; return 0; }();
void geolab::halfedge::laplacian_smoothing(Mesh&, double, int) { throw geolab::NotImplemented(__func__); }
EOF
  # Only the lease folder is replaced (bind-mounted in a private mount namespace): the course tree and the build
  # may themselves live under /tmp (a CI clone), so /tmp as a whole stays.
  mkdir -p /tmp/geolab-sandbox-uids "$out/taken-uids" && chown 12345:12345 "$out/taken-uids"
  unshare -m --propagation private sh -c "mount --bind '$out/taken-uids' /tmp/geolab-sandbox-uids &&
    '$geolab' grade --submission '$out/sub_uid_dir' --lab 01 --json '$out/uid_dir.json' --work-dir '$work' --no-course-build \
      --timeout 5 --memory-mb 512 -q" >"$out/uid_dir.log" 2>&1; rc=$?
  got=$(score_of "$out/uid_dir.json" 2>/dev/null)
  if [ $rc -eq 2 ] && same "$got" 0 && grep -q "refusing to grade" "$out/uid_dir.json" && [ ! -e "$build/ADV_UID_PWNED" ]; then
    echo "ok   uid_dir_taken: refused (status $rc, score $got), nothing written"
  else fail "uid_dir_taken: status $rc, score '$got', $(ls "$build/ADV_UID_PWNED" 2>/dev/null) (expected a refusal, score 0, nothing written)"; fi
  rm -f "$build/ADV_UID_PWNED"
fi

# The wall-clock cap of a whole submission: a stub that sleeps in every test still ends in time, with a report.
start=$(date +%s)
grade "$out/sub_sleep_forever" cap --max-seconds 12
took=$(( $(date +%s) - start ))
got=$(score_of "$out/cap.json")
if [ $took -le 40 ] && grep -q "wall-clock cap" "$out/cap.json" && awk -v g="$got" -v s="$stub" 'BEGIN { exit !(g != "" && g <= s) }'; then
  echo "ok   cap: --max-seconds 12 ended in ${took}s with a report (score $got <= stub $stub)"
else fail "cap: took ${took}s, score '$got' (expected <= 40 s, the cap named, score <= $stub)"; fi

# A symbolic link to the reference is not a submission.
mkdir -p "$out/sub_symlink"; ln -sf "$src/solutions/01_halfedge/src/smoothing.cpp" "$out/sub_symlink/smoothing.cpp"
grade "$out/sub_symlink" symlink
got=$(score_of "$out/symlink.json")
same "$got" 0 && grep -q "symbolic link" "$out/symlink.json" && echo "ok   symlink: $got, the link is ignored and listed" \
  || fail "symlink: scored '$got' (expected 0 with the link listed as ignored)"

# A zip with the files in a sub-folder and extra files: the lab's files are found, the rest listed as ignored.
(cd "$out" && mkdir -p zipped/my_lab/src && cp full/*.cpp zipped/my_lab/src/ && echo hi >zipped/my_lab/notes.txt \
  && cd zipped && zip -qr ../submission.zip my_lab)
grade "$out/submission.zip" zip
got=$(score_of "$out/zip.json")
same "$got" "$full" && grep -q "notes.txt" "$out/zip.json" && echo "ok   zip: $got, notes.txt listed as ignored" \
  || fail "zip: scored '$got' (expected $full with notes.txt listed as ignored)"

# Forbidden calls: the reference's smoothing calls one_ring_vertices; forbidding it for Task 5 zeroes that task.
echo "geolab::halfedge::one_ring_vertices | write the one-ring walk inside smoothing | Task 5: smoothing" >"$out/forbidden.txt"
grade "$out/full" forbidden --forbidden "$out/forbidden.txt"
got=$(score_of "$out/forbidden.json")
same "$got" "$stub" && grep -q "smoothing.cpp calls geolab::halfedge::one_ring_vertices" "$out/forbidden.json" \
  && echo "ok   forbidden: $got, Task 5 zeroed and the call named" || fail "forbidden: scored '$got' (expected $stub)"

fi

# Nothing left behind, nothing written where it must not be.
sleep 0.2
# (Only ours: other graders on the machine share the uid pool.)
left=$(ps -eo uid=,pid=,args= | awk '$1 >= 61000 && $1 < 61512' | grep -F -e "$src" -e "$work" -e "$build")
[ -z "$left" ] || fail "processes of the sandbox uids are still running:\n$left"
pwned=$(find "$src" -maxdepth 4 -name PWNED 2>/dev/null | head -5)
for f in /tmp/geolab_adv_planted.cpp /var/tmp/geolab_adv_planted.cpp /dev/shm/geolab_adv_planted.cpp; do
  [ ! -e "$f" ] || fail "a submission left $f on the host"
done
[ -z "$pwned" ] || fail "files written by a submission: $pwned"
[ "$(md5sum "$build/bin/test_01_halfedge" | cut -d' ' -f1)" = "$sum_before" ] || fail "the course's test program changed"
for j in "$out"/*.json; do "$geolab" gradescope --validate "$j" >/dev/null || fail "$j: not valid Gradescope results"; done

if [ $fails -ne 0 ]; then echo "$fails failure(s)"; exit 1; fi
echo "adversarial suite: all cases scored what their honest behaviour earns"
