#!/usr/bin/env bash
# test_progress.sh -- the progress line of long runs (sw/common/progress.h):
# on a terminal, a run that lasts more than 2 s shows it on stderr and
# erases it before the report; with stderr to a file, or with --json, there
# is none.  The terminal is a pseudo-terminal (python3's pty module) on
# stderr only, so stdout (the report) stays apart.
#
# Each run lasts a few seconds on the ISS (the line waits 2 s).  Whether a
# run is bit-exact is test_cli.sh's business: here a run ends with exit
# status 0 or 1 and its report's verdict (PASS or FAIL).  Runs from
# anywhere; the CLI is $FP3_BIN (set by mk/sw.mk), else build/fp3 of this
# checkout.  Exit status non-zero if any check fails.
set -u
cd "$(dirname "$0")/.."
FP3=${FP3_BIN:-$PWD/build/fp3}
if [ ! -x "$FP3" ]; then
  echo "test_progress: $FP3 not built (make $FP3)"; exit 1
fi
T=$(mktemp -d /tmp/fp3_test_progress.XXXXXX)
trap 'rm -rf "$T"' EXIT

pass=0; fail=0
ok()  { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*"; }

# on_tty OUT ERR CMD...: CMD with stdout to the file OUT and stderr on a
# pseudo-terminal, all that reached the terminal written to the file ERR.
# Returns CMD's exit status.
on_tty() {
  python3 - "$@" <<'PY'
import os, subprocess, sys
out, err, cmd = sys.argv[1], sys.argv[2], sys.argv[3:]
master, slave = os.openpty()
with open(out, "wb") as o:
    p = subprocess.Popen(cmd, stdin=subprocess.DEVNULL, stdout=o, stderr=slave)
os.close(slave)
seen = b""
while True:
    try:
        chunk = os.read(master, 4096)
    except OSError:  # EIO: the last writer closed the terminal
        break
    if not chunk:
        break
    seen += chunk
os.close(master)
open(err, "wb").write(seen)
sys.exit(p.wait())
PY
}

STEPS=1000000  # about 6 s on the ISS here
LINE="fp3 run: [0-9,]* of 1,000,000 integrations ([0-9.]* %), [0-9,.]*/s, about [0-9.]* [a-z]* left"

# ---- a terminal: the line, rewritten in place, erased at the end -------------------
# ran: exit 0 or 1, the report's last line its verdict
ran() { [ "$1" -le 1 ] && tail -1 "$2" | grep -q -e '^ *PASS' -e '^ *FAIL'; }

on_tty "$T/out" "$T/err" "$FP3" run --engine iss --steps $STEPS; rc=$?
if ! ran $rc "$T/out"; then
  bad "fp3 run --steps $STEPS on a terminal: exit $rc, report: $(tail -2 "$T/out")"
else ok; fi
if grep -a -q "$LINE" "$T/err"; then ok
else bad "no progress line on the terminal: $(head -c 300 "$T/err" | cat -A)"; fi
# every line starts with '\r'; the last output is the erase '\r' spaces '\r'
python3 - "$T/err" <<'PY' && ok || bad "the progress line is not erased at the end: $(tail -c 200 "$T/err" | cat -A)"
import re, sys
s = open(sys.argv[1], "rb").read().decode()
pieces = s.split("\r")
lines = [q for q in pieces if q.strip()]
sys.exit(0 if s.startswith("\r") and s.endswith("\r") and re.search(r"\r +\r$", s)
         and all(q.startswith("fp3 run: ") for q in lines) else 1)
PY
# the report on stdout has no trace of it
if grep -a -q -e "$LINE" -e $'\r' "$T/out"; then bad "progress on stdout: $(head -c 200 "$T/out" | cat -A)"
else ok; fi

# ---- stderr to a file: none, the same report -----------------------------------------
"$FP3" run --engine iss --steps $STEPS > "$T/out2" 2> "$T/err2"; rc=$?
if [ $rc -gt 1 ] || [ -s "$T/err2" ]; then
  bad "stderr to a file: exit $rc, stderr: $(head -c 200 "$T/err2" | cat -A)"
else ok; fi
if cmp -s "$T/out" "$T/out2"; then ok; else bad "the report differs with stderr to a file"; fi

# ---- --json on a terminal: none ---------------------------------------------------------
on_tty "$T/out3" "$T/err3" "$FP3" run --engine iss --steps $STEPS --json; rc=$?
if [ $rc -gt 1 ] || [ -s "$T/err3" ]; then
  bad "--json on a terminal: exit $rc, terminal: $(head -c 200 "$T/err3" | cat -A)"
else ok; fi
if python3 -c 'import json,sys; json.load(open(sys.argv[1]))' "$T/out3"; then ok
else bad "--json: not one JSON object"; fi

# ---- many objects count object-steps, frames count frames -------------------------------
on_tty "$T/out4" "$T/err4" "$FP3" run --engine iss --objects 64 --steps 10000; rc=$?
if ran $rc "$T/out4" && grep -a -q "fp3 run: [0-9,]* of 640,000 object-steps (" "$T/err4"; then ok
else bad "fp3 run --objects 64: exit $rc, terminal: $(head -c 200 "$T/err4" | cat -A)"; fi
on_tty "$T/out5" "$T/err5" "$FP3" frames --engine iss --frames 4000 --no-rest-skip; rc=$?
if [ $rc -le 1 ] && [ -s "$T/out5" ] && grep -a -q "fp3 frames: [0-9,]* of 4,000 frames (" "$T/err5"; then ok
else bad "fp3 frames --frames 4000: exit $rc, terminal: $(head -c 200 "$T/err5" | cat -A)"; fi

echo "test_progress: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
