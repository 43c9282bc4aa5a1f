#!/usr/bin/env bash
# geolab mutate on the fixture lab 99_tiny: usage: mutate_test.sh GEOLAB FIXTURE_TREE BUILD_DIR
# Checks: the known mutant is killed, the reviewed equivalent (its entry found by its anchor, not its stale line
# number) survives and is reported as equivalent, the weak
# test leaves a survivor, an ill-typed mutant is stillborn, an endless loop is timed out, nothing in a comment
# or a string is mutated, a constexpr table's mutant is killed and one that leaves the table the same is proven
# equivalent, the schema cache is written, --resume skips logged mutants, --rerun-survivors grades the logged
# survivors again, --only FILE:LINE selects one line, array bounds run only with --array-bounds (rebuilt alone), and
# SIGTERM leaves solutions/ as it was.
set -u
geolab=$1 tree=$2 build=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
src=$tree/solutions/99_tiny/src/tiny.cpp
key() { echo "src/tiny.cpp:$1"; }

"$geolab" mutate 99 --source "$tree" --build "$build" --jobs 2 --log "$work/log.jsonl" --json > "$work/summary.json" 2> "$work/err.txt" ||
    { cat "$work/err.txt"; fail "geolab mutate exited $?"; }
cat "$work/summary.json"
summary=$(cat "$work/summary.json")
log=$(cat "$work/log.jsonl")
outcome() { grep -F "\"key\":\"$1\"" "$work/log.jsonl" | grep -o '"outcome":"[^"]*"' | cut -d'"' -f4; }

# the known mutant: clamp_index's `i < 0` -> `i >= 0` answers 0 for 3
[ "$(outcome "$(key '11:11 | < -> >=')")" = killed ] || fail "i < 0 -> i >= 0 is not killed"
# the reviewed equivalent: survives and is listed apart
[ "$(outcome "$(key '11:11 | < -> <=')")" = equivalent ] || fail "the listed equivalent is not reported as equivalent"
grep -q '"equivalents":\["src/tiny.cpp:11:11 | < -> <="\]' <<<"$summary" || fail "summary does not list the equivalent"
# the weak test: twice's x + x -> x - x survives (twice(0) == 0 either way) and is named with its change
[ "$(outcome "$(key '37:14 | + -> -')")" = survived ] || fail "x + x -> x - x did not survive"
grep -q '"survivors":\[[^]]*"src/tiny.cpp:37:14 | + -> -"' <<<"$summary" || fail "summary does not list the survivor"
# hash + std::to_string(i): the minus does not type-check
[ "$(outcome "$(key '31:17 | + -> -')")" = stillborn ] || fail "string - string is not stillborn"
# while (n >= 0) never ends: killed by the per-test time limit
[ "$(outcome "$(key '20:14 | > -> >=')")" = "timed out" ] || fail "the endless loop is not timed out"
# a constexpr table (a relaxed schema computes it at start-up): i = 1 -> 2 leaves squares.v[1] at 0 and is killed;
# i = 1 -> 0 computes 0 * 0 = 0 into v[0], the same table: proven equivalent without running a test
[ "$(outcome "$(key '50:18 | 1 -> 2')")" = killed ] || fail "the table mutant i = 1 -> 2 is not killed"
[ "$(outcome "$(key '50:18 | 1 -> 0')")" = equivalent ] || fail "the table mutant i = 1 -> 0 is not proven equivalent"
grep -F '"key":"src/tiny.cpp:50:18 | 1 -> 0"' "$work/log.jsonl" | grep -q '"proven":true' || fail "i = 1 -> 0 is not marked proven"
grep -q '"proven_equivalent":1' <<<"$summary" || fail "summary does not count the proven equivalent"
# the schema cache: which sites the schema of this text leaves out (a second run compiles no failing schema again)
[ -s "$build/mutate/99_tiny/schema/tiny.excluded" ] || fail "no schema cache written"
# nothing from the comment (line 8) or the raw string (line 9)
if grep -q '"line":8,\|"line":9,' "$work/log.jsonl"; then fail "a comment or string literal was mutated"; fi
grep -q '"stale_equivalents":\[\]' <<<"$summary" || fail "stale equivalents reported"
grep -q '"rate":' <<<"$summary" || fail "no rate"
n=$(wc -l < "$work/log.jsonl")
[ "$n" -ge 15 ] || fail "only $n mutants logged"

