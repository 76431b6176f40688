"""Lists the C++ functions in src/ and app/ whose bodies are longer than a limit.

A function body is counted from the line after its opening brace to the line before its
closing brace; lambdas and local classes count towards the function that holds them, and a
lambda assigned at namespace scope counts as a function of the variable's name. Prints one
line a function, longest first: file, function, lines. Exit status 1 if any function is
longer than --max (default 100), 0 otherwise. The parsing is lexical (comments, strings and
preprocessor lines stripped, braces matched), enough for this code's style, not a compiler.

    /usr/bin/python3 tests/tools/function_lengths.py [--max 100] [--ignore src/io/settings.cpp]
                                                [--all] [ROOT ...]
"""
import argparse
import re
import sys
from pathlib import Path

SUFFIXES = {".cpp", ".hpp", ".h", ".cc", ".cxx", ".hxx"}
IDENT = re.compile(r"[A-Za-z_~][A-Za-z_0-9]*(?:\s*::\s*~?[A-Za-z_][A-Za-z_0-9]*)*\s*$")
OPERATOR = re.compile(r"((?:[A-Za-z_][A-Za-z_0-9]*\s*::\s*)*operator\s*(?:\(\)|[^\s(]+))\s*$")


def strip_code(text):
    """The text with comments, string and character literals and preprocessor lines blanked
    (newlines kept, so that positions keep their line numbers)."""
    out = []
    i, n = 0, len(text)
    line_start = True
    while i < n:
        c = text[i]
        if line_start and c == "#":
            # a preprocessor line, with its backslash continuations
            while i < n and text[i] != "\n":
                if text[i] == "\\" and i + 1 < n and text[i + 1] == "\n":
                    out.append(" \n")
                    i += 2
                    continue
                out.append(" ")
                i += 1
            continue
        if c == "\n":
            line_start = True
            out.append(c)
            i += 1
            continue
        if not c.isspace():
            line_start = False
        if text.startswith("//", i):
            while i < n and text[i] != "\n":
                out.append(" ")
                i += 1
            continue
        if text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            out.append("".join(ch if ch == "\n" else " " for ch in text[i:end]))
            i = end
            continue
        raw = re.match(r'(?:u8|u|U|L)?R"([^(\s]*)\(', text[i:i + 24])
        if raw and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            end = text.find(")" + raw.group(1) + '"', i)
            end = n if end < 0 else end + len(raw.group(1)) + 2
            out.append('""' + "".join(ch if ch == "\n" else " " for ch in text[i + 2:end]))
            i = end
            continue
        prev = text[i - 1] if i > 0 else " "
        if c == '"' or (c == "'" and not (prev.isalnum() or prev == "_")):
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(c + " " * (j - i - 1) + c)
            i = j + 1
            continue
        out.append(c)
        i += 1
    return "".join(out)


def depth0_positions(header, char):
    """Positions of char in header outside () and [] (<> is not tracked: templates rarely hide it)."""
    depth = 0
    found = []
    for pos, c in enumerate(header):
        if c in "([":
            depth += 1
        elif c in ")]":
            depth -= 1
        elif c == char and depth == 0:
            found.append(pos)
    return found


def classify(header):
    """What a brace at namespace or class scope opens, from the text before it: ('function',
    name), ('scope', None) for namespaces, classes and linkage blocks, or ('data', None)."""
    h = " ".join(header.split())
    if re.search(r"\bnamespace\b", h) or re.fullmatch(r"extern\s*\"\"", h):
        return "scope", None
    if "(" not in h:
        return ("scope", None) if re.search(r"\b(class|struct|union|enum)\b", h) else ("data", None)
    equals = [p for p in depth0_positions(h, "=")
              if h[p - 1:p] not in "=!<>+-*/%&|^" and h[p + 1:p + 2] != "="]
    if equals and "(" not in h[:equals[0]]:
        # an initializer: a function only if it is a lambda (the variable's name is the name)
        rest = h[equals[0] + 1:].lstrip()
        if not rest.startswith("["):
            return "data", None
        name = IDENT.search(h[:equals[0]].rstrip())
        return "function", name.group(0).replace(" ", "") if name else "<lambda>"
    if re.match(r"\s*(class|struct|union|enum)\b", re.sub(r"^template\s*<.*?>\s*", "", h)):
        return "scope", None
    before = h[:h.index("(")].rstrip()
    match = OPERATOR.search(before) or IDENT.search(before)
    return "function", match.group(1 if match.re is OPERATOR else 0).replace(" ", "") if match else "?"


