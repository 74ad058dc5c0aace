#!/bin/sh
# tests/windows/run_wine.sh: runs a Windows program of the Windows build (./build.sh windows)
# under Wine, in a window on an X display (Xvfb), and exits with its exit code:
#
#     run_wine.sh PREFIX PROGRAM.exe [ARGUMENTS...]
#     run_wine.sh PREFIX --start     makes the Wine prefix PREFIX where it is missing, and starts
#                                    a session for the runs to share: an Xvfb display and Wine's
#                                    server, kept running (the windows tests' fixture)
#     run_wine.sh PREFIX --stop      ends that session
#
# PREFIX is the Wine prefix (its C: drive and registry), made under a temporary name and renamed,
# so that it is whole or absent (about 13 s; a run makes it first where it is missing). A run
# inside a session takes its display and its warm server (the tests' runs, side by side: 1.2 s for
# a sample's picture); a run outside one starts an Xvfb of its own, which picks a free display
# itself (-displayfd), and ends every Wine process of the prefix before its display goes (5 s).
# A session's Xvfb ends after 30 minutes whatever happens, and Wine's server a minute after its
# last program. Wine's own messages are off (WINEDEBUG=-all, or PBR_WINEDEBUG's channels where it
# is set: a test reads the loader's, +loaddll); Wine's .NET and HTML engines,
# which a new prefix offers to download, are declined. The text of the command line is UTF-8
# (LC_ALL=C.UTF-8): Wine reads a non-ASCII path there in the locale's encoding.
set -eu
[ $# -ge 2 ] || { echo "usage: run_wine.sh PREFIX PROGRAM.exe [ARGUMENTS...] | PREFIX --start | PREFIX --stop" >&2; exit 2; }
prefix="$1"
shift
case "$prefix" in /*) ;; *) prefix="$PWD/$prefix" ;; esac  # Wine takes an absolute path only
export WINEDEBUG="${PBR_WINEDEBUG:--all}" WINEDLLOVERRIDES="mscoree,mshtml=" WINEPREFIX="$prefix" LC_ALL=C.UTF-8
session="$prefix.session"  # "DISPLAY-NUMBER XVFB-PID" of the running session

# Wine's X11 driver lets a window manager manage its windows by default, and closing such a
# window waits for the manager to withdraw it: Xvfb runs none, so every run that opened a window
# waited out the 2-second timeout (measured: a sample's picture 3.1 s, 1.2 s unmanaged). The
# prefix's windows are unmanaged instead (the registry's X11 Driver\Managed=N); a prefix made
# before this setting is made again.
make_prefix() {
    [ -f "$prefix/system.reg" ] && grep -q '^"Managed"="N"' "$prefix/user.reg" 2>/dev/null &&
        return 0
    temporary="$prefix.making.$$"
    rm -rf "$temporary"
    mkdir -p "$(dirname "$prefix")"
    # (making WHAT-FAILED COMMAND...: the command on the temporary prefix; on a failure its
    # output, the temporary removed, and one line)
    making() {
        what="$1"
        shift
        if ! WINEPREFIX="$temporary" "$@" >"$temporary.log" 2>&1; then
            cat "$temporary.log" >&2
            rm -rf "$temporary" "$temporary.log"
            echo "run_wine.sh: $what" >&2
            exit 1
        fi
    }
    making "wineboot could not make the prefix $prefix" wineboot --init
    making "could not set the prefix's windows unmanaged" \
        wine reg add 'HKCU\Software\Wine\X11 Driver' /v Managed /d N /f
    # wineboot returns before its server has written the registry out
    WINEPREFIX="$temporary" wineserver --wait
    rm -f "$temporary.log"
    rm -rf "$prefix"
    mv "$temporary" "$prefix"
}

# Starts an Xvfb (START_XVFB WORK LIFETIME): its display number in $display, its process in $xvfb
start_xvfb() {
    rm -f "$1/display"  # (written by Xvfb once it listens; an old one must not be taken for it)
    timeout "$2" Xvfb -displayfd 5 -screen 0 1920x1080x24 -nolisten tcp </dev/null >/dev/null \
        5>"$1/display" 2>"$1/xvfb.log" &
    xvfb=$!
    tries=0
    while [ ! -s "$1/display" ]; do
        tries=$((tries + 1))
        if [ "$tries" -gt 200 ] || ! kill -0 "$xvfb" 2>/dev/null; then
            cat "$1/xvfb.log" >&2
            echo "run_wine.sh: Xvfb did not start" >&2
            exit 1
        fi
        sleep 0.05
    done
    display=$(cat "$1/display")
}

stop_session() {
    [ -f "$session" ] || return 0
    pid=$(cut -d" " -f2 "$session")
    rm -f "$session"
    wineserver -k 2>/dev/null || true
    wineserver -w 2>/dev/null || true
    [ -z "${pid:-}" ] || kill "$pid" 2>/dev/null || true
}

case "$1" in
    --start | --make-prefix)
        if ! command -v wine >/dev/null 2>&1; then
            echo "run_wine.sh: no wine (Debian: wine): no prefix, and the windows tests are skipped"
            exit 0
        fi
        make_prefix
        [ "$1" = --start ] || exit 0
        stop_session
        mkdir -p "$prefix.xvfb"
        start_xvfb "$prefix.xvfb" 1800
        # Wine's server stays a minute after its last program, not just the usual 3 seconds
        DISPLAY=":$display" wineserver -p60 </dev/null >/dev/null 2>&1
        echo "$display $xvfb" >"$session.new"
        mv "$session.new" "$session"
        exit 0
        ;;
    --stop)
        stop_session
        exit 0
        ;;
esac

work=$(mktemp -d)
xvfb=""
cleanup() {
    [ -z "$xvfb" ] || kill "$xvfb" 2>/dev/null || true
    rm -rf "$work"
}
trap cleanup EXIT
shared=""
if [ -f "$session" ] && read -r display pid <"$session" && kill -0 "$pid" 2>/dev/null; then
    shared=yes
else
    make_prefix
    start_xvfb "$work" 600
fi
# The program's errors are kept apart from what Wine's own processes (its desktop, its services)
# may print when their display goes away, and shown after it has ended; so is its output, which a
# failed start is told by.
run() {
    status=0
    started=$(date +%s.%N)
    DISPLAY=":$display" wine "$@" >"$work/stdout" 2>"$work/stderr" || status=$?
}
run "$@"
if [ "$status" -ne 0 ] && grep -q "^Application could not be started" "$work/stdout"; then
    # Wine could not map the program and its start.exe could not either ("ShellExecuteEx failed:
    # Internal error", after 0.09 s, seen once early in a fresh session): the program never ran.
    # Said so, and started once more.
    echo "run_wine.sh: Wine could not start $1 ($(head -c 200 "$work/stdout" | tr '\r\n' '  '));" \
         "starting it again" >&2
    run "$@"
fi
if [ "$status" -ne 0 ] && [ ! -s "$work/stderr" ] && [ ! -s "$work/stdout" ]; then
    # Every failure of a sample says why on stderr: a silent one is Wine's (seen once in about 500
    # runs, after 0.04 s, and not since), said so for the next time
    took=$(awk -v a="$started" -v b="$(date +%s.%N)" 'BEGIN { printf "%.2f", b - a }')
    where="its own display :$display"
    [ -z "$shared" ] || where="the shared session's display :$display"
    echo "run_wine.sh: wine ended with $status after $took s and said nothing ($where)" >"$work/stderr"
fi
if [ -z "$shared" ]; then
    # Wine's processes of this prefix end with the run, before its display does
    wineserver -k 2>/dev/null || true
    wineserver -w 2>/dev/null || true
fi
cat "$work/stdout"
cat "$work/stderr" >&2
exit "$status"