# --resume: everything is in the log, nothing runs again
"$geolab" mutate 99 --source "$tree" --build "$build" --log "$work/log.jsonl" --resume --json > "$work/resume.json" 2>/dev/null ||
    fail "--resume failed"
[ "$(wc -l < "$work/log.jsonl")" = "$n" ] || fail "--resume ran logged mutants again"
grep -q '"tests_run":0' "$work/resume.json" || fail "--resume ran tests"

# --rerun-survivors: the logged survivors (twice's x + x -> x - x among them) are graded again, nothing else
survivors=$(grep -c '"outcome":"survived"' "$work/log.jsonl")
"$geolab" mutate 99 --source "$tree" --build "$build" --log "$work/log.jsonl" --resume --rerun-survivors --json \
    > "$work/rerun.json" 2>/dev/null || fail "--rerun-survivors failed"
[ "$(wc -l < "$work/log.jsonl")" = "$((n + survivors))" ] || fail "--rerun-survivors did not grade exactly the $survivors survivors again"
[ "$(tail -n "$survivors" "$work/log.jsonl" | grep -c '"outcome":"survived"')" = "$survivors" ] || fail "--rerun-survivors: a survivor changed"
grep -q '"survivors":\[[^]]*"src/tiny.cpp:37:14 | + -> -"' "$work/rerun.json" || fail "--rerun-survivors lost the survivor"

# --only FILE:LINE: the mutants of that line only
"$geolab" mutate 99 --source "$tree" --build "$build" --only tiny.cpp:11,tiny.cpp:50 --log "$work/only.jsonl" --json > /dev/null 2>&1 ||
    fail "--only tiny.cpp:11,tiny.cpp:50 failed"
[ "$(grep -c . "$work/only.jsonl")" -ge 4 ] || fail "--only tiny.cpp:11,tiny.cpp:50 ran too few mutants"
if grep -v '"line":11,\|"line":50,' "$work/only.jsonl" | grep -q .; then fail "--only FILE:LINE ran mutants of other lines"; fi
"$geolab" mutate 99 --source "$tree" --build "$build" --only tiny.cpp:3 > /dev/null 2> "$work/only_err.txt" &&
    fail "--only on a line without mutants did not fail"
grep -q "no mutant there" "$work/only_err.txt" || fail "--only on a line without mutants: no clear error"

# array bounds (Squares::v[16], line 46): left out and counted by default; --array-bounds rebuilds each alone
if grep -q '"line":46,' "$work/log.jsonl"; then fail "an array bound was mutated without --array-bounds"; fi
grep -q '"array_bound_mutants_left_out":2' <<<"$summary" || fail "summary does not count the 2 array-bound mutants left out"
"$geolab" mutate 99 --source "$tree" --build "$build" --array-bounds --only tiny.cpp:46 --log "$work/bounds.jsonl" --json \
    > "$work/bounds.json" 2>&1 || fail "--array-bounds --only tiny.cpp:46 failed"
[ "$(grep -c '"line":46,.*"mode":"rebuild"\|"mode":"rebuild".*"line":46,' "$work/bounds.jsonl")" = 2 ] ||
    { cat "$work/bounds.jsonl"; fail "--array-bounds: the 2 mutants of v[16] were not rebuilt alone"; }

# SIGTERM in the middle of a run: exit 143, solutions/ byte for byte unchanged, no test left running
before=$(sha256sum "$src" "$tree/solutions/99_tiny/equivalent-mutants.txt")
"$geolab" mutate 99 --source "$tree" --build "$build" --jobs 1 --full --log "$work/term.jsonl" > /dev/null 2> "$work/term.txt" &
pid=$!
for _ in $(seq 1 600); do
    [ -s "$work/term.jsonl" ] && break
    sleep 0.1
done
[ -s "$work/term.jsonl" ] || { kill -9 $pid; fail "no mutant finished within 60 s"; }
kill -TERM $pid
wait $pid
status=$?
cat "$work/term.txt"
[ "$status" = 143 ] || fail "exit status $status after SIGTERM, expected 143"
grep -q "is unchanged" "$work/term.txt" || fail "no restoration check after SIGTERM"
[ "$(sha256sum "$src" "$tree/solutions/99_tiny/equivalent-mutants.txt")" = "$before" ] || fail "solutions/ changed"
sleep 0.5
if pgrep -f "$build/mutate/99_tiny/" > /dev/null; then fail "a mutant's test is still running after SIGTERM"; fi
echo "mutate fixture: all checks passed"
