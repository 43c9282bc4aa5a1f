#!/usr/bin/env bash
# The grader's adversarial suite: each case is lab 01's smoothing.cpp with a twist (tests/grading/adversarial/
# <case>/smoothing.cpp), submitted with the reference for every other file and graded through the real
# `geolab grade --submission` path. `expect` says what its honest behaviour earns:
#   full           the attack is harmless and the code is right: the full score
#   stub           the code does not do its job: exactly the score of the reference with smoothing.cpp left a stub
#   compile_error  score 0, status "compile error", the compiler's message in results.json
# The forge_* cases try to forge the verdict from inside the process that runs the student's code (issue 12):
# record and replay must leave each exactly its honest score.
# Afterwards: no process of the sandbox uids is left, nothing was written into the course tree or the build.
# Usage: run.sh GEOLAB SOURCE_DIR BUILD_DIR
set -uo pipefail
geolab=$1; src=$2; build=$3
here=$(cd "$(dirname "$0")" && pwd)
out=$build/adversarial
rm -rf "$out"; mkdir -p "$out"
work=$build/adversarial-work  # kept between runs: its object cache makes re-runs faster
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }
score_of() { grep -m1 '^  "score"' "$1" | sed 's/[^0-9.]//g'; }
max_of() { grep -m1 '^  "max_score"' "$1" | sed 's/[^0-9.]//g'; }
same() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a != "" && b != "" && a + 0 == b + 0) }'; }
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
  name=$(basename "$case_dir"); expect=$(tr -d '[:space:]' <"$case_dir/expect")
  if [ -e "$case_dir/needs_root" ] && [ "$(id -u)" -ne 0 ]; then
    echo "skip $name: the sandbox (own uid, hidden folders) needs the grader to run as root"; continue
  fi
  sub=$out/sub_$name; mkdir -p "$sub"
  cp "$src"/solutions/01_halfedge/src/*.cpp "$sub/"; cp "$case_dir"/*.cpp "$sub/"
  start=$(date +%s.%N)
  grade "$sub" "$name"; rc=$?
  took=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.1f", e - s }')
  got=$(score_of "$out/$name.json" 2>/dev/null)
  case $expect in
    full) want=$full ;;
    stub) want=$stub ;;
    compile_error) want=0
      grep -q '"output": "status: compile error' "$out/$name.json" || fail "$name: status is not 'compile error'"
      grep -q 'smoothing.cpp:[0-9]*:[0-9]*: error' "$out/$name.json" || fail "$name: the compiler's message is not in results.json" ;;
    *) fail "$name: unknown expectation '$expect'"; continue ;;
  esac
  [ $rc -eq 0 ] || fail "$name: geolab exited with $rc (see $out/$name.log)"
  if same "$got" "$want"; then echo "ok   $name: $got (expected $expect = $want) in ${took}s"
  else fail "$name: scored '$got', its honest behaviour earns $want ($expect); see $out/$name.log"; fi
done

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

# Nothing left behind, nothing written where it must not be.
sleep 0.2
left=$(ps -eo uid=,pid=,args= | awk '$1 >= 61000 && $1 < 61512')
[ -z "$left" ] || fail "processes of the sandbox uids are still running:\n$left"
pwned=$(find "$src" -maxdepth 4 -name PWNED 2>/dev/null | head -5)
[ -z "$pwned" ] || fail "files written by a submission: $pwned"
[ "$(md5sum "$build/bin/test_01_halfedge" | cut -d' ' -f1)" = "$sum_before" ] || fail "the course's test program changed"
for j in "$out"/*.json; do "$geolab" gradescope --validate "$j" >/dev/null || fail "$j: not valid Gradescope results"; done

if [ $fails -ne 0 ]; then echo "$fails failure(s)"; exit 1; fi
echo "adversarial suite: all cases scored what their honest behaviour earns"
