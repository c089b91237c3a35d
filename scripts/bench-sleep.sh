#!/usr/bin/env bash
# bench-sleep.sh FP3 OUTDIR SHIPS FRAMES -- what sleeping saves on a harbour
# (make bench-sleep; docs/skipping.md "Sleeping objects").
#
# `fp3 frames --harbour SHIPS` (60 % moored, 35 % cruising at terminal
# velocity, 5 % accelerating; h = 1/60 s) for FRAMES frames on the RTL,
# every object checked bit for bit against the RK4 golden model after
# every frame, in three configurations:
#   awake        programs/ship_rk4.s, every object run every frame
#   beq          programs/ship_rk4_sleep.s: settled velocities skip the
#                velocity stages (in the program, with beq)
#   beq+rest     ... and the host skips objects at rest (whole register
#                bank unchanged by a frame)
# and once more beq+rest with a wake (10 % of the ships get thrust half
# way).  Writes OUTDIR/sleep.csv and OUTDIR/sleep.md.
set -eu
FP3=$1; OUT=$2; N=$3; F=$4
mkdir -p "$OUT"
csv="$OUT/sleep.csv"; md="$OUT/sleep.md"
fields="cycles_per_frame issued_per_frame object_frames_run object_frames_skipped asleep_at_end woken host_words_per_frame fmax_mhz frames_per_second golden_mismatches pass"
echo "config,objects,frames,$(echo $fields | tr ' ' ',')" >"$csv.tmp"
rc=0
run() {  # NAME ARGS...
  name=$1; shift
  echo "bench-sleep: $name: $FP3 frames --harbour $N --frames $F $*" >&2
  json=$("$FP3" frames --harbour "$N" --frames "$F" --json "$@") || rc=1
  python3 - "$name" "$N" "$F" "$fields" "$json" >>"$csv.tmp" <<'PY'
import json, sys
name, n, f, fields, text = sys.argv[1:6]
d = json.loads(text)
print(','.join([name, n, f] + [str(d[k]).lower() if isinstance(d[k], bool) else str(d[k])
                                for k in fields.split()]))
PY
}
run awake --program programs/ship_rk4.s --no-rest-skip
run beq --no-rest-skip
run beq+rest
run beq+rest+wake --wake $((F / 2)):$((N / 10)):T=4*C
mv "$csv.tmp" "$csv"
python3 - "$csv" "$md" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
base = float(rows[0]['cycles_per_frame'])
with open(sys.argv[2] + '.tmp', 'w') as o:
    o.write('| configuration | cycles per frame | vs awake | instructions per frame | '
            'object-frames run | skipped at rest | at rest at the end | woken | '
            f"frames/s at {rows[0]['fmax_mhz']} MHz | golden mismatches |\n")
    o.write('| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n')
    for r in rows:
        c = float(r['cycles_per_frame'])
        o.write(f"| {r['config']} | {c:,.1f} | {base / c:.2f}x | {float(r['issued_per_frame']):,.1f} | "
                f"{int(r['object_frames_run']):,} | {int(r['object_frames_skipped']):,} | "
                f"{r['asleep_at_end']} | {r['woken']} | {float(r['frames_per_second']):,.0f} | "
                f"{r['golden_mismatches']} |\n")
import os
os.replace(sys.argv[2] + '.tmp', sys.argv[2])
PY
cat "$md"
exit $rc
