"""The workflow's measured results as one Markdown document (OUT/results.md).

Per notebook: its title, its tables and figures under the paper's captions,
and the numbers the paper quotes, all read from the files the notebooks wrote
for the paper, so no result is copied by hand (docs/workflow.md: Results).
A LaTeX command this file does not know is an error, not a silent gap.
The workflow's rule `results` calls write().
"""
import json
import os
import re

# Commands whose argument is kept, as Markdown wraps it (\mode is the paper's).
WRAPPERS = {"mode": "`", "texttt": "`", "textsf": "", "emph": "*", "textbf": "**"}
# Commands dropped with their argument, and symbols (in and out of maths).
DROPPED = {"cite", "label"}
SYMBOLS = {"le": "≤", "leq": "≤", "ge": "≥", "geq": "≥", "times": "×", "propto": "∝", "infty": "∞",
           "in": "∈", "phi": "φ", "lceil": "⌈", "rceil": "⌉", "min": "min", "max": "max",
           "dots": "…", "ldots": "…", "FLIP": "FLIP", "centering": ""}
ESCAPED = {"%": "%", "_": "_", "&": "&", "#": "#", "$": "$", "{": "{", "}": "}", " ": " ", "\n": " "}


def braced(text, start):
    """The text inside the braces opening at text[start], and the index after them."""
    if start >= len(text) or text[start] != "{":
        raise ValueError(f"expected '{{' in {text[max(0, start - 30):start + 30]!r}")
    depth, i = 0, start
    while i < len(text):
        if text[i] == "\\":  # an escaped character or a command: no brace of the group
            i += 2
            continue
        depth += {"{": 1, "}": -1}.get(text[i], 0)
        if depth == 0:
            return text[start + 1:i], i + 1
        i += 1
    raise ValueError(f"unbalanced braces in {text[start:start + 60]!r}")


def without_comments(tex):
    """The text without % comments (an escaped \\% and the pair \\\\ stay)."""
    return re.sub(r"(\\.)|%.*", lambda m: m.group(1) or "", tex)


def plain(tex, macros, references):
    """A LaTeX fragment (a caption, a cell, a number) as Markdown text."""
    tex = without_comments(tex)
    out, i = [], 0
    while i < len(tex):
        c = tex[i]
        if c == "\\":
            name = re.match(r"[A-Za-z]+|.", tex[i + 1:], re.S)
            if not name:
                raise ValueError(f"a lone backslash at the end of {tex.strip()[-80:]!r}")
            name = name.group(0)
            i += 1 + len(name)
            if name == ",":
                out.append("," if out and out[-1][-1:].isdigit() and tex[i:i + 1].isdigit() else " ")
            elif name in ESCAPED:
                out.append(ESCAPED[name])
            elif name == "\\":
                out.append(" ")
            elif name == "textbackslash":  # as notebooks/boxlod_results.py escapes a backslash
                out.append("\\")
                if tex[i:i + 2] == "{}":
                    i += 2
            elif name in WRAPPERS or name in DROPPED or name in ("ref", "reflectbox"):
                argument, i = braced(tex, i)
                if name in WRAPPERS:
                    mark = WRAPPERS[name]
                    out.append(mark + plain(argument, macros, references) + mark)
                elif name == "ref":
                    if argument not in references:
                        raise ValueError(f"\\ref to {argument!r}, a label of no table or figure")
                    out.append(references[argument])
                elif name == "reflectbox":
                    out.append(plain(argument, macros, references))
            elif name in SYMBOLS or name in macros:
                out.append(SYMBOLS[name] if name in SYMBOLS else plain(macros[name], macros, references))
                if tex[i:i + 2] == "{}":
                    i += 2
            else:
                raise ValueError(f"unknown LaTeX command \\{name} in {tex.strip()[:80]!r}")
        elif c == "~":
            out.append(" ")
            i += 1
        elif c in "${}":
            i += 1
        else:
            out.append(c)
            i += 1
    return re.sub(r"\s+", " ", "".join(out)).strip()


def macro_values(paths):
    """name -> value of every \\newcommand in the files (the notebooks' numbers)."""
    values = {}
    for path in paths:
        text = without_comments(open(path, encoding="utf-8").read())
        for match in re.finditer(r"\\newcommand\{\\([A-Za-z]+)\}", text):
            values[match.group(1)], _ = braced(text, match.end())
    return values


