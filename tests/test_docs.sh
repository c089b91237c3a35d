#!/usr/bin/env bash
# test_docs.sh -- the documentation holds together: README.md stays a
# manual of at most 450 lines, and every relative Markdown link in
# README.md and docs/*.md reaches a file of the repository and, for
# `FILE.md#anchor` or `#anchor`, a heading of that file.
#
# Anchors follow GitHub's rule for a heading's id: the heading's text as
# rendered (a link's text, a code span's content), lowercased; every
# character removed except letters, combining marks, decimal and letter
# numbers, connector punctuation (`_`), hyphens and spaces; spaces become
# hyphens; a repeated id gets -1, -2, ... in order.  So `FP³` gives `fp`
# (³ is an "other number", removed) and `h/τ` gives `hτ` (τ is a letter).
# Links inside fenced code blocks and code spans are not links; links with
# a scheme (https:, mailto:) are not checked (no network).
#
# Usage: tests/test_docs.sh [ROOT]   (default: the repository holding it)
# Exit status 0 when all hold, 1 with one line per broken link otherwise.
set -euo pipefail
root=${1:-$(cd "$(dirname "$0")/.." && pwd)}
python3 - "$root" <<'PY'
import os
import re
import sys
import unicodedata

MAX_README_LINES = 450
root = os.path.realpath(sys.argv[1])

FENCE = re.compile(r"^ {0,3}(`{3,}|~{3,})")
HEADING = re.compile(r"^ {0,3}(#{1,6})[ \t]+(.*?)[ \t]*#*[ \t]*$")
LINK = re.compile(r"!?\[((?:[^\[\]]|\[[^\[\]]*\])*)\]\(\s*<?([^)\s>]*)>?(?:\s+\"[^\"]*\")?\s*\)")
CODE_SPAN = re.compile(r"(`+)(.+?)\1")
# A code span may run over lines of one paragraph, not over a blank line.
CODE_SPAN_MULTI = re.compile(r"(`+)((?:(?!\n[ \t]*\n).)+?)\1", re.S)
SCHEME = re.compile(r"^[A-Za-z][A-Za-z0-9+.-]*:")


def prose_lines(text):
    """(line number, line) of the lines outside fenced code blocks."""
    fence = None
    for n, line in enumerate(text.split("\n"), 1):
        m = FENCE.match(line)
        if fence is None:
            if m:
                fence = m.group(1)
                continue
            yield n, line
        elif m and m.group(1)[0] == fence[0] and len(m.group(1)) >= len(fence) \
                and not line.strip()[len(m.group(1)):].strip():
            fence = None


def rendered(heading):
    """The text GitHub renders for a heading's Markdown source."""
    text = CODE_SPAN.sub(lambda m: m.group(2).strip(), heading)
    text = LINK.sub(lambda m: m.group(1), text)
    text = re.sub(r"<[^>]*>", "", text)
    return text


def slug_base(text):
    """GitHub's id of a heading's rendered text, before de-duplication."""
    out = []
    for ch in text.lower():
        cat = unicodedata.category(ch)
        if ch in " -" or cat[0] in "LM" or cat in ("Nd", "Nl", "Pc"):
            out.append("-" if ch == " " else ch)
    return "".join(out)


def anchors(text):
    """The set of heading ids of a Markdown text, duplicates numbered."""
    seen, ids = {}, set()
    for _, line in prose_lines(text):
        m = HEADING.match(line)
        if not m:
            continue
        base = slug_base(rendered(m.group(2)))
        k = seen.get(base, 0)
        seen[base] = k + 1
        ids.add(base if k == 0 else f"{base}-{k}")
    return ids


def self_test():
    """The rule on the cases it must get right (a wrong rule fails here)."""
    cases = {
        "FP³ — Field-Programmable Physics Processor": "fp--field-programmable-physics-processor",
        "Sleeping objects: `beq` and `fp3 frames`": "sleeping-objects-beq-and-fp3-frames",
        "Numerics: FP cores, integrators, work-precision, stability, long runs":
            "numerics-fp-cores-integrators-work-precision-stability-long-runs",
        "The `fp3_top` module": "the-fp3_top-module",
        "Bound h/τ (theory)": "bound-hτ-theory",
        "See [the ISA](isa.md#x) here": "see-the-isa-here",
        "Why 113 cycles per integration": "why-113-cycles-per-integration",
    }
    bad = [(h, slug_base(rendered(h)), want) for h, want in cases.items()
           if slug_base(rendered(h)) != want]
    dup = anchors("# Usage\n\n## Usage\n\n```\n# Usage\n```\n### Usage\n")
    if dup != {"usage", "usage-1", "usage-2"}:
        bad.append(("three headings 'Usage' and one in a code block", sorted(dup),
                    ["usage", "usage-1", "usage-2"]))
    for h, got, want in bad:
        print(f"FAIL: the anchor rule: {h!r} gives {got!r}, GitHub gives {want!r}")
    return not bad


def inside(path):
    return path == root or path.startswith(root + os.sep)


def prose(text):
    """The text with fenced code blocks and code spans blanked (newlines
    kept, so offsets give line numbers): what is left can hold links."""
    keep = dict(prose_lines(text))
    lines = [line if n in keep else "" for n, line in enumerate(text.split("\n"), 1)]
    text = "\n".join(lines)
    return CODE_SPAN_MULTI.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)


def check(md_path, problems, cache):
    rel_md = os.path.relpath(md_path, root)
    with open(md_path, encoding="utf-8") as f:
        text = prose(f.read())
    for m in LINK.finditer(text):
        target = m.group(2)
        if not target or SCHEME.match(target):
            continue
        n = text.count("\n", 0, m.start()) + 1
        path, _, anchor = target.partition("#")
        dest = md_path if not path else os.path.realpath(
            os.path.join(os.path.dirname(md_path), path))
        where = f"{rel_md}:{n}: link '{target}'"
        if not inside(dest):
            problems.append(f"{where}: outside the repository")
            continue
        if not os.path.exists(dest):
            problems.append(f"{where}: no file {os.path.relpath(dest, root)}")
            continue
        if anchor and dest.endswith(".md"):
            if dest not in cache:
                with open(dest, encoding="utf-8") as f:
                    cache[dest] = anchors(f.read())
            if anchor not in cache[dest]:
                problems.append(f"{where}: no heading #{anchor} in "
                                f"{os.path.relpath(dest, root)}")


ok = self_test()
problems = []
readme = os.path.join(root, "README.md")
with open(readme, encoding="utf-8") as f:
    lines = f.read().count("\n")
if lines > MAX_README_LINES:
    problems.append(f"README.md: {lines} lines, more than {MAX_README_LINES}: "
                    "move the topic into docs/")
docs = os.path.join(root, "docs")
files = [readme] + sorted(os.path.join(docs, f) for f in os.listdir(docs) if f.endswith(".md"))
cache = {}
for md in files:
    check(md, problems, cache)
for p in problems:
    print("FAIL:", p)
if problems or not ok:
    sys.exit(1)
print(f"PASS: test_docs (README.md {lines} lines; the links of {len(files)} files reach "
      "their files and headings)")
PY
