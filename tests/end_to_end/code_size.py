#!/usr/bin/env python3
"""Code a newcomer reads in one sitting (issue 48; docs/code.md): no source
file outside tests/ over 600 lines, no function over 60 lines but the
declarative tables named below. Functions are found by brace matching on
lines with strings and comments removed, namespaces not counted.
Usage: code_size.py SOURCE_DIR"""
import re
import subprocess
import sys

MAX_FILE_LINES, MAX_FUNCTION_LINES = 600, 60
TABLES = {"viewer_keys", "sweep_keys", "make_declarations"}  # one row per key: a table, not steps
SOURCES = (".cpp", ".h", ".py")


def code_of(line):
    return re.sub(r'"(\\.|[^"\\])*"|\'(\\.|[^\'\\])\'|//.*', "", line)


def long_functions(lines):
    """(first line, length, name) of every C++ function body longer than the limit: a
    brace opened where every enclosing brace is a namespace, class or struct."""
    found, stack, start, name, recent = [], [], None, "", ""
    for number, line in enumerate(lines, 1):
        code = code_of(line)
        recent = re.split(r"[;{}]", recent)[-1] + " " + code  # the statement so far: a signature may span lines
        container = re.match(r"\s*((namespace|struct|class|union)\b[^;(]*|extern \"C\"\s*)\{", code)
        for _ in range(code.count("{")):
            in_container = all(kind == "container" for kind in stack)
            if container:
                stack.append("container")
                container = None
            elif in_container and start is None and re.search(r"=\s*$", recent.rsplit("{", 1)[0]):
                stack.append("block")  # a table's initializer (`... = {`), not a function body
            elif in_container and start is None:
                head = re.search(r"(~?\w+)\s*\(", recent)
                start, name = number, head.group(1) if head else "?"
                stack.append("function")
            else:
                stack.append("block")
        for _ in range(code.count("}")):
            kind = stack.pop() if stack else "container"
            if kind == "function":
                if number - start + 1 > MAX_FUNCTION_LINES and name not in TABLES:
                    found.append((start, number - start + 1, name))
                start = None
    return found


def main(root):
    files = subprocess.check_output(["git", "-C", root, "ls-files"], text=True).split()
    problems = 0
    for path in files:
        if path.startswith("tests/") or not path.endswith(SOURCES):
            continue
        lines = open(f"{root}/{path}", errors="replace").read().split("\n")
        if len(lines) - 1 > MAX_FILE_LINES:
            print(f"{path}: {len(lines) - 1} lines, more than {MAX_FILE_LINES}")
            problems += 1
        if path.endswith((".cpp", ".h")):
            for start, length, name in long_functions(lines):
                print(f"{path}:{start}: {name} is {length} lines, more than {MAX_FUNCTION_LINES}")
                problems += 1
    print(f"code_size: {len(files)} files looked at, {problems} over the limits")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
