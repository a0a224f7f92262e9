#!/usr/bin/env bash
# Regenerates the user guide's screenshots (docs/images/en, docs/images/zh_CN) from the real
# window on the built-in simulator, offscreen: installs what is missing, builds, runs
# stepcom-shots. Extra arguments go to stepcom-shots (e.g. --lang en, --scene bus-scan).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh
build=${BUILD_DIR:-build}
# Keep the build type of an existing build directory (a Debug tree stays Debug).
if [[ -z "${BUILD_TYPE:-}" && -f "$build/CMakeCache.txt" ]]; then
    BUILD_TYPE=$(sed -n 's/^CMAKE_BUILD_TYPE:STRING=//p' "$build/CMakeCache.txt")
    export BUILD_TYPE
fi
scripts/build.sh
# Chinese text needs a CJK font (fonts-noto-cjk, installed by deps.sh).
fc-list :lang=zh family | grep -q . || echo "screenshots: warning: no Chinese font found" >&2
QT_QPA_PLATFORM=offscreen LC_ALL=C.UTF-8 "$build/app/stepcom-shots" --out docs/images "$@"
du -sh docs/images
