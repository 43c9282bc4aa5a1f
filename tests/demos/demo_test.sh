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
here=$(cd "$(dirname "$0")" && pwd)  # tests/demos (xmouse.py)
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

# ---- every demo, headless (demos 01, 03-09): --help lists its keys and sliders, --png draws something, scripted
# slider moves and drags (--keys) change the status and the picture, and the same demo linked against the untouched
# stubs (demo_NN_name_stubs) runs and says what is not implemented yet ----
# The share of pixels (percent, 1 when some but under 1 %) that differ between two PNGs of one size.
pngdiff() {
  python3 - "$1" "$2" <<'EOF'
import struct, sys, zlib
def rows(path):
    data = open(path, 'rb').read()
    pos, idat = 8, b''
    while pos < len(data):
        n, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b'IHDR':
            w, h, depth, color = struct.unpack('>IIBB', body[:10])
            ch = {2: 3, 6: 4}[color]
        elif kind == b'IDAT':
            idat += body
        pos += 12 + n
    raw, stride, prev, out = zlib.decompress(idat), w * ch, bytearray(w * ch), []
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
        out.append([tuple(line[x * ch:x * ch + 3]) for x in range(w)])
        prev = line
    return out
a, b = rows(sys.argv[1]), rows(sys.argv[2])
if len(a) != len(b) or len(a[0]) != len(b[0]):
    print(100)
else:
    n = len(a) * len(a[0])
    diff = sum(1 for ra, rb in zip(a, b) for pa, pb in zip(ra, rb) if max(abs(x - y) for x, y in zip(pa, pb)) > 12)
    print(100 * diff // n if 100 * diff >= n else (1 if diff else 0))
EOF
}
# An octahedron, so that demo 08 does not need the fetched models.
printf 'OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n' >octahedron.off

# demo | its arguments | a script (sliders, drags) | what its status shows after the script (grep pattern;
# empty: only that it differs from the status before)
demo_cases=(
  "03_quadrics||{c=-0.5}|hyperboloid of one sheet .*c=-0.5 "
  "03_quadrics||{drag 0.5,0.6 0.8,0.6}|real ellipsoid"
  "04_blobby||{T=0.3}|T 0.3, "
  "04_blobby||{kernel=0}|blinn, "
  "05_bezier||{drag -2,2.5,0 0,4,0}|curve, (-3, -1) (0, 4) (1.5, 3)"
  "05_bezier||{t=0.7}|t = 0.7"
  "05_bezier|--mode 5|{u=0.8}|S(0.8, 0.6) = "
  "05_bezier|--mode 5|{drag 1,1,-1 0.6,0.7}|"
  "06_sweeps||{drag -4.5,0,1.5 -4.5,0,3}|control point 2 .green. at"
  "06_sweeps|--view 3|{twist=4}|twist 4 rad"
  "07_csg||{node 4=0}|nodes 1:∩ 2:∪ 3:∪ 4:∪"
  "08_voxelize|--mesh octahedron.off --res 16|{section=0.25}|at 16³: parity, .*section at layer 4"
)
echo "== every demo: --help with its keys, a picture, scripted sliders and drags that change it"
n=0
for c in "${demo_cases[@]}"; do
  IFS='|' read -r lab args script want <<<"$c"
  demo="$bin/demo_$lab"
  n=$((n + 1)); tag="$lab.$n"
  [ -x "$demo" ] || fail "no $demo"
  "$bin/geolab" demo "${lab%%_*}" --help >"help_$tag.txt" 2>&1 || { cat "help_$tag.txt"; fail "geolab demo ${lab%%_*} --help failed"; }
  grep -q "Window keys" "help_$tag.txt" || fail "demo $lab: --help does not list the window keys"
  grep -q "sliders" "help_$tag.txt" || fail "demo $lab: --help does not mention its sliders"
  # shellcheck disable=SC2086
  "$demo" $args --size 640 --png "base_$tag.png" >"base_$tag.log" 2>&1 || { cat "base_$tag.log"; fail "demo $lab --png failed"; }
  # shellcheck disable=SC2086
  "$demo" $args --size 640 --keys "$script" --png "moved_$tag.png" >"moved_$tag.log" 2>&1 ||
    { cat "moved_$tag.log"; fail "demo $lab --keys '$script' --png failed"; }
  after=$(tail -2 "moved_$tag.log" | head -1)
  if [ -n "$want" ]; then
    grep -q -- "$want" <<<"$after" || { cat "moved_$tag.log"; fail "demo $lab: after '$script' the status does not show '$want'"; }
  else
    [ "$after" != "$(tail -2 "base_$tag.log" | head -1)" ] || fail "demo $lab: '$script' left the status as it was: $after"
  fi
  cov=$(coverage "base_$tag.png"); d=$(pngdiff "base_$tag.png" "moved_$tag.png")
  echo "   demo $lab $args: ${cov}% covered; '$script' changed ${d}% of the picture"
  [ "$cov" -ge 2 ] || fail "demo $lab --png draws almost nothing (${cov}%)"
  [ "$d" -ge 1 ] || fail "demo $lab: '$script' did not change the picture"
done
# a slider that is not there, and a bad script: one clear line each, a non-zero status
rc=0; "$bin/demo_03_quadrics" --keys "{zoom=2}" --png x.png >bad.log 2>&1 || rc=$?
[ $rc -eq 1 ] && grep -q "no slider 'zoom' here (sliders: a, b, c, f, g, h, p, q, r, d)" bad.log ||
  { cat bad.log; fail "a slider that does not exist: status $rc, no clear message"; }
rc=0; "$bin/demo_03_quadrics" --keys "{drag 1,2}" --png x.png >bad.log 2>&1 || rc=$?
[ $rc -ne 0 ] && grep -q "drag takes two points" bad.log || { cat bad.log; fail "a bad script: status $rc, no clear message"; }
# --widgets draws the sliders and the status line into the PNG
"$bin/demo_03_quadrics" --size 640 --widgets --png widgets.png >/dev/null
[ "$(pngdiff base_03_quadrics.1.png widgets.png)" -ge 2 ] || fail "--widgets drew no sliders"

echo "== every demo on the untouched stubs: runs, says what is not implemented yet"
stub_cases=(
  "01_halfedge|grid|"
  "02_halfface|ball_with_torus:6|"
  "03_quadrics||{a=0.5}Q{e1=0.3}"
  "04_blobby||{T=0.3}{cells=16}"
  "05_bezier||{drag -2,2.5,0 0,4,0}{t=0.7}BH"
  "05_bezier|--mode 5|{drag -1,-1,2.5 0.5,0.1}{v=0.1}"
  "06_sweeps||{drag -4.5,0,1.5 -4.5,0,3}{samples=20}2"
  "07_csg||{node 1=2}M{resolution=16}"
  "08_voxelize|--mesh octahedron.off|{resolution=16}{section=0.3}V"
  "09_spherical_dc|sphere --level 3|"
)
for c in "${stub_cases[@]}"; do
  IFS='|' read -r lab args script <<<"$c"
  demo="$bin/demo_${lab}_stubs"
  [ -x "$demo" ] || fail "no $demo (the demo linked against the stubs)"
  rc=0
  # shellcheck disable=SC2086
  "$demo" $args --size 640 --keys "$script" --png "stub_$lab.png" >"stub_$lab.log" 2>&1 || rc=$?
  [ $rc -eq 0 ] || { tail -5 "stub_$lab.log"; fail "demo $lab on the stubs failed (status $rc)"; }
  grep -q "not implemented yet" "stub_$lab.log" || { tail -3 "stub_$lab.log"; fail "demo $lab on the stubs does not say what is missing"; }
  [ -s "stub_$lab.png" ] || fail "demo $lab on the stubs wrote no picture"
  echo "   demo $lab on the stubs: $(grep -o 'not implemented yet: [^|]*' "stub_$lab.log" | tail -1 | cut -c1-80)"
done

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
# ---- every demo in a window: a slider moved (or a point dragged), then S; the screenshot shows the change ----
echo "== the windows of demos 03-08: scripted sliders and drags, S screenshots"
window_cases=(
  "03_quadrics||{c=-0.5}S"
  "04_blobby||{T=0.3}S"
  "05_bezier||{t=0.8}{drag -2,2.5,0 0,4,0}S"
  "06_sweeps||{samples=40}{drag -4.5,0,1.5 -4.5,0,3}S"
  "07_csg||{node 4=0}S"
  "08_voxelize|--mesh octahedron.off --res 16|{section=0.25}S"
)
for c in "${window_cases[@]}"; do
  IFS='|' read -r lab args script <<<"$c"
  rm -rf out
  # shellcheck disable=SC2086
  xrun "$bin/demo_$lab" $args --frames 2 --screenshot "win_$lab.png" >"win_$lab.log" 2>&1 ||
    { cat "win_$lab.log"; fail "demo $lab in a window failed"; }
  # shellcheck disable=SC2086
  xrun "$bin/demo_$lab" $args --frames 2 --keys "$script" >"winkeys_$lab.log" 2>&1 ||
    { cat "winkeys_$lab.log"; fail "demo $lab in a window with '$script' failed"; }
  shot=out/screenshots/geolab_screenshot_1.png
  [ -f "$shot" ] || { cat "winkeys_$lab.log"; fail "demo $lab: S wrote no $shot"; }
  read -r w h < <(png_size "$shot")
  d=$(pngdiff "win_$lab.png" "$shot")
  echo "   demo $lab: window $w x $h; '$script' changed ${d}% of it"
  [ "$w" -le 1024 ] && [ "$h" -le 728 ] || fail "demo $lab: the window ($w x $h) does not fit a 1024x768 screen"
  [ "$d" -ge 1 ] || fail "demo $lab: the screenshot after '$script' shows no change"
done
rm -rf out
# ---- a real mouse (XTest events through GLFW) on demo 03's window: drag slider c, press S mid-drag ----
# The layout of slider_rect: rows 26 pixels apart from y = 10 (c is the third: y 62..88); demo 03's one-letter
# labels put the track at x 46..266. A press at x = 150 sets c to about -0.1, the move to x = 100 to about -1.
if python3 -c "import ctypes; ctypes.CDLL('libXtst.so.6')" 2>/dev/null; then
  echo "== a real mouse on demo 03's window: a slider dragged, S pressed mid-drag"
  rm -rf out
  xrun bash -c "timeout 120 '$bin/demo_03_quadrics' >mouse03.log 2>&1 & demo=\$!
    python3 '$here/xmouse.py' mouse03.log 'move 150 75; down; move 130 75; move 100 75; key s; up; wait 1; key Escape'
    wait \$demo" || { cat mouse03.log; fail "demo 03 driven by a real mouse failed"; }
  grep -q "hyperboloid of one sheet .*c=-" mouse03.log || { cat mouse03.log; fail "dragging slider c with the mouse did not make c negative"; }
  [ -f out/screenshots/geolab_screenshot_1.png ] || { cat mouse03.log; fail "S during the drag saved no screenshot"; }
  echo "   $(grep -o 'hyperboloid of one sheet .*c=-[0-9.]*' mouse03.log | tail -1 | sed 's/  (.*|//')"
  rm -rf out
else
  echo "   (no libXtst: the real-mouse check is skipped)"
fi
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
