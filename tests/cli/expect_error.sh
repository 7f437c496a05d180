#!/bin/sh
# Runs a command that must fail cleanly: exit code 1 or 2 (never a signal, never a sanitizer
# report) and a message on stderr that contains every '|'-separated piece of $1.
# usage: expect_error.sh 'piece one|piece two' COMMAND [ARGS...]
expected=$1
shift
err=$(mktemp)
"$@" >/dev/null 2>"$err"
rc=$?
status=0
if [ "$rc" -ne 1 ] && [ "$rc" -ne 2 ]; then
    echo "FAIL: exit code $rc (expected 1 or 2) from: $*"
    status=1
fi
if grep -q -E 'AddressSanitizer|runtime error:|LeakSanitizer' "$err"; then
    echo "FAIL: sanitizer report from: $*"
    status=1
fi
old_ifs=$IFS
IFS='|'
for piece in $expected; do
    if ! grep -q -F -- "$piece" "$err"; then
        echo "FAIL: message lacks \"$piece\""
        status=1
    fi
done
IFS=$old_ifs
echo "--- stderr of: $*"
cat "$err"
rm -f "$err"
[ $status -eq 0 ] && echo "PASS"
exit $status
