#!/usr/bin/env bash
# The one main loop under Xvfb, driven by key presses like a player (Debian's xdotool): a
# swing is started in the golf game, Tab takes it back (no stroke: the clicks it never got
# would have played it out on the way back) and cycles through every mode three times and
# back (each mode made on first use, none aborting), Esc pauses, Esc resumes, the caddie
# plays the tee shot, Tab goes round once more, Esc and Q ask (the round is not saved) and Q
# again quits with exit 0. The
# round's state is read from what the golf mode reports on exit.
# $1 = sweetspot, $2 = check_screenshot.
set -euo pipefail
bin="$1"; check="$2"
if ! command -v xvfb-run >/dev/null || ! command -v xdotool >/dev/null; then
  echo "xvfb-run and xdotool are needed (scripts/dev installs xvfb and xdotool)" >&2; exit 1
fi
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
cat > "$work/drive.sh" <<'D'
#!/usr/bin/env bash
set -u
bin="$1"; work="$2"
"$bin" play --mode golf --seed 1 --course links --holes 1 --no-flyover --screenshot "$work/modes.png" > "$work/log.txt" 2>&1 &
pid=$!
wid=""
for _ in $(seq 1 150); do wid=$(xdotool search --name Sweetspot 2>/dev/null | head -1 || true); [ -n "$wid" ] && break; sleep 0.2; done
[ -n "$wid" ] || { echo "no window"; kill $pid; exit 1; }
sleep 2
xdotool windowfocus --sync "$wid" 2>/dev/null || true
# The backswing starts; the first Tab takes it back.
xdotool key space; sleep 0.15
for _ in $(seq 1 12); do xdotool key Tab; sleep 0.1; done  # golf -> range -> baseball -> lab -> golf, three times
kill -0 $pid 2>/dev/null || { echo "the window closed while cycling modes"; exit 1; }
xdotool key Escape; sleep 0.3                     # pauses
xdotool key Escape; sleep 0.3                     # resumes
xdotool key b; sleep 1.0                          # the caddie plays the tee shot
for _ in $(seq 1 4); do xdotool key Tab; sleep 0.5; done   # once more around
xdotool key Escape; sleep 0.3; xdotool key q      # pause, quit: the round is not saved, so it asks
sleep 0.5
kill -0 $pid 2>/dev/null || { echo "one Q quit a round that was not saved"; exit 1; }
xdotool key q                                     # Q again: quit
for _ in $(seq 1 50); do kill -0 $pid 2>/dev/null || break; sleep 0.2; done
kill $pid 2>/dev/null && { echo "the window did not close on Quit"; exit 1; }
wait $pid
D
chmod +x "$work/drive.sh"
set +e
xvfb-run -a -s "-screen 0 1280x800x24 -noreset" "$work/drive.sh" "$bin" "$work"
rc=$?
set -e
cat "$work/log.txt"
[ "$rc" -eq 0 ] || { echo "exit $rc (expected 0 on Quit)"; exit 1; }
if grep -qi "assert" "$work/log.txt"; then echo "an assertion fired"; exit 1; fi
# One swing cancelled, the caddie's tee shot the only stroke: the round kept across 16 Tabs.
grep -Eq "^golf: hole 1 of 1, 1 stroke, 1 swing cancelled" "$work/log.txt" || { echo "the golf round was not kept"; exit 1; }
"$check" "$work/modes.png" 1280 800
[ -n "${SWEETSPOT_GAME_ARTIFACTS:-}" ] && cp "$work/modes.png" "$SWEETSPOT_GAME_ARTIFACTS/" || true
echo "play modes test passed"
