#!/bin/sh
# Runs a test program in a home of its own, emptied first: settings, backups and logs of an
# earlier run (or of another test running beside it) can change nothing a test sees.
#   fresh-home.sh DIR PROGRAM [ARGS...]
set -e
dir=$1
shift
rm -rf "$dir"
mkdir -p "$dir/config" "$dir/data"
HOME=$dir XDG_CONFIG_HOME=$dir/config XDG_DATA_HOME=$dir/data exec "$@"
