#!/usr/bin/env bash
# The long soak: the simulator on a bad line (lost, corrupt, late and exception answers, a
# hang-up every few hundred answers) for STEPCOM_SOAK_TRANSACTIONS Modbus transactions while
# polling, jogging and writing. See docs/testing.md.
#   scripts/soak.sh                 20000 transactions (about 22 minutes)
#   scripts/soak.sh 100000 [seed]   longer, other fault dice
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh --test
scripts/build.sh >/dev/null
build=${BUILD_DIR:-build}
export STEPCOM_SOAK_TRANSACTIONS=${1:-${STEPCOM_SOAK_TRANSACTIONS:-20000}}
export STEPCOM_SOAK_SEED=${2:-${STEPCOM_SOAK_SEED:-7}}
export QT_QPA_PLATFORM=offscreen
echo "soak: $STEPCOM_SOAK_TRANSACTIONS transactions, seed $STEPCOM_SOAK_SEED"
exec "$build/tests/tests_soak" tst_soak -maxwarnings 0
