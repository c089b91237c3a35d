#!/usr/bin/env bash
# fuzz.sh -- run libFuzzer harnesses for a fixed time each (make fuzz,
# tests/test_fuzz.sh).
#
#   bash scripts/fuzz.sh SECONDS BINDIR NAME...
#
# Each harness BINDIR/fuzz_NAME starts from a working copy of its seeds,
# WORK/corpus/NAME (seeded from fuzz/corpus/NAME and fuzz/regress/NAME,
# and kept between runs so that a longer campaign resumes; WORK is
# $FUZZ_WORK, default BINDIR), and runs SECONDS.  One line per harness: "fuzz NAME: N executions in S s (E
# exec/s), corpus K inputs, 0 crashes", from libFuzzer's final statistics.
# A crash, leak, timeout or sanitizer report ends that harness: the script
# prints the reproducer's path (WORK/crashes/NAME/...) and the command
# that replays it, goes on with the other harnesses, and exits 1.
# libFuzzer's log of each run is WORK/logs/NAME.log.
set -u
if [ $# -lt 3 ]; then
  echo "usage: fuzz.sh SECONDS BINDIR NAME..." >&2
  exit 2
fi
secs=$1 bindir=$2
workdir=${FUZZ_WORK:-$bindir}
shift 2
here=$(cd "$(dirname "$0")/.." && pwd)
failed=0
for name in "$@"; do
  bin=$bindir/fuzz_$name
  work=$workdir/corpus/$name
  crashes=$workdir/crashes/$name
  log=$workdir/logs/$name.log
  mkdir -p "$work" "$crashes" "$(dirname "$log")"
  if [ ! -x "$bin" ]; then
    echo "fuzz $name: no harness $bin (make fuzz-build)"
    failed=1
    continue
  fi
  for d in "$here/fuzz/corpus/$name" "$here/fuzz/regress/$name"; do
    [ -d "$d" ] && find "$d" -maxdepth 1 -type f ! -name '.*' -exec cp -n {} "$work/" \;
  done
  # -close_fd_mask=3: the parsers' own messages (stdout, stderr) are
  # silenced; libFuzzer and the sanitizers keep a copy of stderr for their
  # reports.  -timeout: an input that takes 10 s is a hang.
  "$bin" -max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 -max_len=4096 \
    -close_fd_mask=3 -print_final_stats=1 -artifact_prefix="$crashes/" "$work" >"$log" 2>&1
  rc=$?
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  units=$(find "$work" -maxdepth 1 -type f | wc -l)
  repro=$(sed -n "s/.*Test unit written to \(.*\)$/\1/p" "$log" | tail -1)
  if [ "$rc" -eq 0 ] && [ -z "$repro" ]; then
    echo "fuzz $name: ${execs:-?} executions in $secs s (${rate:-?} exec/s), corpus $units inputs, 0 crashes"
  else
    failed=1
    echo "fuzz $name: FAILED after ${execs:-?} executions (${rate:-?} exec/s), exit status $rc"
    grep -m3 -E '^==[0-9]+==ERROR|runtime error:|^SUMMARY:|ERROR: libFuzzer' "$log" | sed 's/^/  /'
    if [ -n "$repro" ]; then
      echo "  reproducer: $repro"
      echo "  replay: $bin $repro"
    fi
    echo "  log: $log"
  fi
done
exit $failed
