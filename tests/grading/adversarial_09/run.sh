#!/usr/bin/env bash
# The grader's adversarial suite for lab 09 (record and replay with callbacks, member functions and out-pointers):
# each case is a hostile poles.cpp (tests/grading/adversarial_09/<case>/poles.cpp) submitted with the untouched
# stubs for every other file (so each grading is short: the other tasks fail at once), through the real
# `geolab grade --submission` path. `expect` says what its honest behaviour earns:
#   stub   the code does not do its job: exactly the score of the untouched stubs (0)
#   zero   0 and the report says why the submission was rejected (a symbol outside the API, an early section)
#   full   the attack is harmless and the code is right: the score of the stubs with the reference poles.cpp
# The forge_* cases are lab 01's (tests/grading/adversarial) aimed at lab 09's Task 11; write_results forges
# the recording itself; change_test_data writes into the test's own data (the judge's arguments then differ).
# Usage: run.sh GEOLAB SOURCE_DIR BUILD_DIR
set -uo pipefail
geolab=$1; src=$2; build=$3
lab=09_spherical_dc
here=$(cd "$(dirname "$0")" && pwd)
out=${ADVERSARIAL_OUT:-$build/adversarial_09}
rm -rf "$out"; mkdir -p "$out"
work=$out-work
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }
score_of() { grep -m1 '^  "score"' "$1" | sed 's/[^0-9.]//g'; }
same() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a != "" && b != "" && a + 0 == b + 0) }'; }
grade() {  # grade DIR NAME: writes $out/NAME.json and NAME.log
  local dir=$1 name=$2; shift 2
  timeout -s KILL 600 "$geolab" grade --submission "$dir" --lab $lab --json "$out/$name.json" --work-dir "$work" \
    --no-course-build --timeout 20 --memory-mb 2048 -q "$@" >"$out/$name.log" 2>&1
}
sum_before=$(md5sum "$build/bin/judge_$lab" | cut -d' ' -f1)

# The honest twins: the stubs, and the stubs with the reference poles.cpp.
mkdir -p "$out/stub" "$out/full"
cp "$src"/labs/$lab/src/*.cpp "$out/stub/"
cp "$src"/labs/$lab/src/*.cpp "$out/full/"; cp "$src"/solutions/$lab/src/poles.cpp "$out/full/"
grade "$out/stub" twin_stub || fail "grading the stubs failed (see $out/twin_stub.log)"
grade "$out/full" twin_full || fail "grading the reference poles.cpp failed (see $out/twin_full.log)"
stub=$(score_of "$out/twin_stub.json"); full=$(score_of "$out/twin_full.json")
echo "stubs: $stub; stubs with the reference poles.cpp: $full"
awk -v a="$stub" -v b="$full" 'BEGIN { exit !(a + 0 < b + 0) }' || fail "the reference poles.cpp earns nothing?"

for case_dir in "$here"/*/; do
  name=$(basename "$case_dir"); expect=$(head -1 "$case_dir/expect" | sed 's/[[:space:]]*$//')
  [[ $name =~ ${ADVERSARIAL_ONLY:-.} ]] || continue
  sub=$out/sub_$name; mkdir -p "$sub"
  cp "$src"/labs/$lab/src/*.cpp "$sub/"; cp "$case_dir"/*.cpp "$sub/"
  start=$(date +%s.%N)
  grade "$sub" "$name"; rc=$?
  took=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.1f", e - s }')
  got=$(score_of "$out/$name.json" 2>/dev/null)
  case $expect in
    stub) want=$stub ;;
    full) want=$full ;;
    zero) want=0
      grep -q 'rejected: ' "$out/$name.json" || fail "$name: the report does not say why the submission was rejected" ;;
    *) fail "$name: unknown expectation '$expect'"; continue ;;
  esac
  [ $rc -eq 0 ] || fail "$name: geolab exited with $rc (see $out/$name.log)"
  grep -q "not isolated" "$out/$name.json" && fail "$name: the report says the verdict is not isolated"
  if same "$got" "$want"; then echo "ok   $name: $got (expected $expect = $want) in ${took}s"
  else fail "$name: scored '$got', its honest behaviour earns $want ($expect); see $out/$name.log"; fi
done

sleep 0.2
left=$(ps -eo uid=,pid=,args= | awk '$1 >= 61000 && $1 < 61512' | grep -F -e "$src" -e "$work" -e "$build")
[ -z "$left" ] || fail "processes of the sandbox uids are still running:\n$left"
[ "$(md5sum "$build/bin/judge_$lab" | cut -d' ' -f1)" = "$sum_before" ] || fail "the course's judge changed"
for j in "$out"/*.json; do "$geolab" gradescope --validate "$j" >/dev/null || fail "$j: not valid Gradescope results"; done
if [ $fails -ne 0 ]; then echo "$fails failure(s)"; exit 1; fi
echo "adversarial suite (lab 09): all cases scored what their honest behaviour earns"
