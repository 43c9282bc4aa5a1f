#!/usr/bin/env bash
# The lecture demos as a student and a lecturer meet them:
#  - `geolab demo NN --help` reaches the demo's own help, which lists its window keys;
#  - zooming onto a half-edge of a flat mesh (--halfedge N with --png, and Z in the window) looks at it face-on;
#  - the demos cap their memory like the grader (same default; a clear message when student code hits the cap);
#  - lab 02's demo cuts a volume mesh open (--png) and its keys step the radial order and the region complex;
#  - the window fits a 1024×768 screen, and the S key writes its screenshot under out/ (xvfb-run, when installed).
# Usage: demo_test.sh BIN_DIR SCRATCH_DIR      (BIN_DIR holds geolab, demo_01_halfedge, demo_02_halfface,
#        demo_09_spherical_dc)
set -euo pipefail
bin=$(cd "$1" && pwd); scratch=$2
rm -rf "$scratch"; mkdir -p "$scratch"; cd "$scratch"
fail() { echo "FAIL: $*"; exit 1; }

# The share of pixels of a PNG (8-bit RGB/RGBA, as geolab writes them) that are not near-white, in percent.
coverage() {
  python3 - "$1" <<'EOF'
import struct, sys, zlib
data = open(sys.argv[1], 'rb').read()
pos, idat, w, h, ch = 8, b'', 0, 0, 4
while pos < len(data):
    n, kind = struct.unpack('>I4s', data[pos:pos + 8])
    body = data[pos + 8:pos + 8 + n]
    if kind == b'IHDR':
        w, h, depth, color = struct.unpack('>IIBB', body[:10])
        ch = {2: 3, 6: 4}[color]
    elif kind == b'IDAT':
        idat += body
    pos += 12 + n
raw, stride, prev, covered = zlib.decompress(idat), w * ch, bytearray(w * ch), 0
for y in range(h):
    f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
    for i in range(stride):
        a = line[i - ch] if i >= ch else 0
        b, c = prev[i], prev[i - ch] if i >= ch else 0
        if f == 1: line[i] = (line[i] + a) & 255
        elif f == 2: line[i] = (line[i] + b) & 255
        elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
        elif f == 4:
            p = a + b - c
            pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
    covered += sum(1 for x in range(w) if min(line[x * ch:x * ch + 3]) < 235)
    prev = line
print(100 * covered // (w * h))
EOF
}
png_size() { python3 -c "import struct,sys; print(*struct.unpack('>II', open(sys.argv[1],'rb').read()[16:24]))" "$1"; }

echo "== geolab demo NN --help is the demo's help, with its window keys"
for lab in 01 02 09 03; do
  "$bin/geolab" demo $lab --help >"help$lab.txt" 2>&1 || { cat "help$lab.txt"; fail "geolab demo $lab --help failed"; }
  grep -q "Window keys" "help$lab.txt" || { cat "help$lab.txt"; fail "geolab demo $lab --help does not list the window keys"; }
  grep -q -- "--png" "help$lab.txt" || fail "geolab demo $lab --help is not the demo's help"
done
grep -q -- "--halfedge" help01.txt || fail "demo 01's help lacks --halfedge"

echo "== --halfedge N --png on a flat mesh: face-on, not an edge-on line"
for mesh in "grid 40" "grid_holes 100"; do
  set -- $mesh
  "$bin/demo_01_halfedge" "$1" --halfedge "$2" --png "he_$1.png" >/dev/null
  c=$(coverage "he_$1.png")
  echo "   $1, half-edge $2: ${c}% of the picture covered"
  [ "$c" -ge 15 ] || fail "zooming onto half-edge $2 of the flat $1 shows only ${c}% of the picture (edge-on?)"
done

echo "== the memory cap: the grader's default, and a clear message when student code hits it"
grader_mb=$("$bin/geolab" grade --help | sed -n 's/.*--memory-mb[^0-9]*\([0-9][0-9]*\).*/\1/p')
for demo in demo_01_halfedge demo_02_halfface demo_09_spherical_dc demo_03_quadrics; do
  demo_mb=$("$bin/$demo" --help | sed -n 's/.*--memory-mb[^0-9]*\([0-9][0-9]*\).*/\1/p')
  [ -n "$grader_mb" ] && [ "$demo_mb" = "$grader_mb" ] || fail "$demo caps memory at '$demo_mb' MiB, the grader at '$grader_mb'"
done
rc=0
"$bin/demo_09_spherical_dc" sphere --level 10 --view compare --memory-mb 1500 --png big.png >mem.log 2>&1 || rc=$?
grep -q "memory limit (1500 MiB) exceeded" mem.log || { tail -5 mem.log; fail "no clear message at the memory cap (status $rc)"; }
[ $rc -eq 1 ] || fail "at the memory cap the demo exited with status $rc (expected 1, a clean error)"

echo "== lab 02: a cut-away of the ball with a torus region, its 2-cells, the cells around an edge"
"$bin/demo_02_halfface" ball_with_torus:6 --png cut02.png >cut02.log || { cat cut02.log; fail "demo 02 --png failed"; }
grep -q "cut at z = 0; radius ratio" cut02.log || { cat cut02.log; fail "demo 02: no cut-away with quality"; }
c=$(coverage cut02.png)
echo "   ball_with_torus:6 cut at z = 0: ${c}% of the picture covered"
[ "$c" -ge 15 ] || fail "demo 02's cut-away covers only ${c}% of the picture"
"$bin/demo_02_halfface" ball_with_torus:6 --view cells2 --png cells02.png >cells02.log
grep -q "2 regions, 2 patches, 0 curves, 0 corners" cells02.log || { cat cells02.log; fail "demo 02: the paper's complex"; }
"$bin/demo_02_halfface" ball_with_torus:6 --view radial --png radial02.png >radial02.log
grep -q "interior edge e[0-9]* (v[0-9]* → v[0-9]*): 6 cells in radial order" radial02.log ||
  { cat radial02.log; fail "demo 02: the radial view"; }

if ! command -v xvfb-run >/dev/null; then
  echo "SKIPPED the window checks: xvfb-run is not installed (tools/bootstrap.sh installs xvfb)"
  exit 77
fi
echo "== the window on a 1024x768 screen: fits; Z zooms face-on; S writes out/screenshots/"
xrun() { timeout 180 xvfb-run -a -s "-screen 0 1024x768x24" "$@"; }
xrun "$bin/demo_01_halfedge" grid --halfedge 40 --frames 3 --keys ZS --screenshot win01.png >win01.log 2>&1 ||
  { cat win01.log; fail "demo 01 in a window failed"; }
xrun "$bin/demo_09_spherical_dc" sphere --level 3 --frames 3 --screenshot win09.png >win09.log 2>&1 ||
  { cat win09.log; fail "demo 09 in a window failed"; }
for f in win01.png win09.png; do
  read -r w h < <(png_size "$f")
  echo "   $f: $w x $h"
  [ "$w" -le 1024 ] && [ "$h" -le 728 ] || fail "$f: the window ($w x $h) does not fit a 1024x768 screen with its title bar"
done
[ -f out/screenshots/geolab_screenshot_1.png ] || { cat win01.log; fail "S wrote no out/screenshots/geolab_screenshot_1.png"; }
[ -z "$(ls geolab_screenshot_* 2>/dev/null)" ] || fail "a screenshot was written outside out/"
c=$(coverage win01.png)
echo "   window, half-edge 40 of the grid after Z: ${c}% covered"
[ "$c" -ge 15 ] || fail "Z on a half-edge of the flat grid shows only ${c}% of the window (edge-on?)"
xrun "$bin/demo_03_quadrics" --frames 3 --keys N3=Q= --screenshot win03.png >win03.log 2>&1 ||
  { cat win03.log; fail "demo 03 in a window failed"; }
grep -q "imaginary ellipsoid .*c=1.1 " win03.log && grep -q "ε₁ = 1.1," win03.log ||
  { cat win03.log; fail "demo 03: N (next example), 3 (select c), = (+0.1), Q (superquadric), = did not do what the help says"; }
xrun "$bin/demo_02_halfface" ball_with_torus:6 --frames 3 --keys RNNBDD --screenshot win02.png >win02.log 2>&1 ||
  { cat win02.log; fail "demo 02 in a window failed"; }
grep -q "step 3 (orange)" win02.log && grep -q "boundary edge e" win02.log && grep -q "2-cells (one colour each)" win02.log ||
  { cat win02.log; fail "demo 02: R (radial view), N N (step), B (boundary edges), D D (2-cells) did not do what the help says"; }
echo "demos: help with keys, face-on half-edge zoom, the grader's memory cap, a window that fits, screenshots in out/"
