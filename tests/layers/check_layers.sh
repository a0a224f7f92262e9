#!/usr/bin/env bash
# The house rules of docs/architecture.md that a machine can check: which folder may include
# which. Prints every include that breaks them and fails.
set -uo pipefail
cd "${1:-$(dirname "$0")/../..}"
declare -A allowed=(
    [core/map]=""
    [core/i18n]=""
    [core/bus]="map"
    [core/motion]="map i18n"
    [core/device]="map bus motion i18n"
    [core/session]="map bus device motion i18n"
    [core/line]="map bus device session"
    [core/profile]="map bus device motion session i18n"
    [core/commissioning]="map bus device motion profile i18n"
    [core/report]="map bus device motion profile commissioning i18n"
    [core/sim]="map bus device motion session i18n"
    [ui]="map device session line motion profile commissioning report i18n"
)
bad=0
for dir in "${!allowed[@]}"; do
    [[ -d $dir ]] || { echo "check_layers: no folder $dir"; bad=1; continue; }
    while IFS=: read -r file line text; do
        layer=$(sed -E 's/.*#include "([a-z0-9_]+)\/.*/\1/' <<<"$text")
        [[ "core/$layer" == "$dir" ]] && continue
        case " ${allowed[$dir]} " in *" $layer "*) continue ;; esac
        # ui/ has folders of its own (pages/, widgets/, dialogs/)
        [[ $dir == ui && -d ui/$layer ]] && continue
        echo "$file:$line: $dir may not include $layer/ ($text)"
        bad=1
    done < <(grep -rnE '^#include "[a-z0-9_]+/' "$dir" --include='*.cpp' --include='*.h')
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
