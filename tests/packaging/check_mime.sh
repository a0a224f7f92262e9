#!/usr/bin/env bash
# StepCom's file types (packaging/linux/org.stepcom.StepCom.mime.xml): the database builds from
# them; a profile is known as StepCom's by what it holds (GIO, as GNOME's file manager asks
# it), a sequence by its .stepseq name or what it holds, a session log and a support bundle
# by what they hold where their names do not settle it (GIO takes a lone *.log or *.zip glob
# as it is), other JSON, log and zip files are not StepCom's; the desktop entry declares
# exactly these types and takes the file (%f).
#   check_mime.sh SOURCE_DIR
set -euo pipefail
src=${1:?source dir}
fail() { echo "check_mime: $*" >&2; exit 1; }
for tool in update-mime-database gio python3; do
    command -v "$tool" >/dev/null || fail "$tool not found: run scripts/deps.sh --test"
done
xml=$src/packaging/linux/org.stepcom.StepCom.mime.xml
desktop=$src/packaging/linux/org.stepcom.StepCom.desktop
scratch=$(mktemp -d "${TMPDIR:-/tmp}/stepcom-mime.XXXXXX")
trap 'rm -rf "$scratch"' EXIT

# A database of the system's types and ours, as the package's trigger builds it.
mkdir -p "$scratch/data/mime/packages"
cp /usr/share/mime/packages/freedesktop.org.xml "$scratch/data/mime/packages/"
cp "$xml" "$scratch/data/mime/packages/org.stepcom.StepCom.xml"
out=$(update-mime-database -V "$scratch/data/mime" 2>&1) || { echo "$out" >&2; fail "update-mime-database failed"; }
if grep -qi "error\|warning\|invalid" <<<"$out"; then echo "$out" >&2; fail "the XML has problems"; fi

# Sample files as StepCom writes them (the profile's keys sorted, as QJsonDocument writes them).
f=$scratch/files
mkdir -p "$f"
printf '{\n    "format": "stepcom-profile",\n    "map": {\n    }\n}\n' >"$f/machine.json"
printf '{\n    "name": "not a profile"\n}\n' >"$f/other.json"
printf '{\n    "format": "stepcom-sequence",\n    "steps": [\n    ]\n}\n' >"$f/cycle.stepseq"
printf '{\n    "format": "stepcom-sequence",\n    "steps": [\n    ]\n}\n' >"$f/cycle-copy"
printf '# StepCom 0.1.0 session log, part 1: test\n# program: StepCom 0.1.0\n' >"$f/stepcom-20261124-221000"
printf 'just text\n' >"$f/notes.log"
python3 - "$f" <<'PY'
import sys, zipfile
d = sys.argv[1]
for name in ("stepcom-support-20261124-2210", "photos.zip"):
  with zipfile.ZipFile(d + "/" + name, "w") as z:   # README.txt first, as SupportBundle writes
    if name.startswith("stepcom"):
      z.writestr("README.txt", "StepCom support bundle\n")
      z.writestr("logs/stepcom-1.log", "# StepCom 0.1.0 session log\n")
    else:
      z.writestr("a.txt", "x")
PY

type_of() { XDG_DATA_HOME=$scratch/data XDG_DATA_DIRS=$scratch/data gio info -a standard::content-type "$1" | sed -n 's/^ *standard::content-type: //p'; }
expect() {
    local got
    got=$(type_of "$f/$1")
    [[ $got == "$2" ]] || fail "$1 is $got, not $2"
    echo "$1: $got"
}
expect machine.json application/x-stepcom-profile
expect other.json application/json
expect cycle.stepseq application/x-stepcom-sequence
expect cycle-copy application/x-stepcom-sequence
expect stepcom-20261124-221000 application/x-stepcom-session-log
expect notes.log text/x-log
expect stepcom-support-20261124-2210 application/x-stepcom-support-bundle
expect photos.zip application/zip

# The desktop entry opens exactly these types, and gets the file.
declared=$(sed -n 's/^MimeType=//p' "$desktop" | tr ';' '\n' | sed '/^$/d' | sort)
defined=$(sed -n 's/.*<mime-type type="\([^"]*\)".*/\1/p' "$xml" | sort)
[[ -n $defined && $declared == "$defined" ]] || fail "the desktop entry declares [$declared], the XML defines [$defined]"
grep -qx 'Exec=stepcom %f' "$desktop" || fail "the desktop entry's Exec does not take the file (%f)"
echo "check_mime: ok"
