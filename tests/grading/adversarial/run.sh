#!/usr/bin/env bash
# The grader's adversarial suites (issue 12): hostile submissions, graded through the real `geolab grade
# --submission` path (as root: the full sandbox), must each score exactly what their honest behaviour earns.
# Usage: run.sh GEOLAB SOURCE_DIR BUILD_DIR LAB [LAB...]      (LAB: 01, 02, ...)
#
# A case is a folder NN/<case>/ of the lab it attacks. It holds the lab files it replaces (*.cpp; *.cpp.in with
# @SRC@, @BUILD@ and @OUT@ filled in, and a line @REFERENCE@ replaced by the reference's copy of that file, so that
# a case that twists the reference holds only its twist) and `expect`; optionally `base` ("full": start from the reference; default:
# the untouched stubs, which fail fast), `forbidden.txt` (graded with --forbidden), `leak` (a string results.json
# must not contain), `honest/` (the honest twin's files), `needs_root`. What its honest behaviour earns:
#   stub           the case's files do not do their job: the base with those files left as stubs (0 on the stubs)
#   full           the attack is harmless and the code right: the base with the reference's copy of those files
#   honest         the base with the case's files and then its honest/ files over them (e.g. given code left alone)
#   zero           0: the submission is rejected (a symbol outside the lab's API, an early section, a raw system
#                  call), and the report says why
#   zero_task T    the case's own score with no forbidden list, less what it earned in task T (a forbidden call
#                  zeroes that task), and the call named
#   given          the case without the lab's given files (the grader always takes the course's copy)
#   compile_error  0, status "compile error", the compiler's message in results.json
# An honest twin is graded once per run and shared by the cases that need it. Gradings run ADVERSARIAL_JOBS (2)
# at a time, one test at a time each, in job folders of their own that share one object cache (the reference's
# and the stubs' objects are compiled once). NN/epilogue.sh, when there is one, adds the lab's own checks (lab 01:
# a class graded with grade-all, the uid lease folder made by another user, the wall-clock cap, a symbolic link,
# a zip, a forbidden call). Afterwards: no process of the sandbox uids is left, nothing was written into the
# course tree or /tmp, the course's programs are unchanged, and every results.json is valid.
# ADVERSARIAL_ONLY=regex grades only the matching cases (and skips the epilogues); ADVERSARIAL_OUT=dir writes
# elsewhere than BUILD/adversarial (a non-root run cannot write the build).
set -uo pipefail
geolab=$1; src=$2; build=$3; shift 3
here=$(cd "$(dirname "$0")" && pwd)
jobs=${ADVERSARIAL_JOBS:-2}
root_out=${ADVERSARIAL_OUT:-$build/adversarial}
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }
score_of() { grep -m1 '^  "score"' "$1" 2>/dev/null | sed 's/[^0-9.]//g'; }
max_of() { grep -m1 '^  "max_score"' "$1" 2>/dev/null | sed 's/[^0-9.]//g'; }
same() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a != "" && b != "" && a + 0 == b + 0) }'; }
task_max() {  # task_max RESULTS TASK: the points of TASK's tests in a results.json (written by nlohmann, sorted keys)
  awk -v task="\"$2" '/"max_score":/ { m = $2 + 0 } /"tags": \[/ { t = 1 } t && index($0, task) { s += m } /\]/ { t = 0 }
                      END { print s + 0 }' "$1"
}
task_score() {  # task_score RESULTS TASK: the points TASK's tests earned in a results.json
  awk -v task="\"$2" '/^      "score":/ { g = $2 + 0 } /"tags": \[/ { t = 1 } t && index($0, task) { s += g } /\]/ { t = 0 }
                      END { print s + 0 }' "$1"
}
export GEOLAB_ADVERSARIAL_CANARY=the-graders-environment  # a test that can read it has the grader's environment
rm -f /tmp/geolab_adv_planted.cpp /var/tmp/geolab_adv_planted.cpp /dev/shm/geolab_adv_planted.cpp
suite_start=$(date +%s.%N)

