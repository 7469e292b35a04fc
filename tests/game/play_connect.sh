#!/usr/bin/env bash
# `connect` in the window under Xvfb: a launch monitor's session (`shot --gspro --session`)
# is sent to the server the window drives from its frame loop; the device's shot replaces
# the meter and plays the round's first stroke; the Launch monitor panel shows it beside our
# impact model; the window closes after N frames and its last frame is checked.
# $1 = sweetspot, $2 = check_screenshot.
set -euo pipefail
bin="$1"; check="$2"
command -v xvfb-run >/dev/null || { echo "xvfb-run is needed (scripts/dev installs xvfb)" >&2; exit 1; }
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
"$bin" shot golf/7-iron --gspro --session "$work/session.jsonl" >/dev/null
cat > "$work/drive.sh" <<'D'
#!/usr/bin/env bash
set -u
bin="$1"; work="$2"
: >"$work/out.txt"  # created before the server's redirections (see tests/cli/connect.sh)
: >"$work/log.txt"
"$bin" connect --port 0 --course links --frames 360 --screenshot "$work/connect.png" >"$work/out.txt" 2>"$work/log.txt" &
pid=$!
port=""
for _ in $(seq 1 150); do
  port=$(sed -n 's/.*listening on 127\.0\.0\.1:\([0-9]*\).*/\1/p' "$work/log.txt"); [ -n "$port" ] && break; sleep 0.2
done
[ -n "$port" ] || { echo "no listening line"; kill $pid; exit 1; }
"$bin" send "$work/session.jsonl" --port "$port" >"$work/replies.txt" 2>&1 || { echo "send failed"; cat "$work/replies.txt"; }
wait $pid
D
chmod +x "$work/drive.sh"
xvfb-run -a -s "-screen 0 1280x800x24 -noreset" "$work/drive.sh" "$bin" "$work" || { cat "$work/log.txt"; exit 1; }
cat "$work/log.txt" "$work/replies.txt"
grep -q '"Code":200' "$work/replies.txt" || { echo "no 200 reply"; exit 1; }
grep -q '"mode":"round"' "$work/out.txt" || { echo "no round line on stdout"; exit 1; }
grep -q '"hole":1' "$work/out.txt" || { echo "the shot did not play hole 1"; exit 1; }
"$check" "$work/connect.png" 1280 800 40
[ -n "${SWEETSPOT_GAME_ARTIFACTS:-}" ] && cp "$work/connect.png" "$SWEETSPOT_GAME_ARTIFACTS/" || true
echo "play connect test passed"
