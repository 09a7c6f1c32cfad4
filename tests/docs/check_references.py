#!/usr/bin/env python3
"""The repository's documents refer only to themselves (docs/design.md, "Documentation").

Checks, over the source tree given as the first argument (default: this file's repository):
  1. every citation `maths.md ID` (ID such as LP-1, G-4, CO-2, TB-3, JE-1) names a section
     heading of docs/maths.md, `maths.md, "Title"` names one of its headings, and "ID test N" /
     "ID tests N-M" name checks that section lists;
  2. no file cites a document outside the repository: no DESIGN.md, NOTES.md or papers/, and
     ../shared only as ../shared/data (the optional real scans, which tests skip when absent);
  3. every relative link [text](target#anchor) of the Markdown files resolves to a file of the
     repository and, with an anchor, to a heading of that file (GitHub's anchor rules).
Exit 0 when all hold, 1 with one line per problem otherwise.
"""
import os
import re
import sys

ROOT = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else
                       os.path.join(os.path.dirname(__file__), "..", ".."))
TEXT = (".h", ".cc", ".py", ".pyi", ".md", ".txt", ".cmake", ".in", ".sh", ".toml", ".cfg", ".json")
SKIP_DIRS = {".git", "data"}          # datasets/data: bundled clouds and their licences
ID = r"(?:LP|CO|JE|TB|G)-\d+"
THIS = os.path.relpath(os.path.abspath(__file__), ROOT)


def files():
    for top, dirs, names in os.walk(ROOT):
        dirs[:] = [d for d in dirs if d not in SKIP_DIRS and not d.startswith("build")]
        for name in names:
            if name.endswith(TEXT) or name in ("CMakeLists.txt", "LICENSE", "run"):
                path = os.path.join(top, name)
                yield os.path.relpath(path, ROOT), path


def slug(heading):
    s = heading.strip().lower()
    s = re.sub(r"[^\w\- ]", "", s)   # GitHub: drop punctuation, keep letters, digits, - and _
    return s.replace(" ", "-")


def headings(path):
    out, fence = [], False
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("```"):
                fence = not fence
            elif not fence and re.match(r"#{1,6} ", line):
                out.append(line.lstrip("#").strip())
    return out


def main():
    problems = []
    maths = os.path.join(ROOT, "docs", "maths.md")
    text = open(maths, encoding="utf-8").read()
    sections = {}  # ID -> text of its section
    for m in re.finditer(r"^## (" + ID + r")\b.*?(?=^## |\Z)", text, re.M | re.S):
        sections[m.group(1)] = m.group(0)
    titles = set(headings(maths))
    for rel, path in files():
        if rel == THIS:
            continue
        try:
            lines = open(path, encoding="utf-8").read().splitlines()
        except UnicodeDecodeError:
            continue
        for n, line in enumerate(lines, 1):
            where = "%s:%d" % (rel, n)
            for bad in ("DESIGN.md", "NOTES.md", "papers/"):
                if bad in line:
                    problems.append("%s: cites %s, which is not in the repository" % (where, bad))
            for m in re.finditer(r"\.\./shared(/\w+)?", line):
                if m.group(1) != "/data":
                    problems.append("%s: cites %s outside the repository" % (where, m.group(0)))
            if "maths.md" in line and rel != "docs/maths.md":
                tail = line[line.index("maths.md"):]
                if tail.rstrip().endswith(",") and n < len(lines):  # cited title on the next line
                    tail = tail.rstrip() + " " + re.sub(r"^\s*(//|#)?\s*", "", lines[n])
                for cid in re.findall(ID, tail):
                    if cid not in sections:
                        problems.append("%s: docs/maths.md has no section %s" % (where, cid))
                for name in re.findall(r'^maths\.md,\s*\\?"([^"\\]+)', tail):
                    if name not in titles:
                        problems.append('%s: docs/maths.md has no section "%s"' % (where, name))
                for m in re.finditer(r"(" + ID + r")(?:'s)? tests? (\d+)(?:\s*[-–]\s*(\d+))?", tail):
                    cid, first, last = m.group(1), int(m.group(2)), int(m.group(3) or m.group(2))
                    for k in range(first, last + 1):
                        if cid in sections and not re.search(r"(^|\s)%d\. " % k, sections[cid]):
                            problems.append("%s: %s has no check %d" % (where, cid, k))
        if rel.endswith(".md"):
            body = "\n".join(lines)
            body = re.sub(r"```.*?```", "", body, flags=re.S)
            for m in re.finditer(r"\]\(([^)\s]+)\)", body):
                target = m.group(1)
                if re.match(r"[a-z]+:", target):
                    continue  # http:, https:, mailto:
                file_part, _, anchor = target.partition("#")
                dest = os.path.normpath(os.path.join(os.path.dirname(path), file_part)) \
                    if file_part else path
                if not os.path.exists(dest):
                    problems.append("%s: link to missing %s" % (rel, target))
                elif anchor and dest.endswith(".md"):
                    if anchor not in {slug(h) for h in headings(dest)}:
                        problems.append("%s: link %s: no such heading" % (rel, target))
    for p in problems:
        print(p)
    print("%d problem(s)" % len(problems), file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
