#!/usr/bin/env bash
# The window listening beside another master, walked as a screen reader reads it: a line of
# three pseudo-terminals from stepcom-sim (the simulated controller on it), pymodbus's client
# polling it as a PLC on the first (tests/fixtures/plc_master.py), the window on the second with
# --listen, and a11y-walk.py over every page (nothing cut, every control named, the
# E-STOP showing). Usage: listen-walk.sh PYTHON3 STEPCOM-SIM STEPCOM [a11y-walk options]
set -uo pipefail
python=$1 sim=$2 stepcom=$3
shift 3
if ! "$python" -c 'import pymodbus.client' 2>/dev/null; then
    echo "listen-walk: SKIPPED, python3-pymodbus is missing (scripts/deps.sh --test installs it)"
    exit 77
fi
dir=$(mktemp -d)
"$sim" --line 3 --link "$dir/line" >"$dir/sim.log" 2>&1 &
simpid=$!
plcpid=
trap 'kill $simpid $plcpid 2>/dev/null; wait 2>/dev/null; rm -rf "$dir"' EXIT
for _ in $(seq 100); do
    [[ -e $dir/line.3 ]] && break
    sleep 0.1
done
[[ -e $dir/line.3 ]] || { echo "listen-walk: stepcom-sim made no line"; cat "$dir/sim.log"; exit 1; }
# The PLC polls for at most as long as a walk may take; the walk waits for what it hears.
"$python" "$(dirname "$0")/../fixtures/plc_master.py" "$dir/line.1" 9600 480 >/dev/null 2>&1 &
plcpid=$!
"$python" "$(dirname "$0")/a11y-walk.py" --stepcom "$stepcom" \
    --app-args "--port $dir/line.2 --listen" "$@"
