#!/usr/bin/env bash
# desktop.lab: penumbra-desktop --snippets FILE on W09P2c. The sheet's answer written out draws the
# frame of the sheet's answer (the app's lab with no file of its own); a file that does not compile
# is printed at its line and the window keeps drawing (with the sheet's answer, the last good
# functions); a saved change is read again while the window runs. Bad input is exit status 2.
# usage: lab.sh PENUMBRA_DESKTOP OUT_DIR
set -uo pipefail
app=$1 out=$2/lab
here=$(cd "$(dirname "$0")" && pwd) data=$(cd "$(dirname "$0")/../data/snippets" && pwd)
rm -rf "$out" && mkdir -p "$out" || exit 1
fail=0
run() {  # run NAME ARGS...: 5 frames at t = 0.6, the visibility view, a screenshot
  local name=$1; shift
  xvfb-run -a -s "-screen 0 1280x1024x24" "$app" --exercise w09p2c --time 0.6 --aov visibility --filter pcf4x4 \
    --size 256x256 --frames 5 --screenshot "$out/$name.png" "$@" > "$out/$name.log" 2> "$out/$name.err"
}
run answer --snippets "$data/answer.glsl" || { echo "FAIL answer: $(cat "$out/answer.err")"; fail=1; }
grep -q "snippets: .*answer.glsl compiled" "$out/answer.log" && echo "ok answer: compiled" ||
  { echo "FAIL answer: not said compiled: $(cat "$out/answer.log")"; fail=1; }
run broken --snippets "$data/broken.glsl" || { echo "FAIL broken: exit non-zero: $(cat "$out/broken.err")"; fail=1; }
if grep -q "snippets: .*broken.glsl:[45]: " "$out/broken.err" || grep -q "snippets: .*broken.glsl: " "$out/broken.err"; then
  echo "ok broken: $(head -1 "$out/broken.err")"
else echo "FAIL broken: no message at its line: $(cat "$out/broken.err")"; fail=1; fi
run no_bias --snippets "$data/no_bias.glsl" || { echo "FAIL no_bias: $(cat "$out/no_bias.err")"; fail=1; }
# The broken file's window draws the sheet's answer: as answer.glsl's frame (a few rounding pixels
# allowed: two programs, GLSL ES 1.00 4.6.1), and not as no_bias.glsl's (the control).
python3 - "$out/answer.png" "$out/broken.png" "$out/no_bias.png" <<'PY' || fail=1
import sys, struct, zlib
sys.path.insert(0, "$here")
def read(path):
    d = open(path, "rb").read(); pos = 8; idat = b""; w = h = 0
    while pos < len(d):
        n, kind = struct.unpack(">I4s", d[pos:pos + 8]); body = d[pos + 8:pos + 8 + n]; pos += 12 + n
        if kind == b"IHDR": w, h, depth, colour = struct.unpack(">IIBB", body[:10])
        elif kind == b"IDAT": idat += body
    ch = {0: 1, 2: 3, 6: 4}[colour]; raw = zlib.decompress(idat); s = w * ch; out = bytearray(); prev = bytearray(s); p = 0
    for y in range(h):
        f = raw[p]; p += 1; line = bytearray(raw[p:p + s]); p += s
        for x in range(s):
            a = line[x - ch] if x >= ch else 0; b = prev[x]; c = prev[x - ch] if x >= ch else 0
            if f == 1: line[x] = (line[x] + a) & 255
            elif f == 2: line[x] = (line[x] + b) & 255
            elif f == 3: line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                q = a + b - c; pa, pb, pc = abs(q - a), abs(q - b), abs(q - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        out += line; prev = line
    return w * h, ch, out
def differ(a, b):
    n, ca, x = read(a); _, cb, y = read(b)
    return 100.0 * sum(1 for i in range(n) if abs(x[i * ca] - y[i * cb]) > 1) / n
same, control = differ(sys.argv[1], sys.argv[2]), differ(sys.argv[1], sys.argv[3])
ok = same <= 0.1 and control > 1.0
print(("ok" if ok else "FAIL") + f" frames: broken vs answer {same:.3f} % of pixels differ, no_bias vs answer {control:.3f} %")
sys.exit(0 if ok else 1)
PY
# A saved change is read while the window runs.
cp "$data/no_bias.glsl" "$out/live.glsl"
xvfb-run -a -s "-screen 0 1280x1024x24" "$app" --exercise w09p2c --frames 10000 --snippets "$out/live.glsl" \
  > "$out/live.log" 2> "$out/live.err" &
pid=$!
for _ in $(seq 1 100); do grep -q "live.glsl compiled" "$out/live.log" && break; sleep 0.2; done
cp "$data/answer.glsl" "$out/live.glsl"
for _ in $(seq 1 100); do grep -q "live.glsl reloaded: compiled" "$out/live.log" && break; sleep 0.2; done
pkill -TERM -P "$pid" 2> /dev/null; kill "$pid" 2> /dev/null; wait "$pid" 2> /dev/null
if grep -q "live.glsl reloaded: compiled" "$out/live.log"; then echo "ok live: reloaded"
else echo "FAIL live: not reloaded: $(cat "$out/live.log" "$out/live.err" | tail -5)"; fail=1; fi
# Bad input: one line, exit status 2, no window needed.
for args in "--snippets $out/missing.glsl" "--exercise volumes --snippets $data/answer.glsl"; do
  err=$(env -u DISPLAY "$app" $args 2>&1 > /dev/null); rc=$?
  if [ $rc -ne 2 ] || [ "$(printf '%s\n' "$err" | wc -l)" -ne 1 ]; then echo "FAIL $args: exit $rc: $err"; fail=1
  else echo "ok $args: $err"; fi
done
exit $fail
