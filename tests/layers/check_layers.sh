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
    [core/report]="map device motion profile commissioning"
    [core/sim]="map bus motion session"
    [core/support]="map bus device session commissioning"
    [core/pendant]="map device motion session"
    [core/listen]="map bus session support"
    [ui]="map device motion session line profile commissioning report i18n support pendant listen"
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
        layer=$(sed -E 's/.*#include "([a-z0-9_]+)\/.*/\1/' <<<"$text")
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
if [[ $bad -ne 0 ]]; then
    exit 1
fi
echo "check_layers: every include runs the way docs/architecture.md says"
