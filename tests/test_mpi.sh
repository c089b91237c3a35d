#!/usr/bin/env bash
# test_mpi.sh -- build/fp3-mpi ($FP3_MPI_BIN) on 1, 2 and 3 MPI ranks of
# this machine gives fp3's ($FP3_BIN) output byte for byte: fp3 run of a
# model scene, of --objects N and of a ship scene, --json too; fp3 frames
# with sleeping and waking objects; the co-simulation campaign's seed
# digest (build/tests/test_engines-mpi against test_engines in one
# process); and faults: a rank whose engine fails or disagrees with the
# golden model fails the job naming rank, host and objects, a rank that
# dies (on purpose, or killed from outside mid-run) ends the job without a
# hang and with nothing on standard output.  docs/cluster.md.
set -euo pipefail
cd "$(dirname "$0")/.."
# CI runs as root: Open MPI refuses that unless told, here only.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fp3=${FP3_BIN:-build/fp3}
mpi=${FP3_MPI_BIN:-build/fp3-mpi}
cosim=${FP3_COSIM_MPI_BIN:-build/tests/test_engines-mpi}
cosim1=${FP3_COSIM_BIN:-build/tests/test_engines}
for b in "$fp3" "$mpi" "$cosim" "$cosim1"; do
  [ -x "$b" ] || { echo "FAIL: $b is not built (make test-build)"; exit 1; }
done
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
# mpirun with a bound: a job that hangs fails the test instead
mpi_run() { local np=$1; shift; timeout 120 mpirun --oversubscribe -np "$np" "$@"; }

# same NPS -- ARGS: fp3-mpi ARGS on each number of ranks of NPS prints what
# fp3 ARGS prints on stdout, and exits as it does.
same() {
  local nps=$1; shift 2
  set +e; "$fp3" "$@" > "$tmp/one" 2> "$tmp/one.err"; local want=$?; set -e
  for np in $nps; do
    set +e; mpi_run "$np" "$mpi" "$@" > "$tmp/many" 2> "$tmp/many.err"; local got=$?; set -e
    [ "$got" = "$want" ] || { cat "$tmp/many.err"; fail "fp3-mpi $* on $np ranks: exit $got, fp3: $want"; }
    cmp -s "$tmp/one" "$tmp/many" ||
      { diff "$tmp/one" "$tmp/many" | head -20 || true; fail "fp3-mpi $* on $np ranks: stdout differs from fp3's"; }
  done
  echo "ok: $* on ranks $nps = one process"
}

# ---- byte-identical ---------------------------------------------------------
# springs.scene: 24 objects, 3 batches of the default build's 8 contexts;
# on 2 ranks 1 + 2 batches, on 3 one batch each.
same "1 2 3" -- run --scene scenes/springs.scene --steps 100
same "2 3" -- run --scene scenes/springs.scene --steps 100 --json
# 5 batches, the last one part-filled; the ISS engine
same "2 3" -- run --model models/spring.fp3m --objects 37 --steps 60 --json
same "3" -- run --model models/spring.fp3m --objects 37 --steps 60 --engine iss
# a ship scene (the ship scene compiler's path: rank 0 runs it)
same "2" -- run --scene scenes/fleet.scene --steps 50
# frames: sleeping objects, each frame's awake ones in batches; waking
same "1 2 3" -- frames --harbour 100 --frames 100
same "2 3" -- frames --harbour 60 --frames 120 --wake 100:10:T=4*C --json
same "2" -- frames --scene scenes/springs.scene --frames 60
same "3" -- frames --scene scenes/fleet.scene --frames 60
# the per-rank lines on stderr: each rank's objects
mpi_run 2 "$mpi" run --scene scenes/springs.scene --steps 10 > /dev/null 2> "$tmp/err"
grep -q "^fp3-mpi: rank 0 of 2 (host .*): objects 0 .. 7, 80 object-steps in" "$tmp/err" &&
  grep -q "^fp3-mpi: rank 1 of 2 (host .*): objects 8 .. 23, 160 object-steps in" "$tmp/err" ||
  { cat "$tmp/err"; fail "no per-rank line, or not whole batches (8 objects) per rank"; }
echo "ok: per-rank lines, whole batches"

