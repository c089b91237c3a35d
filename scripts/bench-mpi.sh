#!/usr/bin/env bash
# bench-mpi.sh -- object-steps per second of build/fp3-mpi against the
# number of MPI ranks (make bench-mpi, docs/cluster.md).
#
#   scripts/bench-mpi.sh [--np "1 2"] [--label NAME] FP3_MPI fp3-ARGS...
#
# For each number of ranks N of --np (default "1 2"), runs
# `mpirun -np N $MPI_RUN_FLAGS FP3_MPI fp3-ARGS` (MPI_RUN_FLAGS default
# --oversubscribe; add --hostfile FILE for a cluster) and reports: the
# wall seconds of the job, the object-steps (or object-frames) of the
# ranks' lines, object-steps per second, the speed-up over the first N
# and the parallel efficiency (speed-up / (N / first N)); each rank's
# object-steps per CPU second (what other load on the machine does not
# change); and the bytes rank 0 gathered.  Every N's standard output must
# equal the first N's, byte for byte (else exit 1): the sharding changes
# no result.  A benchmark: it fails only when a run fails or differs,
# never on a speed.
set -euo pipefail
usage() { sed -n '2,18p' "$0" | sed 's/^# \{0,1\}//'; }
nps="1 2" label=run
while [ $# -gt 0 ]; do
  case $1 in
    --np) [ $# -ge 2 ] || { usage >&2; exit 2; }; nps=$2; shift 2;;
    --label) [ $# -ge 2 ] || { usage >&2; exit 2; }; label=$2; shift 2;;
    -h|--help) usage; exit 0;;
    *) break;;
  esac
done
[ $# -ge 2 ] || { usage >&2; exit 2; }
bin=$1; shift
[ -x "$bin" ] || { echo "bench-mpi.sh: '$bin' is not an executable (make build/fp3-mpi)" >&2; exit 2; }
for np in $nps; do [[ "$np" =~ ^[1-9][0-9]*$ ]] || { echo "bench-mpi.sh: bad rank count '$np'" >&2; exit 2; }; done
flags=${MPI_RUN_FLAGS:---oversubscribe}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
calc() { awk "BEGIN { printf \"%.9f\", $1 }"; }

echo "bench-mpi ($label): $bin $*"
printf '%6s %10s %14s %16s %9s %11s  %s\n' ranks "wall [s]" work "per second" speed-up efficiency "per rank: per CPU second"
first= wall1= np1=
for np in $nps; do
  t0=$(date +%s.%N)
  # shellcheck disable=SC2086
  if ! mpirun $flags -np "$np" "$bin" "$@" > "$tmp/out.$np" 2> "$tmp/err.$np"; then
    cat "$tmp/err.$np" >&2
    echo "bench-mpi.sh: the run on $np ranks failed" >&2
    exit 1
  fi
  t1=$(date +%s.%N)
  if [ -z "$first" ]; then first=$np; wall1=$(calc "$t1 - $t0"); np1=$np
  elif ! cmp -s "$tmp/out.$first" "$tmp/out.$np"; then
    echo "bench-mpi.sh: the output on $np ranks differs from the output on $first" >&2; exit 1
  fi
  wall=$(calc "$t1 - $t0")
  work=$(sed -n 's/^fp3-mpi: rank [0-9]* of [0-9]* (host [^)]*):.*[ ,]\([0-9][0-9]*\) object-\(steps\|frames\) in .*/\1/p' "$tmp/err.$np" |
         awk '{ s += $1 } END { print s + 0 }')
  unit=$(sed -n 's/^fp3-mpi: rank 0 of .* \(object-steps\|object-frames\) in .*/\1/p' "$tmp/err.$np")
  percpu=$(sed -n 's/^fp3-mpi: rank \([0-9]*\) of .*, \([0-9]*\) per CPU second.*/\2/p' "$tmp/err.$np" | paste -sd' ')
  moved=$(sed -n 's/^fp3-mpi: [0-9]* ranks, \([0-9]*\) bytes .*(\([0-9.]*\) per \(.*\))$/\1 bytes, \2 per \3/p' "$tmp/err.$np")
  speed=$(calc "$wall1 / $wall")
  eff=$(calc "$speed / ($np / $np1)")
  printf '%6s %10.2f %14s %16.0f %9.3f %10.1f %%  %s\n' "$np" "$wall" "$work $unit" \
    "$(calc "$work / $wall")" "$speed" "$(calc "100 * $eff")" "$percpu"
  echo "       gathered on rank 0: $moved"
done
