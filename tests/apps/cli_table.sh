#!/usr/bin/env bash
# cli_table.sh RODVV TABLE WORKDIR [I/K]: runs every row of TABLE (EXIT | TEXT | ARGS, see
# bad_inputs.txt) through RODVV and checks the exit code and that stdout+stderr contain TEXT. Prints
# every mismatch and the count; exits 1 if any row fails, or if the table has fewer than 60 rows.
# WORK in ARGS is replaced by WORKDIR; '' is an empty argument. With I/K, only the rows whose index
# is I modulo K (1 <= I <= K): the K shards are K CTest tests that run in parallel.
set -u
rodvv=$1; table=$2; work=$3; shard=${4:-1/1}
shard_index=${shard%/*}; shard_count=${shard#*/}
if ! [[ "$shard_index" =~ ^[0-9]+$ && "$shard_count" =~ ^[0-9]+$ ]] ||
   (( shard_index < 1 || shard_index > shard_count )); then
  echo "cli_table.sh: shard '$shard' must be I/K with 1 <= I <= K" >&2; exit 2
fi
mkdir -p "$work"
table_rows=0; rows=0; failures=0
while IFS= read -r line; do
  [[ -z "${line// }" || "$line" == \#* ]] && continue
  table_rows=$((table_rows + 1))
  (( (table_rows - 1) % shard_count == shard_index - 1 )) || continue
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
echo "$rows rows (shard $shard of a $table_rows-row table), $failures failed"
[[ $table_rows -ge 60 && $rows -ge 1 && $failures -eq 0 ]]
