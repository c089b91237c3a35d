#!/usr/bin/env python3
"""same_results.py -- two `fp3 run --json` objects (docs/json.md) of one
run on two engines: A valid against docs/fp3.schema.json, pass true in
both, A without golden-model mismatches, the same "results" (every
object's state, golden value, reference) and the same exception flags
(flags_bits: the operations are the golden model's on both).  Prints one line comparing
them; exit status 0 when all holds, else 1.

    tests/same_results.py A.json B.json   (run from the repository root)
"""
import json
import sys

import jsonschema

a, b = (json.load(open(p)) for p in sys.argv[1:3])
jsonschema.validate(a, json.load(open("docs/fp3.schema.json")))
ok = (a["pass"] and b["pass"] and a["results"] == b["results"] and a["golden_mismatches"] == 0
      and a["flags_bits"] == b["flags_bits"])
print(f"  {a['engine']}: pass {a['pass']}, {a['golden_mismatches']} mismatches, cycles {a['cycles']}; "
      f"{b['engine']}: pass {b['pass']}, cycles {b['cycles']}; "
      f"results {'equal' if a['results'] == b['results'] else 'DIFFER'}; "
      f"flags {a['flags']} / {b['flags']}")
sys.exit(0 if ok else 1)