def floats(paper_tex):
    """stem -> (caption, label) of each table and figure of the paper, by the
    generated file it inputs or includes."""
    text = without_comments(paper_tex)
    found = {}
    for match in re.finditer(r"\\begin\{((?:table|figure)\*?)\}(.*?)\\end\{\1\}", text, re.S):
        body = match.group(2)
        stems = re.findall(r"\\(?:input|includegraphics(?:\[[^]]*\])?)\{([^}]+)\}", body)
        caption_at = body.find("\\caption")
        if not stems or caption_at < 0:
            continue
        after = re.match(r"\\caption(\[[^]]*\])?", body[caption_at:]).end()
        caption, _ = braced(body, caption_at + after)
        label = re.search(r"\\label\{([^}]+)\}", body)
        for stem in stems:
            found[os.path.basename(stem)] = (caption, label.group(1) if label else None)
    return found


def references_of(captions):
    """label -> how a \\ref to it reads: the stem of what its float shows."""
    return {label: f"*{stem}*" for stem, (_, label) in captions.items() if label}


def table_rows(tex):
    """The header, the body rows and the note after the tabular (as
    write_table in notebooks/boxlod_results.py writes them) of a booktabs table."""
    text = without_comments(tex)
    try:
        head, rest = text.split("\\toprule", 1)[1].split("\\midrule", 1)
        body, tail = rest.split("\\bottomrule", 1)
        note = tail.split("\\end{tabular}", 1)[1].strip()
    except (IndexError, ValueError):
        raise ValueError("a table without \\toprule, \\midrule, \\bottomrule and \\end{tabular}")
    def rows(part):
        return [[cell.strip() for cell in re.split(r"(?<!\\)&", line)]
                for line in (l.strip() for l in re.split(r"\\\\", part)) if line]
    header, body_rows = rows(head), rows(body)
    if len(header) != 1 or any(len(row) != len(header[0]) for row in body_rows):
        raise ValueError(f"a table whose header is not one row or whose rows differ in length: {header}")
    return header[0], body_rows, note


def markdown_table(header, rows):
    def line(cells):
        return "| " + " | ".join(cell.replace("|", "\\|") for cell in cells) + " |"
    return "\n".join([line(header), line(["---"] * len(header))] + [line(r) for r in rows])


def notebook_title(path):
    cells = json.load(open(path, encoding="utf-8"))["cells"]
    first = next(c for c in cells if c["cell_type"] == "markdown")
    return "".join(first["source"]).splitlines()[0].lstrip("# ").strip()


def stem_of(path):
    return os.path.splitext(os.path.basename(path))[0]


def document(notebooks, generated, notebook_dir, paper_tex, figure_folder):
    """The Markdown text: `notebooks` maps a notebook's name to its generated
    files; figures are linked inside `figure_folder` (relative to the document)."""
    numbers = {stem_of(p): macro_values([os.path.join(generated, stem_of(p) + ".tex")])
               for outputs in notebooks.values() for p in outputs if stem_of(p).startswith("numbers_")}
    macros = {name: value for values in numbers.values() for name, value in values.items()}
    captions = floats(paper_tex)
    references = references_of(captions)
    lines = ["# Results", "",
             "Generated by the workflow (experiments/Snakefile, rule `results`) from the files the "
             "notebooks wrote for the paper; do not edit. Each section is one notebook; its tables "
             "and figures carry the paper's captions.", ""]
    for name, outputs in notebooks.items():
        lines += [f"## {notebook_title(os.path.join(notebook_dir, name + '.ipynb'))}", "",
                  f"From `notebooks/{name}.ipynb`.", ""]
        seen = set()
        for path in outputs:
            stem = stem_of(path)
            if stem in seen:
                continue
            seen.add(stem)
            if stem.startswith("numbers_"):
                rows = [[f"`{key}`", plain(value, macros, references)] for key, value in numbers[stem].items()]
                lines += ["Numbers the paper quotes:", "", markdown_table(["name", "value"], rows), ""]
                continue
            if stem not in captions:
                raise ValueError(f"{stem}: no table or figure of the paper shows it, so it has no caption")
            caption = plain(captions[stem][0], macros, references)
            if stem.startswith("table_"):
                header, rows, note = table_rows(open(os.path.join(generated, stem + ".tex"), encoding="utf-8").read())
                convert = lambda cells: [plain(cell, macros, references) for cell in cells]
                lines += [f"*{stem}*: {caption}", "", markdown_table(convert(header), [convert(r) for r in rows]), ""]
                if note:
                    lines += [plain(note, macros, references), ""]
            else:
                lines += [f"![{stem}]({figure_folder}/{stem}.png)", "", f"*{stem}*: {caption}", ""]
    return "\n".join(lines)


def write(path, notebooks, generated, notebook_dir, paper_path):
    text = document(notebooks, generated, notebook_dir, open(paper_path, encoding="utf-8").read(),
                    os.path.relpath(generated, os.path.dirname(os.path.abspath(path))))
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)
