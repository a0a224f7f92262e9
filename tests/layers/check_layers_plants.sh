#!/usr/bin/env bash
# The layer check must fail on what it guards against: each plant goes into a copy of the
# sources, and check_layers.sh has to reject it (and pass the copy without it).
set -uo pipefail
src=$(cd "${1:-$(dirname "$0")/../..}" && pwd)
check="$src/tests/layers/check_layers.sh"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# One copy of what the check reads; each plant gets a tree of hard links to it (fast), and plants
# change files only by replacing them (sed -i), never in place, so the copy stays clean.
(cd "$src" && tar cf - --exclude='build*' --exclude=node_modules --exclude='*.png' \
    core ui app tests scripts docs packaging resources translations/tsv) |
    (mkdir -p "$tmp/clean" && cd "$tmp/clean" && tar xf -)
fresh() { # a clean tree to plant in
    rm -rf "$tmp/tree"
    cp -al "$tmp/clean" "$tmp/tree"
}
failed=0
out=""
expect() { # expect WORDS: the check fails on the tree as planted, saying WORDS
    if out=$(bash "$check" "$tmp/tree" 2>&1); then
        echo "NOT CAUGHT: $plant"
        failed=1
    elif ! grep -qF -- "$1" <<<"$out"; then
        echo "CAUGHT, but without '$1': $plant"
        echo "$out"
        failed=1
    else
        echo "caught: $plant"
    fi
}
expect_also() { # expect_also WORDS: the last run's output also says WORDS
    if ! grep -qF -- "$1" <<<"$out"; then
        echo "CAUGHT, but without '$1': $plant"
        failed=1
    fi
}
fresh
if ! out=$(bash "$check" "$tmp/tree" 2>&1); then
    echo "the copy without plants fails already:"
    echo "$out"
    exit 1
fi

plant="ui/base includes a floor above it (window/)"
fresh
sed -i '0,/^#include/s//#include "window\/mainwindow.h"\n#include/' "$tmp/tree/ui/base/page.cpp"
expect "ui/base may not include window/"

plant="ui/widgets includes a dialog"
fresh
sed -i '0,/^#include/s//#include "dialogs\/backupsdialog.h"\n#include/' \
    "$tmp/tree/ui/widgets/fields/led.cpp"
expect "ui/widgets may not include dialogs/"

plant="core/sim/model includes the host"
fresh
sed -i '0,/^#include/s//#include "sim\/host\/simhost.h"\n#include/' \
    "$tmp/tree/core/sim/model/simaxis.cpp"
expect "core/sim/model may not include host/"

plant="a 16th source in a room"
fresh
n=$(find "$tmp/tree/core/map" -maxdepth 1 -name '*.cpp' | wc -l)
for ((i = n; i < 16; i++)); do echo "// planted" >"$tmp/tree/core/map/planted$i.cpp"; done
expect "core/map holds 16 .cpp files"

plant="a comment naming an issue number"
fresh
# split, or this file would be caught itself
sed -i '$a // fixed for iss''ue 12' "$tmp/tree/core/map/registermap.h"
expect "names an issue number"

# The test-folder plants share this tree (each run of the check reads every source): a test
# folder for a room the core lacks, a suite on no floor of tests/ui, a folder outside the mirror.
plant="a folder of ui/ on no floor; test folders the sources do not mirror"
fresh
mkdir -p "$tmp/tree/ui/misc" "$tmp/tree/tests/core/misc" "$tmp/tree/tests/cli"
echo "// planted" >"$tmp/tree/ui/misc/x.cpp"
echo "// planted" >"$tmp/tree/tests/core/misc/tst_misc.cpp"
echo "// planted" >"$tmp/tree/tests/ui/tst_misc.cpp"
echo "// planted" >"$tmp/tree/tests/cli/tst_misc.cpp"
expect "ui/misc is on no floor"
expect_also "tests/core/misc tests no folder core/misc"
expect_also "tests/ui/tst_misc.cpp sits in no room of tests/ui"
expect_also "tests/cli is no room of the sources nor a kind of test"

exit $failed
