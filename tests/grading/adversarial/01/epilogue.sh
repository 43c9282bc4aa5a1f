# Lab 01's own checks, sourced by ../run.sh after its cases (variables: geolab src build out work lab; functions
# grade_one, same, score_of, task_max, fail). Each starts from the untouched stubs, like the cases.
t5=$(score_of "$out/twin_stub_ref_smoothing.cpp.json")  # the stubs with the reference smoothing.cpp: Task 5's points

# A class: one student includes another's files by path (grade-all grades them side by side). Root only.
if [ "$(id -u)" -eq 0 ]; then
  rm -rf "$out/class"; mkdir -p "$out/class/alice" "$out/class/mallory"
  cp "$src/labs/$lab/src/"*.cpp "$out/class/alice/"; cp "$src/solutions/$lab/src/smoothing.cpp" "$out/class/alice/"
  cp "$src/labs/$lab/src/"*.cpp "$out/class/mallory/"
  cat >"$out/class/mallory/smoothing.cpp" <<EOF
// mallory's smoothing.cpp: alice's, by path, when the compiler can see it
#if __has_include("$out/class/alice/smoothing.cpp")
#include "$out/class/alice/smoothing.cpp"
#else
#include "geolab/halfedge.hpp"
void geolab::halfedge::laplacian_smoothing(Mesh&, double, int) { throw geolab::NotImplemented(__func__); }
#endif
EOF
  "$geolab" grade-all "$out/class" --lab "$lab" --csv "$out/class.csv" --jobs 2 --no-course-build --work-dir "$work" \
    --results "$out/class-results" --timeout 5 --memory-mb 512 >"$out/class.log" 2>&1 || fail "grade-all failed (see $out/class.log)"
  got=$(awk -F, '$1 == "mallory" { print $2 }' "$out/class.csv"); alice=$(awk -F, '$1 == "alice" { print $2 }' "$out/class.csv")
  if same "$got" 0 && same "$alice" "$t5"; then echo "ok   01/other_student: mallory $got (honest: 0), alice $alice"
  else fail "01/other_student: mallory scored '$got' (expected 0), alice '$alice' (expected $t5)"; fi
fi

# The uid lease folder made first by another user: never grade as root silently (root only: a private /tmp).
if [ "$(id -u)" -eq 0 ] && command -v unshare >/dev/null; then
  rm -rf "$out/sub_uid_dir"; mkdir -p "$out/sub_uid_dir"; cp "$src/labs/$lab/src/"*.cpp "$out/sub_uid_dir/"
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
    '$geolab' grade --submission '$out/sub_uid_dir' --lab $lab --json '$out/uid_dir.json' --work-dir '$work' \
      --no-course-build --timeout 5 --memory-mb 512 -q" >"$out/uid_dir.log" 2>&1; rc=$?
  got=$(score_of "$out/uid_dir.json")
  if [ $rc -eq 2 ] && same "$got" 0 && grep -q "refusing to grade" "$out/uid_dir.json" && [ ! -e "$build/ADV_UID_PWNED" ]; then
    echo "ok   01/uid_dir_taken: refused (status $rc, score $got), nothing written"
  else fail "01/uid_dir_taken: status $rc, score '$got', $(ls "$build/ADV_UID_PWNED" 2>/dev/null) (expected a refusal, score 0, nothing written)"; fi
  rm -f "$build/ADV_UID_PWNED"
fi

# The wall-clock cap of a whole submission: a stub that sleeps in every test still ends in time, with a report.
start=$(date +%s)
grade_one "$out" "$work" "$lab" cap "$out/sub_sleep_forever" --max-seconds 12
took=$(($(date +%s) - start))
got=$(score_of "$out/cap.json")
if [ $took -le 40 ] && grep -q "wall-clock cap" "$out/cap.json" && same "$got" 0; then
  echo "ok   01/cap: --max-seconds 12 ended in ${took}s with a report (score $got)"
else fail "01/cap: took ${took}s, score '$got' (expected <= 40 s, the cap named, score 0)"; fi

# A symbolic link to the reference is not a submission.
rm -rf "$out/sub_symlink"; mkdir -p "$out/sub_symlink"
ln -sf "$src/solutions/$lab/src/smoothing.cpp" "$out/sub_symlink/smoothing.cpp"
grade_one "$out" "$work" "$lab" symlink "$out/sub_symlink"
got=$(score_of "$out/symlink.json")
same "$got" 0 && grep -q "symbolic link" "$out/symlink.json" && echo "ok   01/symlink: $got, the link is ignored and listed" ||
  fail "01/symlink: scored '$got' (expected 0 with the link listed as ignored)"

# A zip with the files in a sub-folder and extra files: the lab's files are found, the rest listed as ignored.
rm -rf "$out/zipped" "$out/submission.zip"; mkdir -p "$out/zipped/my_lab/src"
cp "$src/labs/$lab/src/"*.cpp "$out/zipped/my_lab/src/"; cp "$src/solutions/$lab/src/smoothing.cpp" "$out/zipped/my_lab/src/"
echo hi >"$out/zipped/my_lab/notes.txt"
(cd "$out/zipped" && zip -qr ../submission.zip my_lab)
grade_one "$out" "$work" "$lab" zip "$out/submission.zip"
got=$(score_of "$out/zip.json")
same "$got" "$t5" && grep -q "notes.txt" "$out/zip.json" && echo "ok   01/zip: $got, notes.txt listed as ignored" ||
  fail "01/zip: scored '$got' (expected $t5 with notes.txt listed as ignored)"

# Forbidden calls: the reference smoothing calls one_ring_vertices; forbidding it for Task 5 zeroes that task.
rm -rf "$out/sub_forbidden"; mkdir -p "$out/sub_forbidden"
cp "$src/labs/$lab/src/"*.cpp "$out/sub_forbidden/"
cp "$src/solutions/$lab/src/smoothing.cpp" "$src/solutions/$lab/src/topology.cpp" "$out/sub_forbidden/"
echo "geolab::halfedge::one_ring_vertices | write the one-ring walk inside smoothing | Task 5: smoothing" >"$out/forbidden.txt"
grade_one "$out" "$work" "$lab" forbidden "$out/sub_forbidden" --forbidden "$out/forbidden.txt"
got=$(score_of "$out/forbidden.json"); t3=$(task_max "$out/forbidden.json" "Task 3")
same "$got" "$t3" && grep -q "smoothing.cpp calls geolab::halfedge::one_ring_vertices" "$out/forbidden.json" &&
  echo "ok   01/forbidden: $got (Task 3 only: Task 5 zeroed), the call named" ||
  fail "01/forbidden: scored '$got' (expected Task 3's $t3)"
