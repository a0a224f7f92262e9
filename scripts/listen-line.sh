#!/usr/bin/env bash
# The long run of listening beside a PLC: stepcom-sim --line 3, pymodbus's RTU client polling
# and writing the simulated controller at 38400 for SECONDS (default 120), stepcomctl listen
# --json on the third pty. Passes when every request the PLC made was heard and paired, every
# write decoded with its key and value, no frame damaged or lost, and the listener's pty sent
# nothing. ctest runs the short version (tst_listenline, 6 s).
#   scripts/listen-line.sh [SECONDS] [BUILD_DIR]
set -uo pipefail
seconds=${1:-120}
build=${2:-build}
here=$(cd "$(dirname "$0")/.." && pwd)
sim=$build/app/stepcom-sim
ctl=$build/app/stepcomctl
for f in "$sim" "$ctl"; do [[ -x $f ]] || { echo "listen-line: $f is not built"; exit 2; }; done
dir=$(mktemp -d)
cleanup() { [[ -n ${simpid-} ]] && kill -INT "$simpid" 2>/dev/null; wait 2>/dev/null; rm -rf "$dir"; }
trap cleanup EXIT
"$sim" --line 3 --link "$dir/line" --no-baud-check --answer-delay 5 >"$dir/sim.out" 2>"$dir/sim.err" &
simpid=$!
for _ in $(seq 100); do [[ -e $dir/line.3 ]] && break; sleep 0.1; done
"$ctl" --port "$dir/line.3" --baud 38400 --json listen --seconds $((seconds + 10)) \
    >"$dir/heard.json" 2>"$dir/listen.err" &
listenpid=$!
for _ in $(seq 100); do grep -q "listening on" "$dir/listen.err" && break; sleep 0.1; done
/usr/bin/python3 "$here/tests/fixtures/plc_master.py" "$dir/line.1" 38400 "$seconds" >"$dir/plc.out"
sleep 1
kill -INT "$listenpid"; wait "$listenpid"
kill -INT "$simpid"; wait "$simpid"; simpid=
requests=$(awk '/^done/ {print $2}' "$dir/plc.out")
errors=$(grep -c '^error' "$dir/plc.out")
writes=$(grep -cE '^write' "$dir/plc.out")
heard_writes=$(grep -c '"kind":"write"' "$dir/heard.json")
pairs=$(sed -nE 's/.* ([0-9]+) pairs.*/\1/p' "$dir/listen.err")
summary=$(head -n 2 "$dir/listen.err" | tail -n 1)
sent=$(sed -nE 's/line 3 sent ([0-9]+) bytes/\1/p' "$dir/sim.err")
echo "PLC: $requests requests ($errors failed, $writes writes) in $seconds s at 38400"
echo "listener: $summary"
echo "listener's pty sent: $sent bytes"
ok=1
[[ $errors -eq 0 ]] || { echo "FAIL: the PLC's requests failed"; ok=0; }
[[ $pairs -eq $requests ]] || { echo "FAIL: $pairs pairs heard for $requests requests"; ok=0; }
[[ $heard_writes -eq $writes ]] || { echo "FAIL: $heard_writes writes heard for $writes"; ok=0; }
grep -q " 0 unanswered, 0 exceptions, 0 CRC errors" "$dir/listen.err" ||
    { echo "FAIL: frames damaged or unanswered"; ok=0; }
[[ $sent == 0 ]] || { echo "FAIL: the listener sent $sent bytes"; ok=0; }
[[ $ok -eq 1 ]] && echo "listen-line: 0 frames lost over $seconds s" && exit 0
exit 1
