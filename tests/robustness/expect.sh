#!/usr/bin/env bash
# Usage: expect.sh WANT_RC CMD [ARGS...]
# Runs CMD, shows its output, then prints one verdict line
#   verdict: exit WANT_RC as expected; <first "input error|numerical fault|warning" line>
# or, when the exit code differs, "verdict: FAILED ..." (and exits 1).  The
# CTest tests match the verdict line with PASS_REGULAR_EXPRESSION, so they
# check the exit code and the message together.
want=$1
shift
out=$("$@" 2>&1)
rc=$?
printf '%s\n' "$out"
first=$(printf '%s\n' "$out" | grep -m1 -E '^(input error|numerical fault|warning|error|data problem|interrupted at)')
if [ "$rc" = "$want" ]; then
  echo "verdict: exit $rc as expected; $first"
else
  echo "verdict: FAILED: exit $rc, expected $want"
  exit 1
fi
