#!/usr/bin/env bash
# `sweetspot connect` / `send` / `shot --gspro --session` end to end (DESIGN §10): a server on a
# free port, a session recorded with `shot --gspro --session` and played back with `send`,
# the server's `--record` of it played back to a second server with identical results,
# SIGTERM ending the server with exit 0, and bad input exiting 2 with nothing written.
set -euo pipefail
bin="$1"
fail() { echo "FAIL: $*" >&2; exit 1; }
tmp=$(mktemp -d)
pids=()
cleanup() { for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done; rm -rf "$tmp"; }
trap cleanup EXIT

# Starts a headless server on a free port in the background; sets $port and $server.
start_server() {
  local name="$1"; shift
  # The files exist before the server does: the background child opens its redirections when
  # it is scheduled, and a sed of a file not yet there fails the script under set -e
  # ("sed: can't read .../one.err").
  : >"$tmp/$name.out"
  : >"$tmp/$name.err"
  "$bin" connect --headless --port 0 "$@" >"$tmp/$name.out" 2>"$tmp/$name.err" &
  server=$!
  pids+=("$server")
  port=""
  for _ in $(seq 1 100); do
    port=$(sed -n 's/.*listening on 127\.0\.0\.1:\([0-9]*\).*/\1/p' "$tmp/$name.err")
    [ -n "$port" ] && break
    sleep 0.1
  done
  [ -n "$port" ] || fail "$name: no 'listening on' line: $(cat "$tmp/$name.err")"
}

# A session of three shots numbered by --session (a driver, a 7-iron, a pitching wedge).
for s in golf/driver golf/7-iron golf/pw; do "$bin" shot "$s" --gspro --session "$tmp/session.jsonl" >/dev/null; done
[ "$(wc -l <"$tmp/session.jsonl")" = 3 ] || fail "session has $(wc -l <"$tmp/session.jsonl") lines"
python3 - "$tmp/session.jsonl" <<'PY' || fail "session numbering"
import json, sys
rows = [json.loads(l) for l in open(sys.argv[1])]
assert [r["ShotNumber"] for r in rows] == [1, 2, 3], rows
assert all(r["APIversion"] == "1" and r["ShotDataOptions"]["ContainsBallData"] for r in rows)
PY
"$bin" shot golf/driver --gspro --shot-number 42 | grep -q '"ShotNumber": 42' || fail "--shot-number"

# Play it back to a server that records what it receives.
start_server one --record "$tmp/recorded.jsonl"
"$bin" send "$tmp/session.jsonl" --port "$port" >"$tmp/replies.txt" 2>"$tmp/send.err" || fail "send: $(cat "$tmp/send.err")"
grep -q "3 of 3 messages sent, 3 answered" "$tmp/send.err" || fail "send summary: $(cat "$tmp/send.err")"
[ "$(grep -c '"Code":200' "$tmp/replies.txt")" = 3 ] || fail "replies: $(cat "$tmp/replies.txt")"
grep -q '"Code":201' "$tmp/replies.txt" || fail "no player information: $(cat "$tmp/replies.txt")"
kill -TERM "$server"
rc=0; wait "$server" || rc=$?
[ "$rc" = 0 ] || fail "SIGTERM: exit $rc"
grep -q "SIGTERM: closing" "$tmp/one.err" || fail "no SIGTERM line: $(cat "$tmp/one.err")"
[ "$(wc -l <"$tmp/one.out")" = 3 ] || fail "result lines: $(cat "$tmp/one.out")"
python3 - "$tmp/one.out" "$tmp/session.jsonl" <<'PY' || fail "result lines"
import json, sys
lines = [json.loads(l) for l in open(sys.argv[1])]
sent = [json.loads(l) for l in open(sys.argv[2])]
for got, msg in zip(lines, sent):
    assert got["shot_number"] == msg["ShotNumber"]
    mph = got["launch"]["ball_speed_mps"] / 0.44704
    assert abs(mph - msg["BallData"]["Speed"]) < 1e-6, (mph, msg["BallData"]["Speed"])
    assert got["flight"]["carry_m"] > 50 and got["mode"] == "range"
# The driver carries past the wedge.
assert lines[0]["flight"]["carry_m"] > lines[2]["flight"]["carry_m"] + 50
PY
[ "$(wc -l <"$tmp/recorded.jsonl")" = 3 ] || fail "--record kept $(wc -l <"$tmp/recorded.jsonl") lines"

# The recording played back to a fresh server gives the same result lines, bit for bit.
start_server two --max-shots 3
"$bin" send "$tmp/recorded.jsonl" --port "$port" >/dev/null 2>"$tmp/send2.err" || fail "send recorded: $(cat "$tmp/send2.err")"
rc=0; wait "$server" || rc=$?
[ "$rc" = 0 ] || fail "--max-shots: exit $rc"
cmp -s "$tmp/one.out" "$tmp/two.out" || fail "replay differs: $(diff "$tmp/one.out" "$tmp/two.out" | head -5)"

# A round: the device's shots play the course; the 201 carries the distance to the pin.
# One message for a one-shot server: with more, the server closes with unread messages
# queued, the kernel answers with a reset, and the client may lose the 201 it had not read.
start_server round --course links --max-shots 1
head -1 "$tmp/session.jsonl" >"$tmp/one_shot.jsonl"
"$bin" send "$tmp/one_shot.jsonl" --port "$port" >"$tmp/round_replies.txt" 2>"$tmp/round_send.err" ||
  fail "send to the round: $(cat "$tmp/round_send.err")"
