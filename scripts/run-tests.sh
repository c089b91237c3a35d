#!/usr/bin/env bash
# run-tests.sh -- run every test program given on the command line, count
# the cmocka test cases (and each script as one case), and print one closing
# line "tests: N passed, M failed".  Exit status non-zero on any failure.
set -u
passed=0; failed=0; failed_names=()
for t in "$@"; do
  echo "==> $t"
  log=$(mktemp)
  start=$(date +%s)
  if [[ "$t" == *.sh ]]; then bash "$t" 2>&1 | tee "$log"; rc=${PIPESTATUS[0]}
  else "$t" 2>&1 | tee "$log"; rc=${PIPESTATUS[0]}; fi
  secs=$(( $(date +%s) - start ))
  p=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' "$log" | awk '{s+=$1} END {print s+0}')
  f=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p' "$log" | awk '{s+=$1} END {print s+0}')
  if [ "$p" -eq 0 ] && [ "$f" -eq 0 ]; then   # a script: one case
    if [ "$rc" -eq 0 ]; then p=1; else f=1; fi
  elif [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then f=1; fi
  passed=$((passed + p)); failed=$((failed + f))
  [ "$f" -ne 0 ] && failed_names+=("$t")
  echo "<== $t: $p passed, $f failed (${secs}s)"
  rm -f "$log"
done
[ ${#failed_names[@]} -ne 0 ] && echo "failing: ${failed_names[*]}"
echo "tests: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
