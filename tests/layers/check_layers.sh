#!/usr/bin/env bash
# The house rules of docs/architecture.md that a machine can check: which folder may include
# which, and that the rooms of the core include each other in one direction only. Prints every
# include that breaks them and fails.
set -uo pipefail
cd "${1:-$(dirname "$0")/../..}"
# What each folder may include besides itself: the include graph as it is, no wider. The core
# rooms run map → bus → device → session → line, motion beside them on map.
declare -A allowed=(
    [core/map]=""
    [core/i18n]=""
    [core/bus]="map"
    [core/motion]="map i18n"
    [core/device]="map bus motion i18n"
    [core/session]="map bus device motion i18n"
    [core/line]="map bus device session"
    [core/profile]="map device motion session"
    [core/commissioning]="map device profile"
    [core/report]="map device motion session profile commissioning"
    [core/sim]="map bus motion session"
    [core/support]="map bus device session commissioning"
    [core/pendant]="map device motion session"
    [core/listen]="map bus session support"
    [core/sequence]="map bus device motion session"
    [core/proof]="map bus device motion session"
    [core/gamepad]="session"
    [ui]="map device motion session line profile commissioning report i18n support pendant listen proof sequence gamepad"
)
bad=0
# The rules themselves must have no cycle: a room never reaches itself through the others.
declare -A seen=()
reaches() { # reaches ROOM TARGET: whether ROOM's allowed includes lead to TARGET
    local dep
    for dep in ${allowed[core/$1]-}; do
        [[ $dep == "$2" ]] && return 0
        [[ -n ${seen[$dep]-} ]] && continue
        seen[$dep]=1
        reaches "$dep" "$2" && return 0
    done
    return 1
}
for dir in "${!allowed[@]}"; do
    [[ $dir == core/* ]] || continue
    seen=()
    if reaches "${dir#core/}" "${dir#core/}"; then
        echo "check_layers: $dir reaches itself through the rooms it may include"
        bad=1
    fi
done
for dir in "${!allowed[@]}"; do
    [[ -d $dir ]] || { echo "check_layers: no folder $dir"; bad=1; continue; }
    while IFS=: read -r file line text; do
        # bash's own regex: a subprocess per include line made the check take seconds
        [[ $text =~ \#include\ \"([a-z0-9_]+)/ ]] || continue
        layer=${BASH_REMATCH[1]}
        [[ "core/$layer" == "$dir" ]] && continue
        case " ${allowed[$dir]} " in *" $layer "*) continue ;; esac
        # ui/ has folders of its own (pages/, widgets/, dialogs/, help/)
        [[ $dir == ui && -d ui/$layer ]] && continue
        echo "$file:$line: $dir may not include $layer/ ($text)"
        bad=1
    done < <(grep -rnE '^#include "[a-z0-9_]+/' "$dir" --include='*.cpp' --include='*.h')
done
# Every folder of the core has its rules (a new room must say where it stands).
for dir in core/*/; do
    dir=${dir%/}
    [[ -n ${allowed[$dir]+x} ]] || { echo "check_layers: $dir has no rule here"; bad=1; }
done
# Front-ends speak to the session, not to its parts (the benchmark measures the link itself).
while IFS= read -r hit; do
    echo "$hit: front-ends include no bus/ or poll/ header (use session/devicesession.h)"
    bad=1
done < <(grep -rnE '^#include "(bus|poll)/' app ui --include='*.cpp' --include='*.h' | grep -v '^app/bench/')
# The session's own header is a front door: its parts have headers of their own, so touching the
# client, the store, the poller, a planner or the link rebuilds only the files that use them.
while IFS= read -r hit; do
    echo "$hit: session/devicesession.h includes no client, store, poller, planner or bus header (a part's header does)"
    bad=1
done < <(grep -HnE '^#include "(bus/|device/(deviceclient|parameterstore|poller|readplanner|writeplanner|readlimits)\.h)' core/session/devicesession.h)
# Floors inside ui/ and rooms inside core/sim: a file includes its own floor and those below.
check_floors() { # check_floors DIR "FLOORS low to high" PREFIX (what includes of DIR start with)
    local dir=$1 floors=$2 prefix=$3 floor own target file line text rank i=0
    local -A ranks=()
    for floor in $floors; do
        ranks[$floor]=$i
        i=$((i + 1))
    done
    local pattern="#include \"${prefix}([a-z0-9_]+)/"
    for floor in $floors; do
        [[ -d $dir/$floor ]] || { echo "check_layers: no folder $dir/$floor"; bad=1; continue; }
        own=${ranks[$floor]}
        while IFS=: read -r file line text; do
            [[ $text =~ $pattern ]] || continue
            target=${BASH_REMATCH[1]}
            rank=${ranks[$target]-}
            [[ -z $rank || $rank -le $own ]] && continue
            echo "$file:$line: $dir/$floor may not include $target/, a floor above it ($text)"
            bad=1
        done < <(grep -rnE "^#include \"${prefix}[a-z0-9_]+/" "$dir/$floor" --include='*.cpp' --include='*.h')
    done
    # Every folder there stands on a floor.
    local sub
    for sub in "$dir"/*/; do
        sub=$(basename "$sub")
        [[ -n ${ranks[$sub]+x} ]] || { echo "check_layers: $dir/$sub is on no floor"; bad=1; }
    done
}
check_floors ui "base help widgets dialogs pages replay window" ""
check_floors core/sim "model serve host" "sim/"
# A room holds at most 15 sources: past that it holds more than one concern.
while read -r count folder; do
    [[ $count -gt 15 ]] || continue
    echo "check_layers: $folder holds $count .cpp files (at most 15: split it along a seam)"
    bad=1
done < <(find core ui app -name '*.cpp' -not -path '*/build*' -printf '%h\n' | sort | uniq -c)
# The tests mirror the sources (docs/testing.md): tests/core/<room>, tests/ui/<floor> and
# tests/app/<program> each stand for a folder that exists there; the other folders of tests/
# are the shared fixtures and the kinds of test that cut across the rooms.
mirrored="core ui app"
crosscutting="fixtures a11y docs fuzz i18n interop layers packaging sanitizers soak"
for dir in tests/*/; do
    dir=$(basename "$dir")
    case " $mirrored $crosscutting " in *" $dir "*) continue ;; esac
    echo "check_layers: tests/$dir is no room of the sources nor a kind of test (docs/testing.md)"
    bad=1
done
for top in $mirrored; do
    [[ -d tests/$top ]] || continue
    for dir in tests/"$top"/*/; do
        [[ -d $dir ]] || continue
        room=$(basename "$dir")
        [[ -d $top/$room ]] && continue
        echo "check_layers: tests/$top/$room tests no folder $top/$room (move it where its sources are)"
        bad=1
    done
    while IFS= read -r suite; do
        echo "check_layers: $suite sits in no room of tests/$top (tests/$top/<room>/)"
        bad=1
    done < <(find "tests/$top" -maxdepth 1 -name 'tst_*.cpp')
done
# History stays in the commits: the reader of the code has no issue tracker.
while IFS= read -r hit; do
    echo "$hit: names an issue number (say why, not when)"
    bad=1
done < <(grep -rnIiE '\bissues? #?[0-9]+\b' core ui app tests scripts docs packaging resources \
             translations/tsv --exclude-dir=node_modules --exclude-dir='build*' 2>/dev/null)
if [[ $bad -ne 0 ]]; then
    exit 1
fi
echo "check_layers: every include runs the way docs/architecture.md says"
