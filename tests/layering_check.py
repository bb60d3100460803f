#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Checks disktune's layering against docs/ARCHITECTURE.md (standard library only).

    layering_check.py ROOT [--arrows]

ROOT is a source tree (the repository, or a fabricated one for the self-check). From
ROOT/docs/ARCHITECTURE.md it reads
  - the "Layers and files" table: the layers, and each public header's layer (the
    backquoted names in the "public header" column, relative to include/disktune/);
  - the "Allowed includes" section: one line `layer: other layers it may include` per
    layer, in a fenced block (a layer may always include itself).
Every C++ file under ROOT/src, ROOT/include and ROOT/plugins gets a layer: src/<layer>/...
from its folder, include/disktune/... from the table, plugins/<layer>/... from its
folder. A file that cannot be mapped is a failure. Then it fails on
  - an #include "..." (or <disktune/...>) whose arrow is not allowed, naming file:line and
    the arrow; an include of plugins/ from src/ or include/; an include it cannot find;
  - a string literal in src/ or include/ that names a command-line flag (`--` then a
    letter) or a command of the CLI ("disktune sample"): the library says what is wrong
    in its own terms, the CLI adds its flags.
With --arrows it also prints every arrow in use with a count and an example.
Exit status 0 when all holds, 1 otherwise.
"""

import os
import re
import sys

DOC = os.path.join("docs", "ARCHITECTURE.md")
SOURCE_EXTENSIONS = (".h", ".hh", ".hpp", ".hxx", ".c", ".cc", ".cpp", ".cxx", ".inl", ".ipp", ".tpp")
ROOTS = ("src", "include", "plugins")
FLAG = re.compile(r"--[A-Za-z][\w-]*")
INCLUDE = re.compile(r'^\s*#\s*include\s*(?:"([^"]+)"|<(disktune/[^>]+)>)')


class Failures:
    def __init__(self):
        self.lines = []

    def add(self, text):
        self.lines.append(text)


def section(lines, title):
    """The lines of the '## title' section (without its heading), or None."""
    for i, line in enumerate(lines):
        if line.strip() == "## " + title:
            end = i + 1
            while end < len(lines) and not lines[end].startswith("## "):
                end += 1
            return lines[i + 1:end], i + 2  # the section's first line number
    return None, 0


def read_doc(root, failures):
    """(layers in table order, {public header: layer}, {layer: allowed set})."""
    path = os.path.join(root, DOC)
    try:
        with open(path, encoding="utf-8") as f:
            lines = f.read().splitlines()
    except OSError as e:
        failures.add("%s: cannot read it (%s)" % (DOC, e.strerror))
        return [], {}, {}

    table, first = section(lines, "Layers and files")
    layers, headers = [], {}
    if table is None:
        failures.add('%s: no "## Layers and files" section: the layers and their public headers '
                     "come from its table" % DOC)
    else:
        rows = [(first + k, l) for k, l in enumerate(table) if l.lstrip().startswith("|")]
        for number, row in rows[2:]:  # after the heading row and the --- row
            cells = [c.strip() for c in row.strip().strip("|").split("|")]
            if len(cells) < 2 or not re.fullmatch(r"[a-z][a-z0-9_]*", cells[0]):
                failures.add("%s:%d: a table row whose first cell is not a layer name: %s" % (DOC, number, row))
                continue
            layer = cells[0]
            if layer in layers:
                failures.add("%s:%d: layer %s has two rows" % (DOC, number, layer))
            layers.append(layer)
            for header in re.findall(r"`([^`]+)`", cells[1]):
                if header in headers and headers[header] != layer:
                    failures.add("%s:%d: public header %s is listed for %s and for %s: give it one layer"
                                 % (DOC, number, header, headers[header], layer))
                headers[header] = layer
        if not layers:
            failures.add('%s: the "Layers and files" table has no rows' % DOC)

    block, first = section(lines, "Allowed includes")
    allowed = {}
    if block is None:
        failures.add('%s: no "## Allowed includes" section: it lists, one line per layer, '
                     "`layer: layers it may include`, in a fenced block" % DOC)
        return layers, headers, allowed
    fence = [k for k, l in enumerate(block) if l.strip().startswith("```")]
    if len(fence) < 2:
        failures.add('%s:%d: the "Allowed includes" section has no fenced block (```) holding '
                     "the `layer: allowed layers` lines" % (DOC, first))
        return layers, headers, allowed
    for k in range(fence[0] + 1, fence[1]):
        line, number = block[k].strip(), first + k
        if not line:
            continue
        m = re.fullmatch(r"([a-z][a-z0-9_]*)\s*:\s*([a-z0-9_,\s]*)", line)
        if not m:
            failures.add("%s:%d: not a `layer: allowed layers` line: %s" % (DOC, number, line))
            continue
        layer, targets = m.group(1), [t for t in re.split(r"[,\s]+", m.group(2)) if t]
        for name in [layer] + targets:
            if layers and name not in layers:
                failures.add('%s:%d: "%s" is not a layer of the "Layers and files" table' % (DOC, number, name))
        if layer in allowed:
            failures.add("%s:%d: layer %s has two lines" % (DOC, number, layer))
        allowed[layer] = set(targets)
    for layer in layers:
        if layer not in allowed:
            failures.add('%s: layer %s has no line in "Allowed includes" (write `%s:` if it '
                         "includes no other layer)" % (DOC, layer, layer))
    return layers, headers, allowed


def layer_of(rel, layers, headers):
    """(layer, None) or (None, why it has none) for a path relative to the root."""
    parts = rel.split("/")
    if parts[0] in ("src", "plugins"):
        if len(parts) < 3:
            return None, "a file directly in %s/: put it in a layer's folder" % parts[0]
        if parts[1] not in layers:
            return None, ('its folder %s/%s/ is not a layer of the "Layers and files" table in %s'
                          % (parts[0], parts[1], DOC))
        return parts[1], None
    if parts[0] == "include":
        name = "/".join(parts[2:])
        if len(parts) < 3 or parts[1] != "disktune":
            return None, "public headers live in include/disktune/"
        if name not in headers:
            return None, ('a public header the "Layers and files" table of %s does not list: add `%s` '
                          "to its layer's row" % (DOC, name))
        return headers[name], None
    return None, "outside src/, include/ and plugins/"


def source_files(root):
    for top in ROOTS:
        for folder, dirs, files in os.walk(os.path.join(root, top)):
            dirs.sort()
            for name in sorted(files):
                if name.endswith(SOURCE_EXTENSIONS):
                    yield os.path.relpath(os.path.join(folder, name), root).replace(os.sep, "/")


def resolve(root, rel, target, quoted):
    """The included file relative to the root, as the compiler would find it: next to the
    including file (quoted includes), then under include/. None if neither exists."""
    bases = [os.path.dirname(rel)] if quoted else []
    for base in bases + ["include"]:
        candidate = os.path.normpath(os.path.join(root, base, target))
        if os.path.isfile(candidate):
            return os.path.relpath(candidate, root).replace(os.sep, "/")
    return None


def string_literals(text):
    """(line, text) of each string literal outside comments; adjacent literals are joined,
    as the compiler joins them."""
    out, i, n, line = [], 0, len(text), 1
    last_end = None  # index just past the previous literal, while only blanks follow it
    while i < n:
        c = text[i]
        if c == "\n":
            line += 1
            i += 1
        elif text.startswith("//", i):
            end = text.find("\n", i)
            i = n if end < 0 else end
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            line += text.count("\n", i, end)
            i = end
        elif c == "'" and not (i > 0 and (text[i - 1].isalnum() or text[i - 1] == "_")):
            j = i + 1  # a character literal (a digit separator follows an alnum)
            while j < n and text[j] != "'" and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            i = j + 1 if j < n and text[j] == "'" else j
            last_end = None
        elif c == '"':
            start_line, raw = line, re.search(r'(?:u8|[uUL])?R$', text[max(0, i - 3):i])
            if raw and not (i - len(raw.group(0)) > 0 and (text[i - len(raw.group(0)) - 1].isalnum())):
                m = re.match(r'"([^()\\\s]{0,16})\(', text[i:])
                close = ")" + (m.group(1) if m else "") + '"'
                end = text.find(close, i)
                end = n if end < 0 else end
                body, i = text[i + 1 + (len(m.group(0)) - 1 if m else 0):end], end + len(close)
            else:
                j = i + 1
                while j < n and text[j] != '"' and text[j] != "\n":
                    j += 2 if text[j] == "\\" else 1
                body, i = text[i + 1:j], (j + 1 if j < n and text[j] == '"' else j)
            line += body.count("\n")
            if last_end is not None and out:
                out[-1] = (out[-1][0], out[-1][1] + body)
            else:
                out.append((start_line, body))
            last_end = i
            continue
        elif c.isspace():
            i += 1
            continue
        else:
            i += 1
            last_end = None
            continue
        # newlines and comments between two literals keep them adjacent
    return out


def main(argv):
    show_arrows = argv[2:] == ["--arrows"]
    if len(argv) not in (2, 3) or (len(argv) == 3 and not show_arrows):
        sys.stderr.write("usage: layering_check.py ROOT [--arrows]\n")
        return 2
    root = argv[1]
    failures = Failures()
    layers, headers, allowed = read_doc(root, failures)
    if not layers:
        print("\n".join(failures.lines))
        return 1

    commands = set()
    files = list(source_files(root))
    for rel in files:
        if rel.startswith("plugins/"):
            with open(os.path.join(root, rel), encoding="utf-8", errors="replace") as f:
                commands.update(re.findall(r'add_subcommand\(\s*"([A-Za-z][\w-]*)"', f.read()))
    command_name = re.compile(r"\bdisktune\s+(%s)\b" % "|".join(sorted(commands))) if commands else None

    arrows, includes = {}, 0
    for rel in files:
        here, why = layer_of(rel, layers, headers)
        if here is None:
            failures.add("%s: cannot tell its layer: %s" % (rel, why))
        library = not rel.startswith("plugins/")
        with open(os.path.join(root, rel), encoding="utf-8", errors="replace") as f:
            text = f.read()
        for number, line in enumerate(text.splitlines(), 1):
            m = INCLUDE.match(line)
            if not m:
                continue
            includes += 1
            target = m.group(1) or m.group(2)
            written = '#include "%s"' % target if m.group(1) else "#include <%s>" % target
            found = resolve(root, rel, target, m.group(1) is not None)
            if library and (found or target).split("/").count("plugins"):
                failures.add("%s:%d: %s reaches into plugins/: the library (src/, include/) never "
                             "includes front-end code" % (rel, number, written))
                continue
            if found is None:
                failures.add("%s:%d: %s: no such file next to %s or under include/ (quoted includes are "
                             "disktune's own files)" % (rel, number, written, rel))
                continue
            there, why = layer_of(found, layers, headers)
            if there is None:
                failures.add("%s:%d: %s: cannot tell the layer of %s: %s" % (rel, number, written, found, why))
                continue
            if here is None or here == there:
                continue
            arrows.setdefault((here, there), []).append("%s:%d" % (rel, number))
            if there not in allowed.get(here, set()):
                failures.add("%s:%d: %s is a wrong-way include: %s -> %s is not allowed (%s, "
                             '"Allowed includes": %s: %s)'
                             % (rel, number, written, here, there, DOC, here,
                                ", ".join(sorted(allowed.get(here, set()), key=layers.index)) or "nothing"))
        if library:
            for number, literal in string_literals(text):
                flag = FLAG.search(literal)
                command = command_name.search(literal) if command_name else None
                if flag or command:
                    what = ("a command-line flag (%s)" % flag.group(0)
                            if flag else "a command of the CLI ('%s')" % command.group(0))
                    failures.add('%s:%d: a string literal names %s: "%s"; say it in the library\'s '
                                 "terms, the CLI (plugins/) adds its flags" % (rel, number, what, literal))

    if show_arrows:
        print("arrows in use (including layer -> included layer: count, first place):")
        for (a, b), places in sorted(arrows.items(), key=lambda kv: (layers.index(kv[0][0]), layers.index(kv[0][1]))):
            mark = "" if b in allowed.get(a, set()) else "   <- NOT ALLOWED"
            print("  %-8s -> %-8s %3d  %s%s" % (a, b, len(places), places[0], mark))
    if failures.lines:
        print("\n".join(failures.lines))
        print("layering: %d failure(s) in %d files, %d includes" % (len(failures.lines), len(files), includes))
        return 1
    print("layering: %d files, %d includes, %d arrows between layers, all allowed; no flags in library "
          "strings" % (len(files), includes, len(arrows)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
