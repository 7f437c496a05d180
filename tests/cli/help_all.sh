#!/bin/sh
# The program itself (ui/src/main.c, with the window behind `open`): `tessera --help` names
# every command of the command table (tessera help --list), and each way of asking for a
# command's usage exits 0 with it on stdout. test_cli_table runs every command's help
# in-process; this checks the forms through the real entry point, where each start of the
# program costs a second or two of library loading.
# usage: help_all.sh TESSERA
tessera=$1
status=0
fail() {
    echo "FAIL: $*"
    status=1
}
list=$("$tessera" help --list) || fail "tessera help --list exited $?"
overview=$("$tessera" --help) || fail "tessera --help exited $?"
for cmd in $(printf '%s\n' "$list" | cut -d' ' -f1 | sort -u); do
    printf '%s\n' "$overview" | grep -q -E "^  tessera $cmd( |\$)" ||
        fail "tessera --help does not name $cmd"
done
# shellcheck disable=SC2086 # each form is several words on purpose
for form in "open --help" "render --help" "sweep -h" "help bench" "catalog search --help" \
    "help catalog lod"; do
    out=$("$tessera" $form 2>/dev/null) || fail "tessera $form: exit code $?"
    cmd=$(printf '%s\n' "$form" | sed -e 's/^help //' -e 's/ --help$//' -e 's/ -h$//')
    printf '%s\n' "$out" | grep -q -F "usage: tessera $cmd" ||
        fail "tessera $form: no \"usage: tessera $cmd\" on stdout"
done
echo "$(printf '%s\n' "$list" | wc -l) commands named"
[ $status -eq 0 ] && echo PASS
exit $status
