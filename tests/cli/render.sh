#!/usr/bin/env bash
# `sweetspot render`: a PNG of the requested size from launch flags, every camera, bad input
# -> exit 2 naming the flag, no EGL -> exit 3 with a clear message and no file written.
set -euo pipefail
bin="$1"
fail() { echo "FAIL: $*" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
drive=(--ball-speed 167mph --launch-angle 10.9deg --spin 2686rpm)

# PNG signature and IHDR width/height (big-endian at bytes 16..23).
png_size() { od -An -tu1 -j16 -N8 "$1" | awk '{printf "%d x %d", $1*16777216+$2*65536+$3*256+$4, $5*16777216+$6*65536+$7*256+$8}'; }
is_png() { [ "$(od -An -tx1 -N8 "$1" | tr -d ' \n')" = "89504e470d0a1a0a" ]; }

"$bin" render -o "$tmp/drive.png" "${drive[@]}" --width 320 --height 200 >/dev/null || fail "golf render"
is_png "$tmp/drive.png" || fail "not a PNG"
[ "$(png_size "$tmp/drive.png")" = "320 x 200" ] || fail "size $(png_size "$tmp/drive.png")"
[ "$(stat -c %s "$tmp/drive.png")" -gt 5000 ] || fail "image suspiciously small (blank?)"
ls -A "$tmp" | grep -q '\.tmp' && fail "temporary file left behind"

for cam in behind side top follow; do
  "$bin" render -o "$tmp/$cam.png" "${drive[@]}" --camera "$cam" --width 160 --height 90 >/dev/null || fail "camera $cam"
  [ "$(png_size "$tmp/$cam.png")" = "160 x 90" ] || fail "camera $cam size"
done
"$bin" render -o "$tmp/bb.png" --sport baseball --ball-speed 103mph --launch-angle 28deg --spin 2000rpm \
  --camera side --at 2s --width 200 --height 120 >/dev/null || fail "baseball render"
"$bin" render -o "$tmp/bb2.png" --sport baseball --ball-speed 103mph --launch-angle 28deg --spin 2000rpm \
  --camera side --at 2000ms --width 200 --height 120 >/dev/null || fail "--at 2000ms"
cmp -s "$tmp/bb.png" "$tmp/bb2.png" || fail "--at 2s and --at 2000ms differ"
cmp -s "$tmp/side.png" "$tmp/bb.png" && fail "golf and baseball images identical"

"$bin" render -o "$tmp/msaa.png" "${drive[@]}" --width 320 --height 200 --msaa 4 >/dev/null || fail "--msaa 4"

# The same command twice gives the same image (deterministic scene and rasteriser).
"$bin" render -o "$tmp/again.png" "${drive[@]}" --width 320 --height 200 >/dev/null
cmp -s "$tmp/drive.png" "$tmp/again.png" || fail "repeated render differs"

expect_exit() {  # code, text the message must contain, args...
  local code="$1" text="$2"; shift 2
  set +e; msg=$("$bin" render "$@" 2>&1); rc=$?; set -e
  [ "$rc" -eq "$code" ] || fail "exit $rc (wanted $code) for: $* -- $msg"
  echo "$msg" | grep -qi -- "$text" || fail "message lacks '$text' for: $* -- $msg"
}
expect_exit 2 "behind, side, top, follow" -o "$tmp/x.png" "${drive[@]}" --camera drone
expect_exit 2 "--width: 8 is out of range" -o "$tmp/x.png" "${drive[@]}" --width 8
expect_exit 2 "outside the shot" -o "$tmp/x.png" "${drive[@]}" --at 99s
expect_exit 2 "missing unit" -o "$tmp/x.png" "${drive[@]}" --at 2
expect_exit 2 "--at" -o "$tmp/x.png" "${drive[@]}" --at 2mph
expect_exit 2 "--msaa" -o "$tmp/x.png" "${drive[@]}" --msaa 3
expect_exit 2 "--ball-speed" -o "$tmp/x.png" --launch-angle 10deg --spin 2000rpm
expect_exit 2 "--launch-angle" -o "$tmp/x.png" --ball-speed 160mph --launch-angle 10 --spin 2000rpm
expect_exit 2 "does not exist" -o "$tmp/no/such/dir/x.png" "${drive[@]}"
expect_exit 2 "output" "${drive[@]}"
[ -e "$tmp/x.png" ] && fail "a failed render left an output file"

# Scenario form: the shot is delivered, flown on its world, and drawn with the club/bat.
"$bin" render golf/7-iron -o "$tmp/scen.png" --width 320 --height 180 --camera side >/dev/null || fail "render golf/7-iron"
[ -s "$tmp/scen.png" ] || fail "scenario render wrote nothing"
"$bin" render baseball/line-drive --set swing.speed=60mph -o "$tmp/bb.png" --width 320 --height 180 >/dev/null \
  || fail "render baseball/line-drive --set"
expect_exit 2 "no-such" -o "$tmp/x.png" golf/no-such
expect_exit 2 "not both" golf/driver -o "$tmp/x.png" "${drive[@]}"
expect_exit 2 "swing.speed" golf/driver -o "$tmp/x.png" --set swing.speed=1e9mph
[ -e "$tmp/x.png" ] && fail "a failed scenario render left an output file"

# No EGL vendor at all (GLVND finds none): exit 3, a sentence, no crash, no file.
set +e
msg=$(__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent/sweetspot-no-egl.json "$bin" render -o "$tmp/noegl.png" "${drive[@]}" 2>&1)
rc=$?
set -e
[ "$rc" -eq 3 ] || fail "no EGL: exit $rc (wanted 3): $msg"
echo "$msg" | grep -q "cannot create an off-screen OpenGL context" || fail "no EGL message: $msg"
[ -e "$tmp/noegl.png" ] && fail "no EGL: file written"

# --video: an H.264 MP4 of the whole shot that ffprobe reads with the frame count and the
# duration the clip's timing gives; the strike slowed 20 times lengthens it by 19 x 50 ms.
command -v ffprobe >/dev/null || fail "ffprobe is needed (scripts/dev installs ffmpeg)"
probe() { ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=codec_name,width,height,nb_read_frames:format=duration -of default=nw=1 "$1"; }
out=$("$bin" render golf/driver --video "$tmp/real.mp4" --width 160 --height 96 --fps 10)
real_frames=$(echo "$out" | sed -n 's/.* \([0-9]*\) frames at 10 fps.*/\1/p')
[ -n "$real_frames" ] || fail "--video: no frame count in: $out"
p=$(probe "$tmp/real.mp4")
echo "$p" | grep -qx "codec_name=h264" || fail "--video: not H.264: $p"
echo "$p" | grep -qx "width=160" && echo "$p" | grep -qx "height=96" || fail "--video: size: $p"
echo "$p" | grep -qx "nb_read_frames=$real_frames" || fail "--video: ffprobe counts other than $real_frames frames: $p"
python3 - "$p" "$real_frames" <<'PY' || fail "--video: duration is not frames / fps: $p"
import sys
d = float([l for l in sys.argv[1].splitlines() if l.startswith("duration=")][0].split("=")[1])
assert abs(d - int(sys.argv[2]) / 10.0) < 0.002, d
PY
out=$("$bin" render golf/driver --video "$tmp/slow.mp4" --width 160 --height 96 --fps 10 --slow-motion 20)
slow_frames=$(echo "$out" | sed -n 's/.* \([0-9]*\) frames at 10 fps.*/\1/p')
[ $((slow_frames - real_frames)) -ge 9 ] && [ $((slow_frames - real_frames)) -le 10 ] \
  || fail "--slow-motion 20 added $((slow_frames - real_frames)) frames (19 x 50 ms at 10 fps: 9.5)"
expect_exit 2 "--at" golf/driver --video "$tmp/x.mp4" --at 1s
expect_exit 2 "even" golf/driver --video "$tmp/x.mp4" --width 161
expect_exit 2 "--fps" golf/driver --video "$tmp/x.mp4" --fps 0
expect_exit 2 "--slow-motion" golf/driver --video "$tmp/x.mp4" --slow-motion 0.5
expect_exit 2 "--video F.mp4" golf/driver
expect_exit 2 "name it FILE.mp4" golf/driver --video "$tmp/x.png"
ln -s same.png "$tmp/same.mp4"  # one file under both names
expect_exit 2 "overwrite each other" golf/driver -o "$tmp/same.png" --video "$tmp/same.mp4"
[ -e "$tmp/same.png" ] && fail "a refused -o/--video pair left a file"
[ -e "$tmp/x.mp4" ] && fail "a refused --video left a file"
echo "render CLI ok"
