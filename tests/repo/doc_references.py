#!/usr/bin/env python3
"""Every document the repository names exists, with the section it names.

usage: doc_references.py SOURCE_DIR [ROLLKIN]

The rule (docs/reliability.md, "Comments and messages name what exists"): a source, a message, a help text or a
document that names a docs/*.md file names one that exists, and a section it names after it
(`docs/analysis.md, "Design check"`) is a heading of that document. Checked here over every text file of src/,
include/, python/, bench/, tests/, scripts/, examples/, README.md and docs/ (in docs/ also the links and names
relative to docs/), and, with ROLLKIN, over the --help text of every command, which names its section of
docs/cli.md. A heading matches when it contains the section's words (case and backticks ignored).
Exit 0 when every reference resolves; 1 with one line per one that does not.
"""
import os
import re
import subprocess
import sys

SOURCE = os.path.abspath(sys.argv[1])
ROLLKIN = sys.argv[2] if len(sys.argv) > 2 else None
DIRS = ["src", "include", "python", "bench", "tests", "scripts", "examples"]
TOP_FILES = ["README.md", "CMakeLists.txt"]
TEXT_SUFFIXES = {".cpp", ".hpp", ".hxx", ".h", ".in", ".py", ".sh", ".md", ".txt", ".cmake", ".json", ".js", ".css"}

# A docs/ path ending in .md, optionally followed by ', "Section"' (a C++ string writes the quotes as \").
DOC_REF = re.compile(r'(docs/[A-Za-z0-9_./-]+\.md)(?:\)?,? \\?"([^"\\]+)\\?")?')
# Inside docs/: a link or a name relative to docs/ ("[cli.md](cli.md)", "(cli.md, \"rollkin contours\")").
LOCAL_REF = re.compile(r'(?:\]\(|[\s(])([A-Za-z0-9_-]+\.md)(?:#[^)]*)?(?:\)?,? "([^"]+)")?')

problems = []
headings_cache = {}


def headings(path):
    if path not in headings_cache:
        with open(path, encoding="utf-8") as f:
            headings_cache[path] = [normal(line.lstrip("#")) for line in f if line.startswith("#")]
    return headings_cache[path]


def normal(text):
    return " ".join(text.replace("`", "").lower().split())


def check(where, doc, section, path):
    if not os.path.isfile(path):
        problems.append(f"{where}: names {doc}, which does not exist")
    elif section and not any(normal(section) in h for h in headings(path)):
        problems.append(f"{where}: names the section \"{section}\" of {doc}, which has no such heading")


def scan_text(where, text, in_docs):
    for number, line in enumerate(text.split("\n"), 1):
        at = f"{where}:{number}"
        for m in DOC_REF.finditer(line):
            check(at, m.group(1), m.group(2), os.path.join(SOURCE, m.group(1)))
        if in_docs:
            for m in LOCAL_REF.finditer(line):
                check(at, m.group(1), m.group(2), os.path.join(SOURCE, "docs", m.group(1)))


def files():
    for name in TOP_FILES:
        yield os.path.join(SOURCE, name)
    for d in DIRS + ["docs"]:
        for root, _, names in os.walk(os.path.join(SOURCE, d)):
            for n in names:
                if os.path.splitext(n)[1] in TEXT_SUFFIXES:
                    yield os.path.join(root, n)


count = 0
for path in files():
    if not os.path.isfile(path):
        continue
    rel = os.path.relpath(path, SOURCE)
    with open(path, encoding="utf-8", errors="replace") as f:
        scan_text(rel, f.read(), rel.startswith("docs" + os.sep))
    count += 1

commands = 0
if ROLLKIN:
    # Every command and subcommand from the --help listings, breadth first.
    todo = [[]]
    while todo:
        path = todo.pop(0)
        out = subprocess.run([ROLLKIN, *path, "--help"], capture_output=True, text=True)
        if out.returncode != 0:
            problems.append(f"rollkin {' '.join(path)} --help: exit {out.returncode}")
            continue
        commands += 1
        scan_text(f"rollkin {' '.join(path)} --help".replace("  ", " "), out.stdout, False)
        if path and "docs/cli.md, \"rollkin " + " ".join(path) + "\"" not in out.stdout:
            problems.append(f"rollkin {' '.join(path)} --help: does not name its section of docs/cli.md")
        listing = out.stdout.split("\nSubcommands:\n", 1)  # CLI11's group of subcommands, one "  name  text" each
        if len(listing) == 2:
            for line in listing[1].split("\n"):
                m = re.match(r"  ([a-z][a-z-]*)\s", line)
                if not m:
                    break
                todo.append(path + [m.group(1)])

for p in problems:
    print(p)
print(f"{count} files and {commands} --help texts checked, {len(problems)} reference(s) that do not resolve")
sys.exit(1 if problems else 0)