def functions(path):
    """(name, first body line, body lines) of each function defined in the file."""
    code = strip_code(path.read_text(errors="replace"))
    found = []
    stack = []  # one entry per open brace: 'scope', 'data', 'block' or ('function', name, line)
    header_start = 0
    init_list = False  # inside a constructor's member initializer list
    init_depth = 0
    line = 1
    for pos, c in enumerate(code):
        if c == "\n":
            line += 1
            continue
        if c not in "{};:":
            continue
        if any(entry != "scope" for entry in stack):
            # inside a function body or an initializer: braces only nest
            if c == "{":
                stack.append("block")
            elif c == "}":
                top = stack.pop()
                if isinstance(top, tuple):
                    found.append((top[1], top[2], max(0, line - top[2] - 1)))
                header_start = pos + 1
            continue
        header = code[header_start:pos]
        if c == ":":
            # access labels reset the header; a ':' after a parameter list starts an init list
            if code[pos + 1:pos + 2] == ":" or code[pos - 1:pos] == ":":
                continue
            if re.fullmatch(r"\s*(public|private|protected)\s*", header):
                header_start = pos + 1
            elif ")" in header and "?" not in header:
                init_list = True
            continue
        if c == ";":
            if not init_depth:
                header_start = pos + 1
                init_list = False
            continue
        if c == "}":
            if init_depth:
                init_depth -= 1
                continue
            if stack:
                stack.pop()
            header_start = pos + 1
            init_list = False
            continue
        # c == "{"
        if init_list:
            before = code[header_start:pos].rstrip()
            if (before and (before[-1].isalnum() or before[-1] in "_>")) \
                    or before.count("(") > before.count(")"):
                init_depth += 1  # a member's brace initializer, or a lambda in its parentheses
                continue
            if init_depth:
                init_depth += 1
                continue
        kind, name = classify(header)
        init_list = False
        if kind == "function":
            stack.append(("function", name, line))
        else:
            stack.append(kind)
        header_start = pos + 1
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("roots", nargs="*", default=["src", "app"],
                        help="folders or files to scan (default: src app)")
    parser.add_argument("--max", type=int, default=100,
                        help="longest body allowed, in lines (default 100)")
    parser.add_argument("--ignore", action="append", default=[],
                        help="a path (or folder) to leave out; may be repeated")
    parser.add_argument("--all", action="store_true",
                        help="list every function over the limit, ignored paths included "
                             "(they still do not change the exit status)")
    args = parser.parse_args()

    ignored = [Path(p).resolve() for p in args.ignore]
    rows = []
    for root in args.roots:
        root_path = Path(root)
        files = [root_path] if root_path.is_file() else sorted(
            p for p in root_path.rglob("*") if p.suffix in SUFFIXES)
        for path in files:
            resolved = path.resolve()
            skip = any(resolved == p or p in resolved.parents for p in ignored)
            for name, first, length in functions(path):
                if length > args.max and (args.all or not skip):
                    rows.append((length, str(path), name, skip))
    rows.sort(key=lambda row: (-row[0], row[1], row[2]))
    for length, path, name, skip in rows:
        print(f"{path}\t{name}\t{length}" + ("\t(ignored)" if skip else ""))
    return 1 if any(not skip for _, _, _, skip in rows) else 0


if __name__ == "__main__":
    sys.exit(main())
