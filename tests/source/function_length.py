#!/usr/bin/env python3
"""Fails when a C or C++ function in the given folders is longer than a limit.

A function's length is counted as a reader sees it: from the first line of its signature to the
line of its closing brace, both included. The parser is small on purpose but honest about C++:
comments, string literals (raw ones included), character literals and preprocessor lines are
blanked before braces are matched, so a brace in any of them counts for nothing; namespaces,
classes, structs and unions are entered (their inline member functions are counted), enums and
initialisers are skipped whole, and a brace-initialised member in a constructor's initialiser list
does not end the signature. A lambda is part of the function that holds it.

usage: function_length.py [--max N] [--list] ROOT FOLDER...
  --max N   the longest a function may be, in lines (default 90)
  --list    print every function's length, longest first, and never fail on length
"""

import argparse
import os
import re
import sys

SOURCE_SUFFIXES = (".c", ".cc", ".cpp", ".cxx", ".h", ".hh", ".hpp", ".hxx", ".inl")
SCOPE_KEYWORDS = re.compile(r"\b(namespace|class|struct|union)\b")
# A function-like macro's call in capitals, such as G_DEFINE_TYPE(Name, name, PARENT).
MACRO_CALL = re.compile(r"^\s*[A-Z][A-Z0-9_]*\s*\([^()]*\)\s*")
ENUM_KEYWORD = re.compile(r"\benum\b")
EXTERN_C = re.compile(r'\bextern\s*"[^"]*"\s*$')
# A raw string literal: its prefix before the quote, and its delimiter and '(' after it.
RAW_PREFIX = re.compile(r"(?:^|[^\w])(?:u8|u|U|L)?R$")
RAW_OPEN = re.compile(r'([^ ()\\\t\n]{0,16})\(')
# What a brace follows when it opens a value rather than a body: `x = {`, `f({`, `{{`, `[{`,
# `a, {`, `return {`.
INITIALISER_BEFORE = re.compile(r"(=|\(|\[|\{|,|\breturn)\s*$")


def blank(text):
    """The text with comments, literals and preprocessor lines replaced by spaces (newlines kept),
    so that lines still count and no brace inside them is seen."""
    out = []
    i, n = 0, len(text)
    at_line_start = True
    while i < n:
        c = text[i]
        if at_line_start and c in " \t":
            out.append(c)
            i += 1
            continue
        if at_line_start and c == "#":
            # A preprocessor line, with its backslash continuations.
            j = i
            while j < n:
                if text[j] == "\n" and text[j - 1] != "\\":
                    break
                j += 1
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
            continue
        at_line_start = c == "\n"
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
        elif c == "'" and re.search(r"\b\d[\w']*$", text[max(0, i - 40):i]) and text[i + 1:i + 2].isalnum():
            # A digit separator (1'000'000), not a character literal.
            out.append(c)
            i += 1
        elif c == '"' and RAW_PREFIX.search(text[max(0, i - 4):i]) and RAW_OPEN.match(text, i + 1):
            # A raw string: it ends at )delimiter" whatever it holds, newlines and quotes included.
            closing = ")" + RAW_OPEN.match(text, i + 1).group(1) + '"'
            end = text.find(closing, i + 1)
            j = n if end < 0 else end + len(closing)
            out.append(c + re.sub(r"[^\n]", " ", text[i + 1:j - 1]) + c)
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            closed = j < n and text[j] == c
            out.append(c + re.sub(r"[^\n]", " ", text[i + 1:j]) + (c if closed else ""))
            i = j + 1 if closed else j
        else:
            out.append(c)
            i += 1
    return "".join(out)


def matching_brace(code, open_at):
    depth = 0
    for j in range(open_at, len(code)):
        if code[j] == "{":
            depth += 1
        elif code[j] == "}":
            depth -= 1
            if depth == 0:
                return j
    raise ValueError("unbalanced braces")