# ---- the co-simulation campaign: digest and counts --------------------------
FP3_RANDOM_FIRST=1000 FP3_RANDOM_PROGRAMS=20 "$cosim1" > "$tmp/c1" 2>&1 || { cat "$tmp/c1"; fail "test_engines on programs 1000 .. 1019"; }
want=$(sed -n 's/.*seed digest \(0x[0-9a-f]*\).*/\1/p' "$tmp/c1" | tail -1)
[ -n "$want" ] || { cat "$tmp/c1"; fail "test_engines printed no seed digest"; }
for np in 1 2 3; do
  FP3_RANDOM_FIRST=1000 FP3_RANDOM_PROGRAMS=20 mpi_run "$np" -x FP3_RANDOM_FIRST -x FP3_RANDOM_PROGRAMS \
    "$cosim" > "$tmp/cn" 2>&1 || { cat "$tmp/cn"; fail "test_engines-mpi on $np ranks failed"; }
  grep -q "^random programs 1000 .. 1019 on $np ranks: 0 failed; seed digest $want\$" "$tmp/cn" ||
    { grep "random programs\|rank" "$tmp/cn" || true; fail "test_engines-mpi on $np ranks: not digest $want of one process"; }
  [ "$(grep -c "^rank [0-9]* of $np (host .*): random programs .*: passed" "$tmp/cn")" = "$np" ] ||
    { cat "$tmp/cn"; fail "test_engines-mpi on $np ranks: not a passed line per rank"; }
done
echo "ok: co-simulation programs 1000 .. 1019 on 1, 2, 3 ranks: seed digest $want, as one process"

# ---- faults -----------------------------------------------------------------
# fault KIND:OBJECT NP -- ARGS: the job fails (exit 1 unless given), in time
fault() {
  local f=$1 np=$2; shift 3
  set +e; FP3_MPI_FAULT=$f mpi_run "$np" -x FP3_MPI_FAULT "$mpi" "$@" > "$tmp/out" 2> "$tmp/err"; rc=$?; set -e
  [ "$rc" != 124 ] || fail "FP3_MPI_FAULT=$f: the job hung"
  [ "$rc" != 0 ] || { cat "$tmp/err"; fail "FP3_MPI_FAULT=$f: the job passed"; }
}
fault engine:20 3 -- run --scene scenes/springs.scene --steps 50
[ "$rc" = 1 ] || fail "engine fault: exit $rc, not 1"
grep -q "^fp3 run: rtl engine: rank 2 of 3 (host .*), objects 16 .. 23: the engine does not answer" "$tmp/err" ||
  { cat "$tmp/err"; fail "engine fault: rank, host and objects not named"; }
[ ! -s "$tmp/out" ] || fail "engine fault: something on stdout"
fault golden:9 2 -- run --scene scenes/springs.scene --steps 50 --json
[ "$rc" = 1 ] || fail "golden fault: exit $rc, not 1"
grep -q "^fp3-mpi: rank 1 of 2 (host .*): object 9: 50 golden mismatches" "$tmp/err" ||
  { cat "$tmp/err"; fail "golden fault: rank, host and object not named"; }
python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert d["pass"] is False and d["first_mismatch"]["object"] == 9' "$tmp/out" ||
  fail "golden fault: the JSON is not whole, or does not name object 9"
fault engine:41 2 -- frames --harbour 100 --frames 40
[ "$rc" = 1 ] || fail "frames engine fault: exit $rc, not 1"
grep -q "^fp3 frames: rank [01] of 2 (host .*), objects .*: the engine does not answer" "$tmp/err" ||
  { cat "$tmp/err"; fail "frames engine fault: rank, host and objects not named"; }
[ ! -s "$tmp/out" ] || fail "frames engine fault: something on stdout"
fault kill:12 3 -- run --scene scenes/springs.scene --steps 50
[ ! -s "$tmp/out" ] || fail "a rank killed itself: something on stdout"
grep -q "rank 1 .*exited on signal 9" "$tmp/err" || { cat "$tmp/err"; fail "kill: mpirun does not name rank 1"; }
echo "ok: faults (engine, golden, frames, a rank that dies) fail the job, named"

# A rank killed from outside in the middle of a long run: mpirun ends the
# job within 30 s, exit not 0, nothing on stdout.
mpirun --oversubscribe -np 2 "$mpi" run --model models/spring.fp3m --objects 400 --steps 4000 \
  > "$tmp/out" 2> "$tmp/err" &
mpid=$!
victim=
for _ in $(seq 300); do
  for p in $(pgrep -P "$mpid" || true); do
    tr '\0' '\n' < "/proc/$p/environ" 2>/dev/null | grep -qx OMPI_COMM_WORLD_RANK=1 && victim=$p
  done
  [ -n "$victim" ] && break
  sleep 0.1
done
[ -n "$victim" ] || { kill "$mpid"; fail "rank 1 of the long run not found"; }
sleep 2
kill -KILL "$victim"
for _ in $(seq 300); do kill -0 "$mpid" 2>/dev/null || break; sleep 0.1; done
if kill -0 "$mpid" 2>/dev/null; then kill -KILL "$mpid"; fail "mpirun still runs 30 s after rank 1 was killed"; fi
set +e; wait "$mpid"; rc=$?; set -e
[ "$rc" != 0 ] || fail "rank 1 killed: mpirun exited 0"
[ ! -s "$tmp/out" ] || fail "rank 1 killed: something on stdout"
echo "ok: rank 1 killed mid-run: the job ended (exit $rc), stdout empty"
echo "PASS: fp3-mpi = fp3 on 1, 2, 3 ranks; co-simulation digest; faults"
