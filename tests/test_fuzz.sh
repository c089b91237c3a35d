#!/usr/bin/env bash
# test_fuzz.sh -- the fuzz harnesses in make test (mk/fuzz.mk).
#
# 1. Replay: every seed (scripts/fuzz.sh --seeds NAME: fuzz/regress/NAME/,
#    inputs that once made a parser fail, kept after the fix; fuzz/corpus/
#    NAME/; the project's programs, scenes or models) runs once through
#    build/fuzz/fuzz_NAME, which is built with ASan and UBSan: a crash,
#    leak, hang (10 s) or sanitizer report fails the test.
# 2. Fuzz: each harness FUZZ_TEST_SECONDS (default 10) from its seeds in a
#    fresh working folder (scripts/fuzz.sh); a crash fails the test and
#    the reproducer's path is printed (the folder is then kept).
#
# Environment (exported by mk/fuzz.mk): FUZZ_BIN_DIR, FUZZ_HARNESSES.
set -u
cd "$(dirname "$0")/.."
bindir=${FUZZ_BIN_DIR:-build/fuzz}
names=${FUZZ_HARNESSES:-asm image scene model testfloat options}
secs=${FUZZ_TEST_SECONDS:-10}
fail=0

for name in $names; do
  bin=$bindir/fuzz_$name
  if [ ! -x "$bin" ]; then
    echo "FAIL $name: no harness $bin"
    fail=1
    continue
  fi
  files=()
  while IFS= read -r f; do files+=("$f"); done < <(bash scripts/fuzz.sh --seeds "$name")
  if [ ${#files[@]} -eq 0 ]; then # libFuzzer given no file would fuzz
    echo "FAIL $name: no seed or regression input"
    fail=1
    continue
  fi
  log=$(mktemp)
  if "$bin" -close_fd_mask=3 -timeout=10 "${files[@]}" >"$log" 2>&1; then
    echo "ok   $name: ${#files[@]} regression and seed inputs replayed under ASan/UBSan"
  else
    echo "FAIL $name: replay of the regression and seed inputs"
    grep 'Running: ' "$log" | tail -1 | sed 's/^/  /' # the input that failed
    grep -m5 -E '^==[0-9]+==ERROR|runtime error:|^SUMMARY:' "$log" | sed 's/^/  /'
    fail=1
  fi
  rm -f "$log"
done

work=$(mktemp -d)
if FUZZ_WORK=$work bash scripts/fuzz.sh "$secs" "$bindir" $names; then
  rm -rf "$work"
else
  echo "FAIL fuzzing (reproducers and logs kept in $work)"
  fail=1
fi
exit $fail
