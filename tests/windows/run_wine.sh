#!/bin/sh
# tests/windows/run_wine.sh: runs a Windows program of the Windows build (./build.sh windows)
# under Wine, in a window on an X display of its own (Xvfb), and exits with its exit code:
#
#     run_wine.sh PREFIX PROGRAM.exe [ARGUMENTS...]
#     run_wine.sh PREFIX --make-prefix      makes the Wine prefix PREFIX where it is missing (a
#                                           run makes it first where it is missing: about 13 s)
#
# PREFIX is the Wine prefix (its C: drive and registry), shared by the tests and made once, by
# the windows_wine_prefix fixture: made under a temporary name and renamed, so that it is whole or
# absent. One run at a time in a prefix (the tests hold a CTest lock on it): each run starts its
# own Xvfb, which picks a free display itself (-displayfd), and ends every Wine process of the
# prefix before its display goes. Wine's own messages are off (WINEDEBUG=-all); Wine's .NET and
# HTML engines, which a new prefix offers to download, are declined. The text of the command line
# is UTF-8 (LC_ALL=C.UTF-8): Wine reads a non-ASCII path there in the locale's encoding.
set -eu
[ $# -ge 2 ] || { echo "usage: run_wine.sh PREFIX PROGRAM.exe [ARGUMENTS...] | PREFIX --make-prefix" >&2; exit 2; }
prefix="$1"
shift
case "$prefix" in /*) ;; *) prefix="$PWD/$prefix" ;; esac  # Wine takes an absolute path only
export WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml=" WINEPREFIX="$prefix" LC_ALL=C.UTF-8

make_prefix() {
    [ -f "$prefix/system.reg" ] && return 0
    if ! command -v wine >/dev/null 2>&1; then
        echo "run_wine.sh: no wine (Debian: wine): no prefix, and the windows tests are skipped"
        return 0
    fi
    temporary="$prefix.making.$$"
    rm -rf "$temporary"
    mkdir -p "$(dirname "$prefix")"
    if ! WINEPREFIX="$temporary" wineboot --init >"$temporary.log" 2>&1; then
        cat "$temporary.log" >&2
        rm -rf "$temporary" "$temporary.log"
        echo "run_wine.sh: wineboot could not make the prefix $prefix" >&2
        exit 1
    fi
    # wineboot returns before its server has written the registry out
    WINEPREFIX="$temporary" wineserver --wait
    rm -f "$temporary.log"
    rm -rf "$prefix"
    mv "$temporary" "$prefix"
}
make_prefix
[ "$1" = --make-prefix ] && exit 0

work=$(mktemp -d)
xvfb=""
cleanup() {
    [ -z "$xvfb" ] || kill "$xvfb" 2>/dev/null || true
    rm -rf "$work"
}
trap cleanup EXIT
Xvfb -displayfd 5 -screen 0 1920x1080x24 -nolisten tcp 5>"$work/display" 2>"$work/xvfb.log" &
xvfb=$!
tries=0
while [ ! -s "$work/display" ]; do
    tries=$((tries + 1))
    if [ "$tries" -gt 200 ] || ! kill -0 "$xvfb" 2>/dev/null; then
        cat "$work/xvfb.log" >&2
        echo "run_wine.sh: Xvfb did not start" >&2
        exit 1
    fi
    sleep 0.05
done
# The program's errors are kept apart from what Wine's own processes (its desktop, its services)
# may print when their display goes away, and shown after it has ended.
status=0
DISPLAY=":$(cat "$work/display")" wine "$@" 2>"$work/stderr" || status=$?
# Wine's processes of this prefix end with the run, before its display does
wineserver -k 2>/dev/null || true
wineserver -w 2>/dev/null || true
cat "$work/stderr" >&2
exit "$status"
