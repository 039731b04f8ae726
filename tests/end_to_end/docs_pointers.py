#!/usr/bin/env python3
"""Every pointer into the docs resolves (docs/code.md: Checks of this page and of the docs):
  - `docs/NAME.md: Heading` in code, scripts and docs (also `NAME.md: Heading`
    inside docs/), where the text after the colon, up to the end of its line
    or one of `,;)]`, starts with a heading of that file or the bold label
    that opens one of its paragraphs or list items (`- **Memory**`), or the
    heading starts with it (a pointer wrapped onto the next line);
  - Markdown links `[text](NAME.md#anchor)` and `(#anchor)`, where the anchor
    is the GitHub slug of a heading of the file.
Prints every pointer that does not resolve and exits 1 if there is one.
Usage: docs_pointers.py SOURCE_DIR"""
import os
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1])
docs = root / "docs"


def headings(path, labels=False):
    """A file's headings; with labels, also the bold labels that open its paragraphs and list items."""
    if not path.exists():
        return None
    found, fenced = [], False
    for line in path.read_text(encoding="utf-8").splitlines():
        if line.startswith("```"):
            fenced = not fenced
        elif not fenced and re.match(r"#{1,6} ", line):
            found.append(line.lstrip("#").strip())
        elif not fenced and labels and (m := re.match(r"(?:- )?\*\*([^*]+?)\.?\*\*", line)):
            found.append(m.group(1))
    return found


def slug(heading):
    """GitHub's anchor for a heading: lower case, punctuation dropped, spaces as hyphens."""
    text = re.sub(r"[`*_]", "", heading).lower()
    return re.sub(r"[^\w\- ]", "", text).replace(" ", "-")


def skipped(name):  # build folders (tests write in them while this runs), git's, the workflow's outputs
    return name in (".git", "out") or name.startswith("build")


sources = []
for folder, folders, files in os.walk(root):
    folders[:] = sorted(f for f in folders if not skipped(f))
    sources += [pathlib.Path(folder, name) for name in files
                if os.path.splitext(name)[1] in (".cpp", ".h", ".py", ".sh", ".md", ".txt", ".cmake", ".html", ".yaml")
                or name in ("Snakefile", "Makefile")]
pointer = re.compile(r"(docs/)?([a-z_]+)\.md: ([A-Z][^,;)\]\n]*)")
link = re.compile(r"\]\(([a-z_./]*\.md)?#([a-z0-9\-_]+)\)")
bad, checked = [], 0
for path in sorted(sources):
    text = path.read_text(encoding="utf-8", errors="replace")
    in_docs = path.parent == docs
    for number, line in enumerate(text.splitlines(), 1):
        for m in pointer.finditer(line):
            if not m.group(1) and not in_docs:
                continue  # "NAME.md: ..." outside docs/ is not a pointer into them
            target = docs / (m.group(2) + ".md")
            names = headings(target, labels=True)
            # Strip comment leaders and trailing punctuation a wrapped line keeps.
            wanted = re.sub(r"\s*(\*/|\.|:|`)*\s*$", "", m.group(3)).strip()
            checked += 1
            if names is None:
                bad.append(f"{path.relative_to(root)}:{number}: {target.name} does not exist")
            elif not any(wanted.startswith(h) or (h.startswith(wanted) and len(wanted) >= 4) for h in names):
                bad.append(f"{path.relative_to(root)}:{number}: no heading of {target.name} starts '{wanted}'")
        if path.suffix != ".md":
            continue
        for m in link.finditer(line):
            target = (path.parent / m.group(1)) if m.group(1) else path
            names = headings(target.resolve())
            checked += 1
            if names is None:
                bad.append(f"{path.relative_to(root)}:{number}: {m.group(1)} does not exist")
            elif m.group(2) not in {slug(h) for h in names}:
                bad.append(f"{path.relative_to(root)}:{number}: no heading of {target.name} has the anchor #{m.group(2)}")
for line in bad:
    print(line)
print(f"docs_pointers: {checked} pointers, {len(bad)} that do not resolve")
sys.exit(1 if bad else 0)
