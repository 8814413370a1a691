#!/usr/bin/env bash
# expect.sh CODE PATTERN COMMAND...: runs COMMAND, passes when it exits with CODE (a crash, which
# exits by a signal, never matches) and its output contains PATTERN.
set -u
code=$1; pattern=$2; shift 2
out=$("$@" 2>&1); rc=$?
printf '%s\n' "$out"
if [ "$rc" -ne "$code" ]; then echo "expect.sh: exit code $rc, expected $code" >&2; exit 1; fi
if ! printf '%s' "$out" | grep -qF -- "$pattern"; then
  echo "expect.sh: output lacks '$pattern'" >&2; exit 1
fi
