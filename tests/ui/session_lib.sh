# Sourced by the Xvfb session scripts, which take TESSERA OUTDIR SCREENSHOT_CHECK and one more
# argument of their own.

# session_start TESSERA OUTDIR SCREENSHOT_CHECK ...: sets $tessera, $out and $check, gives
# the session an empty $out, and $out/state as its XDG_STATE_HOME.
session_start() {
    tessera=$1 out=$2 check=$3
    rm -rf "$out"
    mkdir -p "$out"
    # The window's autosaves and recent files stay in the session's folder, not the user's.
    export XDG_STATE_HOME="$out/state"
}

# The X authority file for xvfb-run, in the session's own folder: without one xvfb-run makes a
# temporary folder and exits 5 ("problem while cleaning up temporary directory") when its
# removal fails, whatever the window did; seen now and then with several sessions at once.
xvfb_auth_file() {
    echo "$out/.Xauthority"
}

# session_xvfb COMMAND [ARGS]: COMMAND on a new Xvfb server (a free display number) whose
# screen is $SESSION_SCREEN (default 1280x720x24), with its authority file in $out; exits as
# COMMAND does. Every script that needs an X server starts it here.
session_xvfb() {
    xvfb-run -a -f "$(xvfb_auth_file)" -s "-screen 0 ${SESSION_SCREEN:-1280x720x24}" "$@"
}

# session_window PROJECT SIZE SCRIPT LOG [MORE OPTIONS]: the planner window on PROJECT (empty:
# none) under Xvfb (session_xvfb), driven by SCRIPT, stderr into LOG; the test fails unless it
# exits 0.
session_window() {
    project=$1 size=$2 script=$3 log=$4
    shift 4
    # shellcheck disable=SC2086 # an empty project is no argument
    session_xvfb "$tessera" open $project --size "$size" --script "$script" "$@" 2>"$log" || {
        cat "$log"
        echo "FAIL: the session $script did not exit 0"
        exit 1
    }
    cat "$log"
}

# session_shots NAME...: each screenshot $out/NAME.png was written.
session_shots() {
    for shot in "$@"; do
        test -s "$out/$shot.png" || { echo "FAIL: no screenshot $shot"; exit 1; }
    done
}