# grade_one OUT WORK LAB NAME DIR [extra args]: writes OUT/NAME.json, NAME.log and NAME.time (seconds, status).
# Picks a free job folder (slot) with flock: at most $jobs gradings of a lab run at once, each in its own folder.
grade_one() {
  local out=$1 work=$2 lab=$3 name=$4 dir=$5; shift 5
  local slot fd start rc
  for ((slot = 0; ; slot = (slot + 1) % jobs)); do
    exec {fd}>"$out/.slot$slot"
    flock -n "$fd" && break
    exec {fd}>&-
    ((slot == jobs - 1)) && sleep 0.2
  done
  start=$(date +%s.%N)
  # A wall-clock cap of its own: a submission that makes the grader run on fails here instead of hanging CI.
  timeout -s KILL 900 "$geolab" grade --submission "$dir" --lab "$lab" --json "$out/$name.json" --work-dir "$work" \
    --job "$slot" --jobs 1 --no-course-build --timeout "${ADV_TIMEOUT:-20}" --memory-mb "${ADV_MEMORY:-2048}" -q "$@" \
    >"$out/$name.log" 2>&1
  rc=$?
  echo "$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.1f", e - s }') $rc" >"$out/$name.time"
  exec {fd}>&-
}

# run_pool FILE: each line "NAME<tab>DIR<tab>extra args..." graded by grade_one, $jobs at a time.
run_pool() {
  local line name dir extra running=0
  while IFS=$'\t' read -r name dir extra; do
    [ -n "$name" ] || continue
    if ((running >= jobs)); then wait -n; running=$((running - 1)); fi
    # shellcheck disable=SC2086
    grade_one "$out" "$work" "$lab" "$name" "$dir" $extra &
    running=$((running + 1))
  done <"$1"
  wait
}

# put FILE DIR: a case's file into a submission folder; a *.cpp.in has @SRC@, @BUILD@ and @OUT@ filled in, and a
# line @REFERENCE@ becomes the reference's copy of that file (a case adds its twist around it).
put() {
  local f=$1 dir=$2 b
  b=$(basename "$f" .in)
  if [[ $f == *.in ]]; then
    awk -v ref="$src/solutions/$lab/src/$b" '$0 == "@REFERENCE@" { while ((getline l < ref) > 0) print l; next } { print }' "$f" |
      sed -e "s|@SRC@|$src|g" -e "s|@BUILD@|$build|g" -e "s|@OUT@|$out|g" >"$dir/$b"
  else cp "$f" "$dir/$b"; fi
}

