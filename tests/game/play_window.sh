#!/usr/bin/env bash
# The game window under Xvfb: `play --frames N --screenshot` opens a real GLFW window with
# the ImGui panels, runs N frames and saves the window's image; check_screenshot verifies
# size and content. $1 = sweetspot, $2 = check_screenshot.
set -euo pipefail
bin="$1"; check="$2"
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
if ! command -v xvfb-run >/dev/null; then
  echo "xvfb-run missing: install Debian's xvfb (scripts/dev installs it)" >&2; exit 1
fi
for scenario in golf/driver baseball/home-run; do
  out="$work/${scenario//\//-}.png"
  xvfb-run -a -s "-screen 0 1280x800x24 -noreset" "$bin" play "$scenario" --frames 40 --screenshot "$out" \
    > "$work/log.txt" 2>&1 || { cat "$work/log.txt"; exit 1; }
  cat "$work/log.txt"
  grep -q "ms per frame" "$work/log.txt"
  # No sound device here (CI, Xvfb): the window plays silently, with no audio library's
  # complaint on its output.
  if grep -Eq "AL lib|ALSA lib" "$work/log.txt"; then echo "audio errors without a sound device"; exit 1; fi
  "$check" "$out" 1280 800
  [ -n "${SWEETSPOT_GAME_ARTIFACTS:-}" ] && cp "$out" "$SWEETSPOT_GAME_ARTIFACTS/" || true
done
# A small window: one sidebar beside the 3D view, which keeps half the window.
small="$work/small.png"
xvfb-run -a -s "-screen 0 1280x800x24 -noreset" "$bin" play golf/pw --frames 30 --width 800 --height 600 --screenshot "$small" \
  > "$work/log.txt" 2>&1 || { cat "$work/log.txt"; exit 1; }
"$check" "$small" 800 600
[ -n "${SWEETSPOT_GAME_ARTIFACTS:-}" ] && cp "$small" "$SWEETSPOT_GAME_ARTIFACTS/" || true
# A bad scenario fails before any window opens, exit 2.
set +e
xvfb-run -a -s "-noreset" "$bin" play golf/no-such-scenario --frames 2 > "$work/bad.txt" 2>&1
rc=$?
set -e
[ "$rc" -eq 2 ] || { echo "expected exit 2 for an unknown scenario, got $rc"; cat "$work/bad.txt"; exit 1; }
grep -q "no-such-scenario" "$work/bad.txt"
# Headless (no DISPLAY): says so, prints the table, exit 0; it writes no file unless
# --screenshot names one (no sweetspot-play.png dropped in the folder it runs in).
mkdir "$work/quiet"
(cd "$work/quiet" && env -u DISPLAY -u WAYLAND_DISPLAY "$bin" play golf/7-iron > ../headless.txt 2> ../headless.err)
# The fallback is said on stderr; stdout holds only the shot (a refused run prints nothing there).
grep -q "no display" "$work/headless.err"
if grep -q "no display" "$work/headless.txt"; then echo "the fallback note went to stdout"; exit 1; fi
grep -qi "carry" "$work/headless.txt"
grep -q "^image: none" "$work/headless.txt"
[ -z "$(ls -A "$work/quiet")" ] || { echo "headless play wrote files: $(ls -A "$work/quiet")"; exit 1; }
(cd "$work" && env -u DISPLAY -u WAYLAND_DISPLAY "$bin" play golf/7-iron --screenshot shot.png > headless2.txt)
if grep -q "^image: shot.png" "$work/headless2.txt"; then "$check" "$work/shot.png" 1280 800 50; fi
# F10: a clip of the shot on screen, made off-screen beside the game and waited for at the
# end; ffprobe reads it as H.264 at 30 fps.
mkdir "$work/clips"
cat > "$work/clip.sh" <<'D'
#!/usr/bin/env bash
set -u
"$1" play golf/7-iron --frames 150 --mute --shots-dir "$2/clips" > "$2/clip_log.txt" 2>&1 &
pid=$!
wid=""
for _ in $(seq 1 150); do wid=$(xdotool search --name Sweetspot 2>/dev/null | head -1 || true); [ -n "$wid" ] && break; sleep 0.2; done
[ -n "$wid" ] || { echo "no window"; kill $pid; exit 1; }
sleep 1; xdotool windowfocus --sync "$wid" 2>/dev/null || true
xdotool key F10
wait $pid
D
chmod +x "$work/clip.sh"
xvfb-run -a -s "-screen 0 1280x800x24 -noreset" "$work/clip.sh" "$bin" "$work" || { cat "$work/clip_log.txt"; exit 1; }
cat "$work/clip_log.txt"
grep -q "^clip: .*sweetspot_clip_1.mp4 ([0-9]* frames at 30 fps)" "$work/clip_log.txt" || { echo "no clip line"; exit 1; }
frames=$(sed -n 's/^clip: .* (\([0-9]*\) frames at 30 fps)/\1/p' "$work/clip_log.txt")
probe=$(ffprobe -v error -count_frames -show_entries stream=codec_name,nb_read_frames -of default=nw=1 "$work/clips/sweetspot_clip_1.mp4")
echo "$probe" | grep -qx "codec_name=h264" && echo "$probe" | grep -qx "nb_read_frames=$frames" || { echo "clip: $probe"; exit 1; }
echo "play window test passed"
