#!/usr/bin/env python3
"""Checks that the C++ sources of the stack stay readable: no file longer
than --max-file lines and no function body longer than --max-function lines.

usage: check_sizes.py [--max-file N] [--max-function N] [--exceptions FILE] DIR...

The limits are a signal to look at, not a reason to split one class over two
files: a file may pass its limit when scripts/size_exceptions.txt lists it
("path lines reason"), with the reason written down.

Functions are found by brace matching on the source with comments, strings
and character literals blanked out: a brace that opens a body whose header
(the text since the previous ';', '{' or '}') has a parameter list and is not
a control statement, a namespace, a class or an initializer. Nested lambdas
and local classes count towards the function that holds them. Prints one
line per violation (path:line: what) and exits 1 if there is any.
"""
import argparse
import os
import re
import sys

SOURCE_EXT = (".cpp", ".cc", ".h", ".hpp")
SKIP_DIRS = {"build", "devel", "install", ".git", "node_modules"}
SCOPE_RE = re.compile(r"^\s*(template\s*<.*>\s*)?(namespace|class|struct|union|enum|extern\s+\"C\")\b", re.S)
CONTROL_RE = re.compile(r"(^|[^\w])(if|for|while|switch|catch|do|else|try)\s*(\(|$)")


def blank_literals(text):
    """Replaces comments and string/char literals by spaces, keeping newlines."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == 'R' and text.startswith('R"', i):
            m = re.match(r'R"([^(]*)\(', text[i:])
            if m:
                end = text.find(")" + m.group(1) + '"', i)
                end = n if end < 0 else end + len(m.group(1)) + 2
                out.append(re.sub(r"[^\n]", " ", text[i:end]))
                i = end
            else:
                out.append(c)
                i += 1
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(c + " " * (j - i - 2) + (c if j - i >= 2 else ""))
            i = j
        else:
            out.append(c)
            i += 1
    return "".join(out)


def functions(text):
    """Yields (first_line, last_line, header) of every outermost function body."""
    code = re.sub(r"(?m)^[ \t]*#.*?(?<!\\)$", lambda m: " " * len(m.group(0)), blank_literals(text))
    stack = []  # entries: "scope", "func", "other"
    header_start = 0
    func_start = None
    for i, c in enumerate(code):
        if c == "{":
            header = code[header_start:i]
            in_func = "func" in stack
            kind = "other"
            if not in_func:
                h = header.strip()
                if SCOPE_RE.match(h) or h.endswith("=") or not h:
                    kind = "scope" if SCOPE_RE.match(h) else "other"
                elif ")" in h and not CONTROL_RE.search(h.split("(")[0] + "("):
                    kind = "func"
                    func_start = code.count("\n", 0, header_start + len(header) - len(header.lstrip())) + 1
                    func_header = " ".join(h.split())[:100]
            stack.append(kind)
            header_start = i + 1
        elif c == "}":
            kind = stack.pop() if stack else "other"
            if kind == "func" and "func" not in stack:
                yield func_start, code.count("\n", 0, i) + 1, func_header
            header_start = i + 1
        elif c == ";":
            header_start = i + 1
        elif c == ":" and code[i - 1:i + 1] != "::" and code[i:i + 2] != "::":
            # "public:" / "case X:" end a header; a constructor's initializer
            # list ("Foo() : a_(1) {") keeps its ')' before the ':'.
            if ")" not in code[header_start:i]:
                header_start = i + 1


def source_files(dirs):
    for d in dirs:
        for root, subdirs, files in os.walk(d, followlinks=False):
            subdirs[:] = sorted(s for s in subdirs if s not in SKIP_DIRS)
            for f in sorted(files):
                if f.endswith(SOURCE_EXT):
                    yield os.path.join(root, f)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("dirs", nargs="+")
    ap.add_argument("--max-file", type=int, default=500)
    ap.add_argument("--max-function", type=int, default=80)
    ap.add_argument("--exceptions", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "size_exceptions.txt"))
    a = ap.parse_args()
    allowed = {}
    if os.path.exists(a.exceptions):
        with open(a.exceptions, encoding="utf-8") as f:
            for line in f:
                parts = line.split(None, 2)
                if parts and not parts[0].startswith("#"):
                    if len(parts) < 3:
                        print(f"{a.exceptions}: expected 'path lines reason', got: {line.strip()}")
                        return 1
                    allowed[os.path.normpath(parts[0])] = int(parts[1])
    problems = []
    for path in source_files(a.dirs):
        with open(path, encoding="utf-8", errors="replace") as f:
            text = f.read()
        n = text.count("\n")
        if n > allowed.get(os.path.normpath(path), a.max_file):
            problems.append(f"{path}:1: file has {n} lines (at most {a.max_file})")
        for first, last, header in functions(text):
            if last - first + 1 > a.max_function:
                problems.append(f"{path}:{first}: function has {last - first + 1} lines "
                                f"(at most {a.max_function}): {header}")
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
