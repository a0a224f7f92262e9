#!/usr/bin/env bash
# Installs what StepCom needs from Debian/Ubuntu packages, only what is missing.
#   scripts/deps.sh          build and run
#   scripts/deps.sh --test   also the test peers (mbpoll, socat, pymodbus with serial-asyncio, Xvfb), the package
#                            checks (dpkg-dev, desktop-file-utils, appstream, shared-mime-info and
#                            gio for the file types), clang with
#                            libFuzzer (scripts/fuzz.sh), clang-format (scripts/check-format.sh)
#                            the accessibility bus with pyatspi (tests/a11y/a11y-walk.py) and
#                            headless chromium with node and puppeteer-core (tests/core/pendant)
set -euo pipefail

packages=(build-essential cmake ninja-build pkg-config
          qt6-base-dev qt6-serialbus-dev qt6-serialport-dev qt6-tools-dev qt6-tools-dev-tools
          qt6-l10n-tools qt6-charts-dev libqt6opengl6-dev libxkbcommon-dev qt6-svg-dev
          qt6-translations-l10n libgl-dev libquazip1-qt6-dev
          qt6-httpserver-dev qt6-websockets-dev libqrencode-dev libsdl2-dev
          qt6-qpa-plugins fonts-noto-cjk help2man)
if [[ "${1:-}" == "--test" ]]; then
    packages+=(mbpoll socat python3-pymodbus python3-serial-asyncio xvfb xauth dpkg-dev file poppler-utils
               desktop-file-utils appstream clang libclang-rt-dev clang-format
               python3-pyatspi at-spi2-core dbus-daemon dbus-bin shared-mime-info libglib2.0-bin
               chromium)
    # node and npm from Debian, unless a node of another origin (which brings its own npm) is there
    command -v node >/dev/null || packages+=(nodejs)
    command -v npm >/dev/null || packages+=(npm)
fi

missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# The pendant's browser test drives chromium with puppeteer-core (no browser download: it uses
# Debian's chromium), pinned by tests/core/pendant/package-lock.json.
browser_test() {
    if [[ "${1:-}" == "--test" && ! -d tests/core/pendant/node_modules/puppeteer-core ]]; then
        (cd tests/core/pendant && npm ci --no-audit --no-fund --loglevel=error)
    fi
}
cd "$(dirname "$0")/.."
if [[ ${#missing[@]} -eq 0 ]]; then
    browser_test "${1:-}"
    exit 0
fi

sudo=()
if [[ $(id -u) -ne 0 ]]; then
    command -v sudo >/dev/null || { echo "deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
    sudo=(sudo)
fi
echo "deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
browser_test "${1:-}"
