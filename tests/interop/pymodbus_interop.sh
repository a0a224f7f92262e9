#!/usr/bin/env bash
# stepcomctl against pymodbus's own Modbus RTU server (a second, independent controller that
# answers in a few ms, with FC05/FC06 answers that are the request's exact copy) on a socat pty
# pair: read everything, write and verify, every kind of command, the E-STOP, monitor. Nothing
# may fail, be taken for an echo or be thrown away as a late answer.
#   pymodbus_interop.sh STEPCOMCTL
set -uo pipefail
ctl=$1
here=$(cd "$(dirname "$0")" && pwd)
for tool in socat /usr/bin/python3; do
    command -v "$tool" >/dev/null || { echo "interop: $tool is missing (scripts/deps.sh --test)"; exit 1; }
done
/usr/bin/python3 -c 'import pymodbus, serial_asyncio' 2>/dev/null ||
    { echo "interop: python3-pymodbus and python3-serial-asyncio are missing (scripts/deps.sh --test)"; exit 1; }
dir=$(mktemp -d)
pids=()
cleanup() {
    for p in "${pids[@]}"; do kill "$p" 2>/dev/null; done
    wait 2>/dev/null
    rm -rf "$dir"
}
trap cleanup EXIT
socat pty,raw,echo=0,link="$dir/ctl" pty,raw,echo=0,link="$dir/dev" 2>"$dir/socat.log" &
pids+=($!)
for _ in $(seq 50); do [[ -e $dir/ctl && -e $dir/dev ]] && break; sleep 0.1; done
/usr/bin/python3 "$here/pymodbus_controller.py" "$dir/dev" >"$dir/server.log" 2>&1 &
pids+=($!)
for _ in $(seq 100); do grep -q "pymodbus controller" "$dir/server.log" && break; sleep 0.1; done
sleep 0.5 # the server opens the port after it said so

failed=0
run() { # run NAME EXPECTED-EXIT ARGS...: stepcomctl with ARGS, output kept in $dir/NAME
    local name=$1 want=$2
    shift 2
    "$ctl" --port "$dir/ctl" --verbose "$@" >"$dir/$name.out" 2>"$dir/$name.err"
    local got=$?
    if [[ $got -ne $want ]]; then
        echo "FAIL $name: exit $got, expected $want ($*)"
        sed 's/^/    /' "$dir/$name.out" "$dir/$name.err"
        failed=$((failed + 1))
        return 1
    fi
    if grep -qiE "echo(es)? what it sends|sooner than the controller|no answer within" "$dir/$name.err" "$dir/$name.out"; then
        echo "FAIL $name: a good answer was refused"
        sed 's/^/    /' "$dir/$name.err"
        failed=$((failed + 1))
        return 1
    fi
    echo "ok   $name"
}
expect() { # expect NAME PATTERN: the output of NAME holds PATTERN
    if ! grep -qE "$2" "$dir/$1.out"; then
        echo "FAIL $1: output lacks /$2/"
        sed 's/^/    /' "$dir/$1.out"
        failed=$((failed + 1))
    fi
}

run read-all 0 read && expect read-all "motor1.step_angle.*1\.80"
run read-two 0 read motor1.speed motor2.microsteps && expect read-two "motor1.speed.*300"
run write 0 write motor1.speed=222 motor1.move_distance=12.5
run read-back 0 read motor1.speed motor1.move_distance &&
    expect read-back "motor1.speed.*222" && expect read-back "motor1.move_distance.*12\.50"
# What the window asks before writing is asked here too: exit 2 and no write frame without --yes.
nowrite() { # nowrite NAME: no write frame went out in NAME's traffic
    if grep -qE "  TX  .*  write " "$dir/$1.err"; then
        echo "FAIL $1: a write frame went out"
        failed=$((failed + 1))
    fi
}
run home-on-limit 2 write motor1.home_input=1 && nowrite home-on-limit
grep -q "positive limit" "$dir/home-on-limit.err" ||
    { echo "FAIL home-on-limit: the question is not printed"; failed=$((failed + 1)); }
run mode-4 2 write mode.system=4 && nowrite mode-4
run review-held 0 read motor1.home_input mode.system &&
    expect review-held "motor1.home_input = 2" && expect review-held "mode.system = 0"
run mode-4-yes 0 --yes write mode.system=4
run mode-0 0 --yes write mode.system=0
run command-output 0 command output1_on
run command-stop 0 command motor1.stop
run command-estop 0 command estop
run save 0 command save_to_flash
# --json: a line a sample, then the envelope with the exit code as the last line.
run monitor 0 monitor --count 3 --json &&
    [[ $(grep -c '"motor1.position"' "$dir/monitor.out") -eq 3 ]] &&
    tail -n 1 "$dir/monitor.out" | grep -q '"exit":0' ||
    { echo "FAIL monitor: not 3 samples and the envelope"; failed=$((failed + 1)); }
grep -hE "^stepcomctl: link:|line:" "$dir/monitor.err" | head -1
# At an id nobody has, the independent server is silent too: the message names the command
# that finds controllers.
"$ctl" --port "$dir/ctl" --id 9 --timeout 300 --retries 0 read device.id >"$dir/wrong-id.out" \
    2>"$dir/wrong-id.err"
got=$?
if [[ $got -ne 1 ]] || ! grep -q "stepcomctl scan" "$dir/wrong-id.err"; then
    echo "FAIL wrong-id: exit $got (expected 1), or the message does not name stepcomctl scan"
    sed 's/^/    /' "$dir/wrong-id.out" "$dir/wrong-id.err"
    failed=$((failed + 1))
else
    echo "ok   wrong-id"
fi

if [[ $failed -ne 0 ]]; then
    echo "pymodbus server log:"; sed 's/^/    /' "$dir/server.log"
    echo "$failed failed"
    exit 1
fi
echo "every request answered by pymodbus's RTU server was taken"
