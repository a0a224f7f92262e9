#!/usr/bin/env bash
# Builds the Debian package from a configured and built tree, checks what it holds and runs
# its programs from a scratch root.   check_deb.sh BUILD_DIR VERSION
set -euo pipefail
export QT_QPA_PLATFORM=offscreen LC_ALL=C.UTF-8   # stepcom --version needs no display

build=${1:?build dir}
version=${2:?version}
fail() { echo "check_deb: $*" >&2; exit 1; }
for tool in cpack dpkg-deb dpkg file; do
    command -v "$tool" >/dev/null || fail "$tool not found: run scripts/deps.sh --test"
done

scratch=$(mktemp -d "${TMPDIR:-/tmp}/stepcom-deb.XXXXXX")
trap 'rm -rf "$scratch"' EXIT

# gzip: the same package, built several times faster than with xz.
cpack -G DEB --config "$build/CPackConfig.cmake" -B "$scratch/out" \
      -D CPACK_DEBIAN_COMPRESSION_TYPE=gzip >"$scratch/cpack.log" 2>&1 \
    || { cat "$scratch/cpack.log" >&2; fail "cpack failed"; }
shopt -s nullglob
debs=("$scratch"/out/*.deb)
[[ ${#debs[@]} -eq 1 ]] || fail "expected one .deb in $scratch/out, found ${#debs[@]}"
deb=${debs[0]}
arch=$(dpkg --print-architecture)
[[ $(basename "$deb") == "stepcom_${version}_${arch}.deb" ]] || fail "unexpected name $(basename "$deb")"

# The control fields: name, version, Depends from dpkg-shlibdeps.
info=$(dpkg-deb -f "$deb" Package Version Architecture Section Depends)
echo "$info"
field() { dpkg-deb -f "$deb" "$1"; }
[[ $(field Package) == stepcom ]] || fail "Package is '$(field Package)'"
[[ $(field Version) == "$version" ]] || fail "Version is '$(field Version)', not $version"
[[ $(field Architecture) == "$arch" ]] || fail "Architecture is '$(field Architecture)'"
description=$(field Description)
[[ $description == "commissioning tool for a 2-axis Modbus RTU stepper controller"$'\n'* ]] \
    || fail "the Description's synopsis is wrong: $description"
[[ $description != *";"* ]] || fail "the Description holds a CMake list separator: $description"
grep -qx '  \.' <<<"$(dpkg-deb -I "$deb")" || fail "the Description's empty line is not ' .'"
depends=$(field Depends)
for lib in libc6 libqt6core6 libqt6serialbus6 libqt6serialport6 libqt6network6 libqt6gui6 \
           libqt6widgets6 libqt6svg6 libqt6charts6 libsdl2-2.0-0; do
    [[ ", $depends" =~ ,\ $lib([ ,]|$) ]] || fail "Depends lacks $lib: $depends"
done
[[ $depends =~ libqt6core6(t64)?\ \(\>=\ 6\. ]] || fail "Depends has no Qt 6 version: $depends"

# The files.
contents=$(dpkg-deb -c "$deb" | awk '{print $6}')
expect=(./usr/bin/stepcom ./usr/bin/stepcomctl ./usr/bin/stepcom-sim
        ./usr/share/applications/org.stepcom.StepCom.desktop
        ./usr/share/mime/packages/org.stepcom.StepCom.xml
        ./usr/share/metainfo/org.stepcom.StepCom.metainfo.xml
        ./usr/lib/udev/rules.d/60-stepcom-ftdi-latency.rules
        ./usr/share/icons/hicolor/scalable/apps/stepcom.svg
        ./usr/share/man/man1/stepcom.1.gz ./usr/share/man/man1/stepcomctl.1.gz
        ./usr/share/man/man1/stepcom-sim.1.gz ./usr/share/doc/stepcom/copyright
        ./usr/share/stepcom/guide/guide.md ./usr/share/stepcom/guide/guide.zh_CN.md
        ./usr/share/stepcom/guide/images/en/01-connectionPage.png
        ./usr/share/stepcom/guide/images/zh_CN/01-connectionPage.png)
sizes=(16 24 32 48 64 128 256)
for s in "${sizes[@]}"; do expect+=("./usr/share/icons/hicolor/${s}x${s}/apps/stepcom.png"); done
for f in "${expect[@]}"; do
    grep -qxF "$f" <<<"$contents" || fail "the package lacks $f"
done
! grep -q 'stepcom-bench\|stepcom-svg2png\|/tst_\|\.a$\|/include/' <<<"$contents" \
    || fail "the package holds build-only files: $(grep 'stepcom-bench\|stepcom-svg2png\|/tst_\|\.a$\|/include/' <<<"$contents")"

# `cmake --install` into a DESTDIR installs the same files as the package.
DESTDIR="$scratch/destdir" cmake --install "$build" --prefix /usr >"$scratch/install.log" 2>&1 \
    || { cat "$scratch/install.log" >&2; fail "cmake --install into a DESTDIR failed"; }
installed=$(cd "$scratch/destdir" && find . -type f | sort)
packaged=$(dpkg-deb -c "$deb" | awk '$1 !~ /^d/ {print $6}' | sort)
[[ $installed == "$packaged" ]] \
    || fail "cmake --install and the package differ: $(diff <(echo "$installed") <(echo "$packaged"))"

# Unpacked into a scratch root, the files are what they claim to be and the programs run.
root=$scratch/root
dpkg -x "$deb" "$root"
for s in "${sizes[@]}"; do
    grep -q "PNG image data, $s x $s," <<<"$(file -b "$root/usr/share/icons/hicolor/${s}x${s}/apps/stepcom.png")" \
        || fail "the ${s}x${s} icon is not a $s px PNG"
done
for p in stepcomctl stepcom-sim; do
    page=$(gzip -dc "$root/usr/share/man/man1/$p.1.gz")
    [[ $page == *".TH "* ]] || fail "$p.1 is not a man page"
    # Every option of --help is documented.
    for option in $("$root/usr/bin/$p" --help | grep -o -- '--[a-z][a-z-]*' | sort -u); do
        grep -qF -- "${option//-/\\-}" <<<"$page" || grep -qF -- "$option" <<<"$page" \
            || fail "$p.1 does not document $option"
    done
done
out=$("$root/usr/bin/stepcomctl" --version)
[[ $out == "stepcomctl $version" ]] || fail "stepcomctl --version printed '$out'"
out=$("$root/usr/bin/stepcom" --version)
[[ $out == "stepcom $version" ]] || fail "stepcom --version printed '$out'"
# Also on a machine with no display at all (ssh, a build server).
out=$(env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM "$root/usr/bin/stepcom" --version) \
    || fail "stepcom --version without a display failed: $out"
[[ $out == "stepcom $version" ]] || fail "stepcom --version without a display printed '$out'"
out=$("$root/usr/bin/stepcomctl" --sim read) || fail "stepcomctl --sim read failed: $out"
grep -q '^motor1\.speed = ' <<<"$out" || fail "stepcomctl --sim read printed no motor1.speed: $out"
grep -q '^device\.id = 1' <<<"$out" || fail "stepcomctl --sim read printed no device.id: $out"
echo "check_deb: $(basename "$deb") OK ($(du -k "$deb" | cut -f1) kB)"
