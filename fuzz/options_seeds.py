#!/usr/bin/env python3
"""options_seeds.py -- seeds of fuzz_options from the project's own command
lines: every `fp3 CMD ...` (also "$FP3" CMD, build/fp3 CMD, and the
`expect STATUS PATTERN -- CMD ...` lines of the test scripts) in
tests/*.sh, README.md and docs/*.md becomes fuzz/corpus/options/SOURCE-NNN,
one argument per line, the first the subcommand ("CMD model" when an
argument is a model scene and no --model names the model, as fp3 decides
by reading the scene).  Shell variables assigned a plain string or array in
the same file are expanded; any other `$...` argument becomes a file name
of the same kind (x.s, x.scene, ...).  Lines with placeholders of the
manual ([options], FILE, ...) are skipped; duplicates are written once.

  python3 fuzz/options_seeds.py [ROOT]     (default: the repository)

It adds files and removes none: run it after `rm fuzz/corpus/options/*-[0-9][0-9][0-9]`
to regenerate.
"""
import glob, os, re, shlex, sys
root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
out = os.path.join(root, "fuzz/corpus/options")
CMDS = {"asm", "disasm", "run", "compile", "spatial", "configure", "frames", "bench", "tbgen", "testfloat"}
inv = re.compile(r'(?:"\$\{?FP3(?:_BIN)?\}?"|\$\{?FP3(?:_BIN)?\}?|\bbuild/fp3|(?<![\w/.-])fp3)\s+(%s)\b(.*)' % "|".join(sorted(CMDS)))
exp = re.compile(r'^\s*expect\w*\s.*?\s--\s+()(.*)')
cut = re.compile(r'\s(?:\||>|2>|<|;|&&|\|\|)|\)\s*$|\)\s*[|;&]|`')

def is_model_scene(p):
    f = os.path.join(root, p)
    if not (p.endswith(".scene") and os.path.isfile(f)):
        return False
    for line in open(f):
        line = line.strip()
        if line and not line.startswith("#"):
            return line.split()[0] == "model"
    return False

def placeholder(tok):
    for ext in (".s", ".hex", ".scene", ".fp3m", ".csv", ".vcd", ".params"):
        if ext in tok:
            return "x" + ext
    return "x"

seen, n_by = set(), {}
for src in sorted(glob.glob(os.path.join(root, "tests/*.sh"))) + [os.path.join(root, "README.md")] + sorted(glob.glob(os.path.join(root, "docs/*.md"))):
    text = open(src).read().replace("\\\n", " ")
    assigns = dict(re.findall(r'^\s*(?:local\s+)?(\w+)="([^"$`]*)"\s*$', text, re.M))
    assigns.update(re.findall(r'^\s*(?:local\s+)?(\w+)=\(([^)$`]*)\)\s*$', text, re.M))
    name = os.path.splitext(os.path.basename(src))[0]
    for line in text.split("\n"):
        m = exp.match(line) or inv.search(line)
        if not m:
            continue
        cmd, rest = m.group(1), m.group(2)
        c = cut.search(rest)
        if c:
            rest = rest[:c.start()]
        try:
            toks = shlex.split(rest, comments=True)
        except ValueError:
            continue
        args = []
        for t in toks:
            v = re.fullmatch(r'\$\{?(\w+)(?:\[@\])?\}?', t)
            if v and v.group(1) in assigns:
                args += shlex.split(assigns[v.group(1)])
            elif "$" in t:
                args.append(placeholder(t))
            else:
                args.append(t)
        if not cmd:
            if not args or args[0] not in CMDS:
                continue
            cmd, args = args[0], args[1:]
        if any(a in ("...", "[options]", "[OPTIONS]") or a.startswith("[") or a.isupper() and len(a) > 1 for a in args):
            continue
        first = cmd + (" model" if any(is_model_scene(a) for a in args) and "--model" not in " ".join(args) else "")
        data = "\n".join([first] + args)
        if data in seen:
            continue
        seen.add(data)
        n_by[name] = n_by.get(name, 0) + 1
        with open(os.path.join(out, "%s-%03d" % (name, n_by[name])), "w") as f:
            f.write(data)
print(sum(n_by.values()), n_by)
