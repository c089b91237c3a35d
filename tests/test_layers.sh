#!/usr/bin/env bash
# test_layers.sh -- the dependency arrows of sw/ point one way.
#
# Each folder of sw/ is one layer, ranked from the bottom up:
#   common (formatting and file helpers, the progress line) < isa (assembler, disassembler,
#   program images) < ref (golden models and references) < model (the
#   model language: parser, literal golden model, GSL reference) < engine (ISS,
#   RTL engine, vector runner) < scene (many objects, sleeping) <
#   compiler (scene compiler, configurator) < bench < cli (the fp3 tool).
# A file may include headers of its own layer and of layers below it,
# never above: the library never includes a CLI file.  The ISA's one
# table, sw/isa/fp3_isa.h, is the root that every layer may include.
set -euo pipefail
cd "$(dirname "$0")/.."
python3 - <<'PY'
import glob, os, re, sys
order = ["common", "isa", "ref", "model", "engine", "scene", "compiler", "bench", "cli"]
rank = {l: i for i, l in enumerate(order)}
where = {}
for f in glob.glob("sw/*/*.[ch]"):
    layer = f.split("/")[1]
    if layer not in rank:
        sys.exit(f"FAIL: {f}: folder sw/{layer} is not a known layer (tests/test_layers.sh)")
    base = os.path.basename(f)
    if base in where:
        sys.exit(f"FAIL: two headers or sources named {base}: {where[base]} and {f}")
    where[base] = f
bad = 0
for f in sorted(glob.glob("sw/*/*.[ch]")):
    layer = f.split("/")[1]
    for n, line in enumerate(open(f), 1):
        m = re.match(r'\s*#\s*include\s+"([^"]+)"', line)
        if not m or m.group(1) == "fp3_isa.h":
            continue
        inc = where.get(m.group(1))
        if inc is None:
            continue
        dep = inc.split("/")[1]
        if rank[dep] > rank[layer]:
            print(f"FAIL: {f}:{n}: sw/{layer} includes {inc} of the higher layer sw/{dep}")
            bad += 1
if bad:
    sys.exit(1)
print(f"PASS: {len(where)} files in {len(order)} layers, every include points down")
PY