rc=0; wait "$server" || rc=$?
[ "$rc" = 0 ] || fail "round server: exit $rc"
grep -q '"DistanceToTarget"' "$tmp/round_replies.txt" || fail "no DistanceToTarget: $(cat "$tmp/round_replies.txt")"
grep -q '"mode":"round"' "$tmp/round.out" || fail "round line: $(cat "$tmp/round.out")"

# Bad input: exit 2, the flag or file:line named, nothing written.
expect2() {
  local what="$1" pattern="$2"; shift 2
  local rc=0
  "$@" >"$tmp/bad.out" 2>"$tmp/bad.err" || rc=$?
  [ "$rc" = 2 ] || fail "$what: exit $rc (want 2): $(cat "$tmp/bad.err")"
  grep -q -- "$pattern" "$tmp/bad.err" || fail "$what: message '$(cat "$tmp/bad.err")' lacks '$pattern'"
}
expect2 "port range" "--port" "$bin" connect --headless --port 70000
expect2 "bad bind" "--bind" "$bin" connect --headless --port 0 --bind nowhere
expect2 "idle range" "--idle-timeout" "$bin" connect --headless --port 0 --idle-timeout 0.1s
expect2 "unknown course" "--course: .*nowhere" "$bin" connect --headless --port 0 --course nowhere
expect2 "unknown world" "--world: .*moon" "$bin" connect --headless --port 0 --world moon
expect2 "baseball world" "--world: .*baseball" "$bin" connect --headless --port 0 --world ballpark
# The flat range ("none", no world to load) serves its shots.
start_server flat --world none --max-shots 1
head -1 "$tmp/session.jsonl" > "$tmp/one_shot.jsonl"
"$bin" send "$tmp/one_shot.jsonl" --port "$port" >/dev/null 2>"$tmp/flat_send.err" || fail "send to --world none: $(cat "$tmp/flat_send.err")"
rc=0; wait "$server" || rc=$?
[ "$rc" = 0 ] || fail "--world none: exit $rc: $(cat "$tmp/flat.err")"
grep -q '"world": *"none"' "$tmp/flat.out" || fail "--world none: result line: $(cat "$tmp/flat.out")"
printf '%s\n{"ShotNumber":2,"BallData":{"Speed":900},"ShotDataOptions":{"ContainsBallData":true}}\n' \
  "$(head -1 "$tmp/session.jsonl")" >"$tmp/bad_session.jsonl"
expect2 "bad session line" "bad_session.jsonl:2: BallData.Speed" "$bin" send "$tmp/bad_session.jsonl" --port 9
printf 'not json\n' >"$tmp/garbage.jsonl"
expect2 "garbage session" "garbage.jsonl:1" "$bin" send "$tmp/garbage.jsonl" --port 9
expect2 "device session" "not a regular file" "$bin" send /dev/zero --port 9
cp "$tmp/garbage.jsonl" "$tmp/garbage_before.jsonl"
expect2 "--session into a foreign file" "garbage.jsonl:1" "$bin" shot golf/driver --gspro --session "$tmp/garbage.jsonl"
cmp -s "$tmp/garbage.jsonl" "$tmp/garbage_before.jsonl" || fail "--session changed a file it refused"
expect2 "--shot-number range" "--shot-number" "$bin" shot golf/driver --gspro --shot-number 0
# Nothing listening: exit 1 with the reason.
rc=0; "$bin" send "$tmp/session.jsonl" --port 1 --timeout 1s >/dev/null 2>"$tmp/refused.err" || rc=$?
[ "$rc" = 1 ] && grep -q "cannot connect" "$tmp/refused.err" || fail "send to a closed port: rc=$rc $(cat "$tmp/refused.err")"
# A hostile server: its replies carry a terminal's escape sequences (raw ESC in garbage, a C1
# CSI inside a JSON string). `send` prints them escaped, never raw.
python3 - "$tmp/evil.port" <<'PY' &
import socket, sys
s = socket.socket(); s.bind(("127.0.0.1", 0)); s.listen(1)
open(sys.argv[1], "w").write(str(s.getsockname()[1]))
c, _ = s.accept(); c.recv(65536)
c.sendall(b'\x1b]0;owned\x07\x1b[2J{"Code":200,"Message":"\xc2\x9b31mred","Player":null}')
c.close()
PY
pids+=("$!")
for _ in $(seq 1 50); do [ -s "$tmp/evil.port" ] && break; sleep 0.1; done
head -1 "$tmp/session.jsonl" >"$tmp/one_line.jsonl"
"$bin" send "$tmp/one_line.jsonl" --port "$(cat "$tmp/evil.port")" --timeout 2s >"$tmp/evil.out" 2>/dev/null || true
grep -q "Code" "$tmp/evil.out" || fail "send printed no reply from the hostile server: $(cat -v "$tmp/evil.out")"
if LC_ALL=C grep -q "$(printf '\033')" "$tmp/evil.out" || LC_ALL=C grep -q "$(printf '\302\233')" "$tmp/evil.out"; then
  fail "send printed a server's escape sequence raw: $(cat -v "$tmp/evil.out")"
fi
echo "connect: ok"