# make_sub DIR BASE MODE CASEDIR: a submission folder: the base's files (stubs or reference), then per MODE:
# case, nolist (the case's files), stub (the case's files left out: the stub is used), ref (the reference's copy of
# the case's files), honest (the case's files, then its honest/ files over them), given (the case's files, then
# the course's given files over them).
make_sub() {
  local dir=$1 base=$2 mode=$3 case_dir=$4 f b
  rm -rf "$dir"; mkdir -p "$dir"
  if [ "$base" = full ]; then cp "$src/solutions/$lab/src/"*.cpp "$dir/"; else cp "$src/labs/$lab/src/"*.cpp "$dir/"; fi
  for f in "$case_dir"/*.cpp "$case_dir"/*.cpp.in; do
    [ -e "$f" ] || continue
    b=$(basename "$f" .in)
    case $mode in
      case | honest | nolist | given) put "$f" "$dir" ;;
      stub) rm -f "$dir/$b" ;;
      ref) cp "$src/solutions/$lab/src/$b" "$dir/$b" ;;
    esac
  done
  if [ "$mode" = honest ]; then
    for f in "$case_dir"/honest/*.cpp "$case_dir"/honest/*.cpp.in; do [ -e "$f" ] && put "$f" "$dir"; done
  fi
  if [ "$mode" = given ]; then
    for f in $(grep -v '^#' "$src/labs/$lab/given.txt" 2>/dev/null); do cp "$src/labs/$lab/src/$f" "$dir/$f"; done
  fi
}

for nn in "$@"; do
  lab=$(basename "$(ls -d "$src/labs/${nn}"_* | head -1)")
  [ -d "$here/$nn" ] || { fail "no cases for lab $nn in $here/$nn"; continue; }
  out=$root_out/$nn
  work=$out-work  # kept between runs: its object cache makes re-runs faster
  rm -rf "$out"; mkdir -p "$out"
  lab_start=$(date +%s.%N)
  declare -A twin_of=() twin_seen=()
  : >"$out/twins.txt"; : >"$out/cases.txt"
  echo "# no forbidden calls (the honest twin of a zero_task case)" >"$out/no_forbidden_calls.txt"
  cases=()
  for case_dir in "$here/$nn"/*/; do
    name=$(basename "$case_dir")
    [[ $name =~ ${ADVERSARIAL_ONLY:-.} ]] || continue
    if [ -e "$case_dir/needs_root" ] && [ "$(id -u)" -ne 0 ]; then
      echo "skip $nn/$name: the sandbox (own uid, allow-list file system) needs the grader to run as root"; continue
    fi
    expect=$(head -1 "$case_dir/expect" | sed 's/[[:space:]]*$//')
    base=$(cat "$case_dir/base" 2>/dev/null || echo stub)
    extra=""; [ -e "$case_dir/forbidden.txt" ] && extra="--forbidden $case_dir/forbidden.txt"
    make_sub "$out/sub_$name" "$base" case "$case_dir"
    cases+=("$name")
    printf '%s\t%s\t%s\n' "$name" "$out/sub_$name" "$extra" >>"$out/cases.txt"
    # The honest twin, if its score is not known without grading: keyed by what it holds, graded once.
    files=$(cd "$case_dir" && ls *.cpp *.cpp.in 2>/dev/null | sed 's/\.in$//' | sort | tr '\n' ' ')
    case $expect in
      stub) mode=stub ;;
      full) mode=ref ;;
      zero_task*) mode=nolist ;;
      honest) mode=honest ;;
      given) mode=given ;;
      *) mode="" ;;
    esac
    key=""
    if [ "$mode" = honest ] || [ "$mode" = nolist ] || [ "$mode" = given ]; then key="${mode}_$name"
    elif [ "$mode" = stub ] && [ "$base" = stub ]; then key=""  # the untouched stubs: 0
    elif [ "$mode" = ref ] && [ "$base" = full ]; then key=""   # the reference: its maximum
    elif [ -n "$mode" ]; then
      key="twin_${base}_${mode}_$(echo $files | tr ' ' '+')"  # graded without the case's forbidden list
    fi
    twin_of[$name]=$key
    if [ -n "$key" ] && [ -z "${twin_seen[$key]:-}" ]; then
      twin_seen[$key]=1
      make_sub "$out/sub_$key" "$base" "$mode" "$case_dir"
      twin_extra=""; [ "$mode" = nolist ] && twin_extra="--forbidden $out/no_forbidden_calls.txt"
      printf '%s\t%s\t%s\n' "$key" "$out/sub_$key" "$twin_extra" >>"$out/twins.txt"
    fi
  done
  sum_before=$(md5sum "$build/bin/judge_$lab" "$build/bin/test_$lab" | md5sum)
  cat "$out/twins.txt" "$out/cases.txt" >"$out/pool.txt"  # twins first
  run_pool "$out/pool.txt"

  for name in "${cases[@]}"; do
    case_dir=$here/$nn/$name
    expect=$(head -1 "$case_dir/expect" | sed 's/[[:space:]]*$//')
    base=$(cat "$case_dir/base" 2>/dev/null || echo stub)
    json=$out/$name.json
    took=?; rc=?
    [ -e "$out/$name.time" ] && read -r took rc <"$out/$name.time"
    got=$(score_of "$json"); max=$(max_of "$json")
    key=${twin_of[$name]}
    if [ -n "$key" ]; then
      twin=$(score_of "$out/$key.json")
      [ -n "$twin" ] || fail "$nn/$name: its honest twin $key could not be graded (see $out/$key.log)"
    elif [ "$base" = stub ]; then twin=0
    else twin=$max; fi
    case $expect in
      stub | full | honest | given) want=$twin ;;
      zero) want=0
        grep -q 'rejected: ' "$json" || fail "$nn/$name: the report does not say why the submission was rejected" ;;
      zero_task\ *) task=${expect#zero_task }  # the case with no list, less what it earned in the task
        want=$(awk -v f="$twin" -v t="$(task_score "$out/$key.json" "$task")" 'BEGIN { print f - t }')
        grep -q 'forbidden call: ' "$json" || fail "$nn/$name: the forbidden call is not named" ;;
      compile_error) want=0
        grep -q '"output": "status: compile error' "$json" || fail "$nn/$name: status is not 'compile error'"
        grep -q "src/[a-z_]*\.cpp:[0-9]*:[0-9]*: error" "$json" || fail "$nn/$name: the compiler's message is not in results.json" ;;
      *) fail "$nn/$name: unknown expectation '$expect'"; continue ;;
    esac
    [ "$rc" = 0 ] || fail "$nn/$name: geolab exited with $rc (see $out/$name.log)"
    if [ "$expect" != compile_error ] && grep -q '"output": "status: compile error' "$json"; then
      fail "$nn/$name: the case does not compile, so it attacks nothing (see $out/$name.log)"
    fi
    if [ -n "$key" ] && grep -q '"output": "status: compile error' "$out/$key.json"; then
      fail "$nn/$name: its honest twin $key does not compile (see $out/$key.log)"
    fi
    grep -q "verdict not isolated" "$json" && fail "$nn/$name: the report says the verdict is not isolated"
    if [ -e "$case_dir/leak" ] && grep -q "$(cat "$case_dir/leak")" "$json"; then
      fail "$nn/$name: results.json holds what the submission must not see: $(grep -o "$(cat "$case_dir/leak")[^\\\"]*" "$json" | head -5 | tr '\n' ';')"
    fi
    if same "$got" "$want"; then printf 'ok   %s/%-28s %6s (honest: %s = %s) in %ss\n' "$nn" "$name" "$got" "$expect" "$want" "$took"
    else fail "$nn/$name: scored '$got', its honest behaviour earns $want ($expect); see $out/$name.log"; fi
  done

  if [ -z "${ADVERSARIAL_ONLY:-}" ] && [ -e "$here/$nn/epilogue.sh" ]; then
    # shellcheck source=/dev/null
    . "$here/$nn/epilogue.sh"
  fi
  [ "$(md5sum "$build/bin/judge_$lab" "$build/bin/test_$lab" | md5sum)" = "$sum_before" ] ||
    fail "lab $nn: the course's judge or test program changed"
  for j in "$out"/*.json; do "$geolab" gradescope --validate "$j" >/dev/null || fail "$j: not valid Gradescope results"; done
  echo "lab $nn: ${#cases[@]} cases and ${#twin_seen[@]} twins in $(awk -v s="$lab_start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.0f", e - s }') s"
  unset twin_of twin_seen
done

# Nothing left behind, nothing written where it must not be.
sleep 0.2
left=$(ps -eo uid=,pid=,args= | awk '$1 >= 61000 && $1 < 61512' | grep -F -e "$src" -e "$root_out" -e "$build")
[ -z "$left" ] || fail "processes of the sandbox uids are still running:\n$left"
for f in /tmp/geolab_adv_planted.cpp /var/tmp/geolab_adv_planted.cpp /dev/shm/geolab_adv_planted.cpp; do
  [ ! -e "$f" ] || fail "a submission left $f on the host"
done
pwned=$(find "$src" -maxdepth 4 -name PWNED 2>/dev/null | head -5)
[ -z "$pwned" ] || fail "files written by a submission: $pwned"
times >"$root_out/.times"  # (the builtin, in this shell: its second line is the CPU of every grading it waited for)
echo "wall $(awk -v s="$suite_start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.0f", e - s }') s; CPU of the gradings" \
  "(user, sys): $(tail -1 "$root_out/.times")"
if [ $fails -ne 0 ]; then echo "$fails failure(s)"; exit 1; fi
echo "adversarial suite (labs $*): every case scored what its honest behaviour earns"
