"""experiments/results_document.py on a hand-made notebook output, and on every
caption of the real paper (each must convert: an unknown LaTeX command fails).
Usage: results_document.py REPO"""
import glob
import json
import os
import re
import sys
import tempfile

repo = sys.argv[1]
sys.path.insert(0, os.path.join(repo, "experiments"))
import results_document as rd

failures = 0


def check(condition, message):
    global failures
    print(("ok   " if condition else "FAIL ") + message)
    failures += not condition


with tempfile.TemporaryDirectory() as work:
    generated = os.path.join(work, "paper", "generated")
    notebooks = os.path.join(work, "notebooks")
    os.makedirs(generated)
    os.makedirs(notebooks)
    with open(os.path.join(generated, "numbers_demo.tex"), "w") as f:
        f.write("% generated\n\\newcommand{\\DemoModel}{manual}\n\\newcommand{\\DemoBytes}{2\\,750}\n"
                "\\newcommand{\\DemoShare}{25\\,\\%}\n")
    with open(os.path.join(generated, "table_demo.tex"), "w") as f:
        f.write("% generated\n\\begin{tabular}{lrr}\n\\toprule\nmode & \\FLIP{} & bytes \\\\\n\\midrule\n"
                "top\\_down & 0.013 & 12\\,345 \\\\\nhybrid & -- & $\\infty$ \\\\\n"
                "x\\textbackslash{}2\\&c&  & 5\\% % a comment after an escaped per cent\n\\\\\n"
                "\\bottomrule\n\\end{tabular}\nA note \\emph{after} it.\n")
    paper = ("\\begin{table}[t]\n\\caption{Best \\FLIP{} of \\mode{\\DemoModel} within \\DemoShare{} "
             "($\\le$ \\DemoBytes{} bytes); see Figure~\\ref{fig:demo}.} % a comment\n"
             "\\label{tab:demo}\n\\input{table_demo}\n\\end{table}\n"
             "\\begin{figure}[t]\n\\includegraphics[width=\\linewidth]{plot_demo}\n"
             "\\caption{The \\emph{demo} plot.}\n\\label{fig:demo}\n\\end{figure}\n")
    with open(os.path.join(notebooks, "00_demo.ipynb"), "w") as f:
        json.dump({"cells": [{"cell_type": "code", "source": ["x = 1"]},
                             {"cell_type": "markdown", "source": ["# A demo notebook\n", "\n", "text"]}]}, f)
    outputs = [os.path.join(generated, n) for n in ("plot_demo.pdf", "plot_demo.png", "table_demo.tex", "numbers_demo.tex")]
    text = rd.document({"00_demo": outputs}, generated, notebooks, paper, "paper/generated")
    print(text)
    check("## A demo notebook" in text, "a section titled by the notebook's first heading")
    check("| mode | FLIP | bytes |" in text, "the table's header, commands converted")
    check("| top_down | 0.013 | 12,345 |" in text and "| hybrid | -- | ∞ |" in text, "each body row, escapes and maths converted")
    check("| x\\2&c |  | 5% |" in text, "escaped characters, an empty cell, a comment after an escaped per cent")
    check(len(re.findall(r"^\| (top_down|hybrid|x\\2&c) ", text, re.M)) == 3, "one Markdown row per table row")
    check("A note *after* it." in text, "the note after the tabular kept")
    check("Best FLIP of `manual` within 25 % (≤ 2,750 bytes); see Figure *plot_demo*." in text,
          "the caption with the numbers' macros expanded and the reference named")
    check("![plot_demo](paper/generated/plot_demo.png)" in text and text.count("plot_demo.png") == 1,
          "the figure linked once (its PDF twin not repeated)")
    check("| `DemoBytes` | 2,750 |" in text, "the notebook's numbers listed with their values")
    check("a comment" not in text, "LaTeX comments dropped")
    check(not re.search(r"\\[A-Za-z]", text), "no LaTeX command left")
    check(rd.braced("{a \\\\} b}", 0) == ("a \\\\", 6), "a line break before a closing brace closes the group")
    def refused(what, call, needle):
        try:
            call()
            check(False, f"{what} is an error")
        except ValueError as e:
            check(needle in str(e), f"{what} is an error naming it: {e}")
    refused("an unknown command", lambda: rd.plain("\\unknowncommand{x}", {}, {}), "unknowncommand")
    refused("a reference to no float", lambda: rd.plain("see \\ref{fig:none}", {}, {}), "fig:none")
    refused("a row of another length", lambda: rd.table_rows("\\toprule a & b \\\\ \\midrule 1 \\\\ \\bottomrule \\end{tabular}"),
            "differ in length")
    refused("a generated table the paper shows nowhere",
            lambda: rd.document({"00_demo": [os.path.join(generated, "table_other.tex")]}, generated, notebooks, paper, "x"),
            "table_other")

# Every caption of the real paper converts, each number macro standing for a
# value: the macros the captions use are names the notebooks write.
paper = open(os.path.join(repo, "paper", "paper.tex"), encoding="utf-8").read()
captions = rd.floats(paper)
shown = {os.path.basename(stem) for stem in re.findall(r"\\(?:input|includegraphics(?:\[[^]]*\])?)\{((?:[^}]*/)?(?:table_|)[^}]+)\}", paper)
         if not os.path.basename(stem).startswith("numbers_")}
check(set(captions) == shown, f"every table and figure of the paper found with its caption ({len(captions)} of {len(shown)})")
written = set()
for path in glob.glob(os.path.join(repo, "notebooks", "*.ipynb")):
    cells = json.load(open(path, encoding="utf-8"))["cells"]
    written |= set(re.findall(r"[\"']([A-Z][A-Za-z]+)[\"']", "".join("".join(c["source"]) for c in cells if c["cell_type"] == "code")))
macros = {name: "1" for name in written}
unconverted = []
for stem, (caption, _) in sorted(captions.items()):
    try:
        rd.plain(caption, macros, rd.references_of(captions))
    except ValueError as e:
        unconverted.append(f"{stem}: {e}")
check(not unconverted, "every caption of the paper converts " + "; ".join(unconverted))
sys.exit(1 if failures else 0)
