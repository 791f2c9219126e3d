#!/usr/bin/env bash
# cli_table.sh RODVV TABLE WORKDIR: runs every row of TABLE (EXIT | TEXT | ARGS, see bad_inputs.txt)
# through RODVV and checks the exit code and that stdout+stderr contain TEXT. Prints every mismatch
# and the count; exits 1 if any row fails. WORK in ARGS is replaced by WORKDIR; '' is an empty argument.
set -u
rodvv=$1; table=$2; work=$3
rows=0; failures=0
while IFS= read -r line; do
  [[ -z "${line// }" || "$line" == \#* ]] && continue
  expected_exit=$(echo "${line%%|*}" | xargs)
  rest=${line#*|}
  text=$(echo "${rest%%|*}" | sed 's/^ *//; s/ *$//')
  args_text=$(echo "${rest#*|}" | sed 's/^ *//; s/ *$//')
  args_text=${args_text//WORK/$work}
  args=()
  for word in $args_text; do
    if [[ "$word" == "''" ]]; then args+=(""); else args+=("$word"); fi
  done
  rows=$((rows + 1))
  output=$("$rodvv" "${args[@]}" 2>&1); code=$?
  if [[ $code -ne $expected_exit || "$output" != *"$text"* ]]; then
    failures=$((failures + 1))
    printf 'FAIL: rodvv %s\n  expected exit %s and "%s"; got exit %s:\n%s\n' "$args_text" "$expected_exit" "$text" "$code" \
      "$(echo "$output" | tail -3)"
  fi
done < "$table"
echo "$rows rows, $failures failed"
[[ $rows -ge 60 && $failures -eq 0 ]]
