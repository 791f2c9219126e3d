#!/usr/bin/env bash
# cli_expect.sh EXPECTED_EXIT EXPECTED_TEXT COMMAND... : runs COMMAND, checks its exit code and that
# stdout+stderr contain EXPECTED_TEXT (empty = no check). Used by the CLI tests in CTest.
set -u
expected_exit=$1; expected_text=$2; shift 2
output=$("$@" 2>&1); code=$?
if [[ $code -ne $expected_exit ]]; then
  printf 'expected exit %s, got %s from: %s\n%s\n' "$expected_exit" "$code" "$*" "$output"; exit 1
fi
if [[ -n "$expected_text" && "$output" != *"$expected_text"* ]]; then
  printf 'expected output to contain "%s" from: %s\n%s\n' "$expected_text" "$*" "$output"; exit 1
fi
exit 0