def function_name(header):
    """The qualified name before the parameter list: the identifier (or operator) that precedes
    the first '(' at the outer level of the signature."""
    flat = " ".join(header.split())
    match = re.search(r"((?:[\w~]+::)*(?:operator\s*[^\s(]+|~?[\w]+))\s*\(", flat)
    return match.group(1) if match else flat[:60]


def opens_scope(header):
    """Whether the brace after this header opens a namespace, class, struct or union. A macro
    call in capitals before it that takes no ';' (GLib's G_DEFINE_TYPE(...)) is passed over, so
    the namespace after it is not taken for a function's body."""
    while True:
        macro = MACRO_CALL.match(header)
        if not macro:
            break
        header = header[macro.end():]
    return bool(SCOPE_KEYWORDS.search(header)) and "(" not in header


def functions(code, start=0, end=None):
    """Yields (name, first index, closing brace index) of every function body between start and
    end, a namespace- or class-level scope of the blanked code."""
    end = len(code) if end is None else end
    header_start = start
    i = start
    while i < end:
        c = code[i]
        if c in ";}":
            header_start = i + 1
        elif c == "{":
            header = code[header_start:i]
            close = matching_brace(code, i)
            if INITIALISER_BEFORE.search(header) or "(" not in header and not SCOPE_KEYWORDS.search(header) \
                    and not EXTERN_C.search(header.strip()):
                # A value: skip it whole; the statement goes on to its ';'.
                i = close + 1
                continue
            if ENUM_KEYWORD.search(header) and "(" not in header:
                i = close + 1
                continue
            if EXTERN_C.search(header.strip()) or opens_scope(header):
                yield from functions(code, i + 1, close)
                header_start = close + 1
                i = close + 1
                continue
            # A body, unless this brace initialises a member in a constructor's initialiser list:
            # then a ',' or the body's own '{' follows it, and the signature goes on.
            after = code[close + 1:close + 200].lstrip()
            if after[:1] in (",", "{") and re.search(r"\)\s*:", header):
                i = close + 1
                continue
            first = header_start + (len(header) - len(header.lstrip()))
            yield function_name(header), first, close
            header_start = close + 1
            i = close + 1
            continue
        i += 1


def line_of(code, index):
    return code.count("\n", 0, index) + 1


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--max", type=int, default=90)
    parser.add_argument("--list", action="store_true")
    parser.add_argument("root")
    parser.add_argument("folders", nargs="+")
    args = parser.parse_args()

    found = []
    for folder in args.folders:
        base = os.path.join(args.root, folder)
        if not os.path.isdir(base):
            print(f"{folder}: no such folder under {args.root}", file=sys.stderr)
            return 2
        for directory, _, names in sorted(os.walk(base)):
            for name in sorted(names):
                if not name.endswith(SOURCE_SUFFIXES):
                    continue
                path = os.path.join(directory, name)
                with open(path, encoding="utf-8") as f:
                    code = blank(f.read())
                relative = os.path.relpath(path, args.root)
                try:
                    for function, first, close in functions(code):
                        first_line, last_line = line_of(code, first), line_of(code, close)
                        found.append((last_line - first_line + 1, relative, first_line, function))
                except ValueError as problem:
                    print(f"{relative}: cannot be parsed: {problem}", file=sys.stderr)
                    return 2

    if not found:
        print("no function found: is the root right?", file=sys.stderr)
        return 2
    found.sort(key=lambda item: (-item[0], item[1], item[2]))
    if args.list:
        for length, path, line, function in found:
            print(f"{length:5d}  {path}:{line}  {function}")
        return 0
    too_long = [item for item in found if item[0] > args.max]
    for length, path, line, function in too_long:
        print(f"{path}:{line}: {function} is {length} lines, more than {args.max}")
    print(f"{len(found)} functions in {', '.join(args.folders)}; the longest is {found[0][0]} lines "
          f"({found[0][3]}, {found[0][1]}:{found[0][2]}); {len(too_long)} over {args.max}")
    return 1 if too_long else 0


if __name__ == "__main__":
    sys.exit(main())
