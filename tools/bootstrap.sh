#!/usr/bin/env bash
# The first command of the README: install the Debian/Ubuntu packages geolab needs, fetch the models, configure,
# build, and run the main job. In the instructor's tree (with solutions/) the main job grades the reference
# solutions; in the student release it grades the student's own code. Either way it renders every lab's figures
# with the code being built into out/figures/ (never over the handouts' figures in docs/).
# Usage: tools/bootstrap.sh [--no-main-job]      Build folder: ./build   Results: ./out
# GEOLAB_CMAKE_ARGS (optional): extra arguments for the configure step, e.g. "-DGEOLAB_BENCHMARKS=OFF".
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
main_job=1
[ "${1:-}" = "--no-main-job" ] && main_job=0

packages=(build-essential cmake ninja-build pkg-config git
          libglm-dev libglfw3-dev libosmesa6-dev libgl-dev doctest-dev libstb-dev nlohmann-json3-dev
          libcli11-dev libeigen3-dev libgmp-dev libbenchmark-dev libopenmesh-dev libopenvdb-dev libboost-dev libtbb-dev
          xvfb xauth zip unzip python3  # python3, xvfb: the demos test reads PNGs and opens a window
          clang-tools  # clang-query: the grader's source-level check of forbidden calls
          tetgen  # lab 02: tetrahedral meshes of the models (tools/fetch_models.sh)
          libfreetype-dev fonts-dejavu-core  # lab 05: glyph outlines
          ccache)  # compiler cache: rebuilds, and the release/Gradescope builds the tests make, reuse objects
missing=()
for p in "${packages[@]}"; do dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p"); done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "== installing: ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
fi

echo "== fetching the CGAL demo models (data/models)"
tools/fetch_models.sh || echo "   (continuing without models: tests that need them will say so)"

echo "== configuring and building (build/)"
# ccache, when installed (GEOLAB_NO_CCACHE=1: not), with paths relative to this tree: another copy of the course
# (the student release, the Gradescope tree the tests build) compiles the same files to the same cache entries.
launcher=()
if command -v ccache >/dev/null 2>&1 && [ -z "${GEOLAB_NO_CCACHE:-}" ] && [[ $root != *[\;\ ]* ]]; then
  launcher=("-DCMAKE_C_COMPILER_LAUNCHER=/usr/bin/env;CCACHE_BASEDIR=$root;ccache"
            "-DCMAKE_CXX_COMPILER_LAUNCHER=/usr/bin/env;CCACHE_BASEDIR=$root;ccache")
fi
# shellcheck disable=SC2086  # GEOLAB_CMAKE_ARGS is a list of arguments
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" ${GEOLAB_CMAKE_ARGS:-} >/dev/null
cmake --build build -j"$(nproc)"

[ $main_job -eq 1 ] || exit 0
mkdir -p out/grades out/figures
if [ -d solutions ]; then
  echo "== grading the reference solutions"
  ./build/bin/geolab grade --solutions --json out/grades/results.json --junit out/grades/junit.xml -q
  code="the reference solutions"
else
  echo "== grading your code (labs/*/src)"
  ./build/bin/geolab grade --json out/grades/results.json --junit out/grades/junit.xml -q
  code="your code"
fi
echo "== rendering the labs' figures with $code (out/figures)"
for demo in build/bin/demo_*; do
  [ -x "$demo" ] || continue
  lab=$(basename "$demo"); lab=${lab#demo_}
  if [ -d solutions ]; then
    "$demo" --figures "out/figures/$lab"
  else  # unfinished code may fail a figure: say so, and go on
    "$demo" --figures "out/figures/$lab" || echo "   ($lab: some figures could not be rendered with your code; see above)"
  fi
done
echo
echo "Results: out/grades/results.json (Gradescope), out/grades/junit.xml; figures drawn with $code: out/figures/"
if [ -d solutions ]; then
  echo "Next: ctest --test-dir build --output-on-failure"
else
  echo "Next, after each change: cmake --build build && build/bin/geolab grade 01   (or 09, ...)"
fi
