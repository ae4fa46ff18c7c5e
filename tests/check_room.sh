#!/bin/sh
# Fails when LIBRARY (a static library) needs a brdfnav symbol that neither it nor BELOW (the
# libraries of the rooms it may stand on) defines: an arrow from its room to one above, or to one
# it may not use. Prints the first ones. Usage: check_room.sh NM LIBRARY BELOW...
set -eu
nm=$1 library=$2
shift 2
defined=$(mktemp) needed=$(mktemp)
trap 'rm -f "$defined" "$needed"' EXIT
# nm -C prints "address type name" for a definition and "U name" for a need; names have spaces.
for lib in "$library" "$@"; do
  "$nm" -C --defined-only "$lib" | sed -n 's/^[0-9a-f]* [A-Za-z] //p'
done | sort -u >"$defined"
"$nm" -C --undefined-only "$library" | sed -n 's/^ *U //p' | grep '^brdfnav::' | sort -u >"$needed"
missing=$(comm -23 "$needed" "$defined")
if [ -n "$missing" ]; then
  echo "$library needs brdfnav symbols that it and $* do not define (a room above it):" >&2
  echo "$missing" | head -20 >&2
  exit 1
fi
echo "$library: its $(wc -l <"$needed") brdfnav symbols are its own or from $*"
