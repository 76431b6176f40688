#!/usr/bin/python3
"""Mutation fuzzing of feticon's four input kinds (issue 21, item 7): problem files (YAML) of
`feticon run`, Gmsh MSH meshes a custom problem file names, the Matrix Market files of
`feticon qp`, and CalculiX / Abaqus input decks of `feticon run model.inp`; and (kind export)
decks and problem files through `feticon export --format calculix`, whose deck must not hold a
non-finite number. Each mutant is a
seed of tests/data/fuzz/ (decks: tests/data/calculix/) with one to three mutations, run in a
fresh folder under a time limit. A mutant fails when feticon dies of a signal, hangs (timeout),
exits with another status than 0 or 1 (or 3, "not converged", for `feticon qp`), writes a
non-finite number (summary.json, the CSV files, the qp JSON report, x.mtx, the data rows of
a deck run's .dat and .frd), ends an exit 1
with more or less than one line on stderr, or reports success without its report.

Usage: fuzz_inputs.py FETICON SOURCE_DIR [--mutants N | --minutes M] [--seed S]
                      [--kinds problem,gmsh,mm,deck,export] [--timeout SECONDS] [--keep DIR]
The mutants are a function of the seed: mutant i of seed S is the same in every run, so
--minutes M runs a prefix of the same sequence. Failing mutants are saved in --keep DIR
(default: a new temporary folder) with their inputs, diff.txt against the seed, the output
and command.sh to reproduce them. Prints a table of outcomes per kind; exit status 1 when a
mutant failed.
"""
import argparse
import difflib
import json
import math
import os
import random
import re
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile
import time

# Seeds, each run well under 2 s unmutated. A problem or gmsh case lists its files: the
# problem file first (the one `feticon run` gets), then the mesh it names.
PROBLEM_SEEDS = [["two_boxes.yaml"], ["pretension_bar.yaml"], ["hertz_small.yaml"], ["gmsh41.yaml", "punch41.msh"],
                 ["gmsh22.yaml", "punch22.msh"], ["gmsh_tet10.yaml", "punch_tet10.msh"],
                 ["gmsh_2d.yaml", "blocks_2d.msh"], ["sections.yaml", "sections_bar.msh"]]
MM_FILES = ["A.mtx", "b.mtx", "l.mtx"]

# Work bound: the machine running the fuzzer is shared, so a mutant whose model legitimately
# needs gigabytes is refused by feticon's memory guard (an exit 1) instead of taking them.
RUN_OPTIONS = ["--set", "output.plots=false", "--set", "output.vtu=false",
               "--set", "memory_limit=2e9"]
QP_COMMAND = ["qp", "--A", "A.mtx", "--b", "b.mtx", "--lower", "l.mtx", "--out", "x.mtx"]

OUTCOMES = ["exit 0", "exit 1", "exit 3", "other exit", "signal", "timeout", "non-finite",
            "multi-line error", "bad output"]
FAILURES = {"other exit", "signal", "timeout", "non-finite", "multi-line error", "bad output"}

EXTREMES = ["0", "-1", "1e308", "-1e308", "nan", "inf", "-inf", "2147483648", "999999999999",
            "1e-320", "heavy"]
YAML_EXTREMES = EXTREMES + [".nan", ".inf", "-.inf", "0x7fffffff", "1_000"]
NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


# ---- generic mutators: text is bytes decoded as latin-1, so every byte survives ------------

def flip_bits(text, rng):
    if not text:
        return None
    chars = list(text)
    places = []
    for _ in range(rng.randint(1, 4)):
        i = rng.randrange(len(chars))
        bit = rng.randrange(8)
        chars[i] = chr(ord(chars[i]) ^ (1 << bit))
        places.append(f"{i}:{bit}")
    return "".join(chars), "bit flips (offset:bit) " + " ".join(places)


def delete_line(text, rng):
    lines = text.splitlines(keepends=True)
    if not lines:
        return None
    i = rng.randrange(len(lines))
    return "".join(lines[:i] + lines[i + 1:]), f"line {i + 1} deleted"


def duplicate_line(text, rng):
    lines = text.splitlines(keepends=True)
    if not lines:
        return None
    i = rng.randrange(len(lines))
    copy = lines[i] if lines[i].endswith("\n") else lines[i] + "\n"
    return "".join(lines[:i] + [copy] + lines[i:]), f"line {i + 1} duplicated"


def swap_lines(text, rng):
    lines = text.splitlines(keepends=True)
    if len(lines) < 2:
        return None
    i, j = sorted(rng.sample(range(len(lines)), 2))
    lines = [line if line.endswith("\n") else line + "\n" for line in lines]
    lines[i], lines[j] = lines[j], lines[i]
    return "".join(lines), f"lines {i + 1} and {j + 1} swapped"


def truncate(text, rng):
    if not text:
        return None
    i = rng.randrange(len(text))
    return text[:i], f"truncated to {i} bytes"


def insert_junk(text, rng):
    junk = rng.choice(["\0", "\xff", "\r", "\t", "\x1b", "\xef\xbb\xbf", "\n\n", " "])
    i = rng.randrange(len(text) + 1)
    return text[:i] + junk + text[i:], f"{junk!r} inserted at offset {i}"


def number_replacer(values):
    def replace_number(text, rng):
        matches = list(NUMBER.finditer(text))
        if not matches:
            return None
        m = rng.choice(matches)
        value = rng.choice(values)
        line = text.count("\n", 0, m.start()) + 1
        return (text[:m.start()] + value + text[m.end():],
                f"number {m.group()} on line {line} replaced by {value}")
    return replace_number


GENERIC = [flip_bits, delete_line, duplicate_line, swap_lines, truncate, insert_junk]


# ---- YAML structures ------------------------------------------------------------------------

def nested(rng):
    depth = rng.choice([8, 100, 1000, 10000, 100000])
    if rng.random() < 0.5:
        return "[" * depth + "1" + "]" * depth, f"lists nested {depth} deep"
    return "{a: " * depth + "1" + "}" * depth, f"maps nested {depth} deep"


def alias_bomb(rng):
    # Each level holds ten aliases of the one below: 10^levels scalars once expanded.
    levels = rng.randint(3, 8)
    parts = ["&l0 [" + ", ".join(["1"] * 10) + "]"]
    parts += [f"&l{k} [" + ", ".join([f"*l{k - 1}"] * 10) + "]" for k in range(1, levels)]
    return "[" + ", ".join(parts) + "]", f"alias bomb of 10^{levels} scalars"


STRUCTURES = ["[1, 2]", "[]", "{}", "{a: 1, b: [2, 3]}", "~", "null", '""', "[[1], {x: 2}]",
              "!!binary AAAA", "!custom 1", "*undefined", "&r [*r]", "? [1]\n", "{? a}",
              "[a, {b: c}, [d, [e]]]", '"\\x00"', "'''", "|\n  text", "- 1"]


def structure(rng):
    roll = rng.random()
    if roll < 0.2:
        return nested(rng)
    if roll < 0.3:
        return alias_bomb(rng)
    value = rng.choice(STRUCTURES)
    return value, f"{value!r}"


YAML_VALUE = re.compile(r"(?<=: )[^,\]}\n#]+")
YAML_KEY = re.compile(r"([A-Za-z_][\w.]*): ")


def yaml_value(text, rng):
    matches = list(YAML_VALUE.finditer(text))
    if not matches:
        return None
    m = rng.choice(matches)
    value, what = structure(rng)
    return text[:m.start()] + value + text[m.end():], f"value {m.group()!r} replaced by {what}"


def yaml_insert(text, rng):
    """A new key line (an existing key: a duplicate or a misplaced one) with a structure."""
    lines = text.splitlines(keepends=True)
    i = rng.randrange(len(lines) + 1)
    keys = YAML_KEY.findall(text)
    key = rng.choice(keys) if keys and rng.random() < 0.7 else rng.choice(["zz", "qp", "0", "<<"])
    indent = ""
    if i < len(lines) and rng.random() < 0.5:
        indent = re.match(r"[ -]*", lines[i]).group().replace("-", " ")
    value, what = structure(rng)
    lines.insert(i, f"{indent}{key}: {value}\n")
    return "".join(lines), f"line {i + 1} inserted: {indent}{key}: {what}"


def yaml_duplicate_key(text, rng):
    """Repeats a key: value pair within its flow map or block."""
    pairs = list(re.finditer(r"([A-Za-z_]\w*): ([^,\]}\n#]+)", text))
    if not pairs:
        return None
    m = rng.choice(pairs)
    value = rng.choice([m.group(2), rng.choice(YAML_EXTREMES)])
    line_start = text.rfind("\n", 0, m.start()) + 1
    in_flow = "{" in text[line_start:m.start()]
    if in_flow:
        insert = f", {m.group(1)}: {value}"
        at = m.end()
    else:
        insert = f"\n{' ' * (m.start() - line_start)}{m.group(1)}: {value}"
        at = text.find("\n", m.end()) if "\n" in text[m.end():] else len(text)
    return text[:at] + insert + text[at:], f"key {m.group(1)} repeated with value {value}"


def yaml_alias(text, rng):
    matches = list(YAML_VALUE.finditer(text))
    if len(matches) < 2:
        return None
    a, b = rng.sample(matches, 2)
    # Replace from the back so that the first span's offsets stay valid.
    edits = sorted([(a, f"&x {a.group()}"), (b, "*x")], key=lambda e: e[0].start(), reverse=True)
    for m, new in edits:
        text = text[:m.start()] + new + text[m.end():]
    return text, f"anchor &x on {a.group()!r}, alias *x for {b.group()!r}"


def yaml_block_nesting(text, rng):
    depth = rng.choice([10, 100, 1000])
    lines = text.splitlines(keepends=True)
    i = rng.randrange(len(lines) + 1)
    block = "".join("  " * k + "a:\n" for k in range(depth)) + "  " * depth + "1\n"
    lines.insert(i, block)
    return "".join(lines), f"block maps nested {depth} deep inserted at line {i + 1}"


def yaml_document(text, rng):
    marker = rng.choice(["---\n", "...\n", "%YAML 1.2\n---\n", "%TAG ! tag:x,2000:\n---\n",
                         "--- !!map\n", "---\n---\n"])
    lines = text.splitlines(keepends=True)
    i = rng.randrange(len(lines) + 1)
    lines.insert(i, marker)
    return "".join(lines), f"{marker!r} inserted at line {i + 1}"


def yaml_magnitude(text, rng):
    """A number of a valid problem file (a modulus, a load, a size, a setting) times 10^k,
    k in -30..30: a valid model far from steel's, which must solve or end in one line."""
    numbers = [(v.start() + m.start(), v.start() + m.end(), float(m.group()))
               for v in YAML_VALUE.finditer(text) for m in NUMBER.finditer(v.group())
               if float(m.group()) != 0]
    if not numbers:
        return None
    start, end, value = rng.choice(numbers)
    exponent = rng.choice([-30, 30, rng.randint(-30, 30)])
    new = f"{value * 10.0 ** exponent:.9e}"
    line = text.count("\n", 0, start) + 1
    return text[:start] + new + text[end:], f"{text[start:end]} on line {line} times 1e{exponent}"


YAML_MUTATORS = [number_replacer(YAML_EXTREMES), yaml_value, yaml_insert, yaml_duplicate_key,
                 yaml_alias, yaml_block_nesting, yaml_document, yaml_magnitude, yaml_magnitude]


# ---- Gmsh MSH sections ------------------------------------------------------------------------

def section_line(text, name):
    """Offsets of the line after `$name` (its count line), or None."""
    m = re.search(rf"^\${name}[ \t\r]*\n([^\n]*)", text, re.M)
    return (m.start(1), m.end(1)) if m else None


def msh_count(text, rng):
    names = [n for n in ["Nodes", "Elements", "PhysicalNames", "Entities"]
             if section_line(text, n)]
    if not names:
        return None
    name = rng.choice(names)
    start, end = section_line(text, name)
    words = text[start:end].split()
    if not words:
        return None
    k = rng.randrange(len(words))
    old = int(words[k]) if re.fullmatch(r"-?\d+", words[k]) else 1
    words[k] = str(rng.choice([old + 1, old - 1, 0, -1, 2 * old, 2147483648, 999999999999,
                               -2147483649, "x", "1e308", "1.5"]))
    return text[:start] + " ".join(words) + text[end:], f"${name} count line -> {' '.join(words)}"


def msh_physical(text, rng):
    block = re.search(r"^\$PhysicalNames[ \t\r]*\n[^\n]*\n(.*?)^\$EndPhysicalNames", text,
                      re.M | re.S)
    if not block or not block.group(1).strip():
        return None
    lines = block.group(1).splitlines(keepends=True)
    i = rng.randrange(len(lines))
    parts = lines[i].rstrip("\n").split(" ", 2)
    if len(parts) < 3:
        return None
    dim, tag, name = parts
    change = rng.choice(["dim", "tag", "quote"])
    if change == "dim":
        dim = str(rng.choice([-1, 0, 1, 2, 3, 4, 7, 255, 2147483648, "x"]))
    elif change == "tag":
        tags = [line.split(" ", 2)[1] for line in lines if line.count(" ") >= 2]
        tag = str(rng.choice([0, -1, 2147483647, 2147483648, 999999999999, rng.choice(tags)]))
    else:
        name = rng.choice([name.lstrip('"'), name.rstrip('"'), name.strip('"'), '""',
                           name[:-1] + '"x"', '"' + "n" * 10000 + '"', '"a b"', '"\\"'])
    lines[i] = f"{dim} {tag} {name}\n"
    return (text[:block.start(1)] + "".join(lines) + text[block.end(1):],
            f"$PhysicalNames line {i + 1} -> {lines[i].strip()[:60]}")


def msh_format(text, rng):
    where = section_line(text, "MeshFormat")
    if not where:
        return None
    current = text[where[0]:where[1]]
    version = rng.choice([v for v in ["2.2 0 8", "4.1 0 8", "4 0 8", "4.0 0 8", "3.0 0 8",
                                      "1.0 0 8", "4.1 1 8", "4.1 0 4", "2.2 1 8", "4.1", "",
                                      "41 0 8", "nan 0 8", "-4.1 0 8", "2.2 0 8 extra"]
                          if v != current])
    return text[:where[0]] + version + text[where[1]:], f"$MeshFormat line -> {version!r}"


def msh_section(text, rng):
    sections = list(re.finditer(r"^\$(\w+)[ \t\r]*\n.*?^\$End\1[ \t\r]*\n?", text, re.M | re.S))
    if not sections:
        return None
    s = rng.choice(sections)
    name = s.group(1)
    change = rng.choice(["drop end", "drop", "duplicate", "rename", "move first"])
    body = s.group()
    if change == "drop end":
        body = re.sub(rf"^\$End{name}[ \t\r]*\n?", "", body, flags=re.M)
    elif change == "drop":
        body = ""
    elif change == "duplicate":
        body = body + body
    elif change == "rename":
        body = body.replace(f"${name}", f"${name}z", 1)
    else:
        return body + text[:s.start()] + text[s.end():], f"section ${name} moved first"
    return text[:s.start()] + body + text[s.end():], f"section ${name}: {change}"


MSH_MUTATORS = [number_replacer(EXTREMES), msh_count, msh_physical, msh_format, msh_section]


# ---- Matrix Market headers ---------------------------------------------------------------------

BANNER_WORDS = [["%%MatrixMarket", "%MatrixMarket", "%%matrixmarket", "MatrixMarket", "%%"],
                ["matrix", "vector", "Matrix", "tensor"],
                ["coordinate", "array", "COORDINATE", "dense"],
                ["real", "integer", "complex", "pattern", "double", "Real"],
                ["general", "symmetric", "skew-symmetric", "hermitian", "Symmetric", "upper"]]


def mm_header(text, rng):
    end = text.find("\n")
    words = text[:end if end >= 0 else len(text)].split()
    change = rng.choice(["word", "word", "word", "drop", "add", "remove banner"])
    if change == "remove banner":
        return text[end + 1:] if end >= 0 else "", "banner line removed"
    if change == "word" and words:
        k = rng.randrange(min(len(words), len(BANNER_WORDS)))
        words[k] = rng.choice(BANNER_WORDS[k])
    elif change == "drop" and words:
        del words[rng.randrange(len(words))]
    else:
        words.insert(rng.randrange(len(words) + 1), rng.choice(["real", "extra", "%"]))
    banner = " ".join(words)
    return banner + (text[end:] if end >= 0 else ""), f"banner -> {banner!r}"


def mm_size(text, rng):
    m = re.search(r"^(?!%)[^\n]*", text, re.M)
    if not m:
        return None
    words = m.group().split()
    change = rng.choice(["number", "number", "number", "drop", "add"])
    if change == "number" and words:
        k = rng.randrange(len(words))
        old = int(words[k]) if re.fullmatch(r"-?\d+", words[k]) else 1
        words[k] = str(rng.choice([old + 1, old - 1, 0, -1, 2147483648, 999999999999,
                                   "x", "1.5", "1e308", "nan"]))
    elif change == "drop" and words:
        del words[rng.randrange(len(words))]
    else:
        words.append(rng.choice(["1", "12", "0"]))
    line = " ".join(words)
    return text[:m.start()] + line + text[m.end():], f"size line -> {line!r}"


MM_MUTATORS = [number_replacer(EXTREMES), mm_header, mm_size]


# ---- CalculiX / Abaqus input decks -----------------------------------------------------------
# Mutations aimed at the deck reader (src/io/deck_*.cpp): its keyword and data lines, the
# numbers it parses, the references between nodes, elements, sets and surfaces, *INCLUDE, and
# the magnitudes a valid deck may carry (1e-30 to 1e30 moduli, loads and coordinates).

DECK_SEEDS = ["contact1.inp", "contactenergy.inp", "cubespring.inp", "contact1_friction.inp", "contactenergy_plastic.inp",
              "punch_tet10.inp",
              "punch_c3d20r.inp", "contactenergy_density.inp", "rings_cax4.inp", "tie_blocks.inp",
              "change_friction.inp", "rubber_block.inp", "changesurfbeh.inp", "assembly_two_blocks.inp",
              "pret2.inp", "plate.inp", "friction2.inp", "bolt.inp"]
# Seeds of our own (tests/data/fuzz/): a C3D10 deck, feticon's export of gmsh_tet10.yaml, and
# a C3D20 / C3D20R one (reduced integration per cell), the same punch meshed with hex20; two
# CAX4 rings shrink-fitted through a node-to-surface pair of element edges (issue 64). From
# tests/data/calculix/: tie_blocks.inp, two blocks glued by a *TIE (issue 63),
# change_friction.inp, a block pushed along a base over three steps, *CHANGE FRICTION in the last,
# rubber_block.inp, a Neo-Hooke block compressed 30 % through contact (issue 66), and CalculiX's
# changesurfbeh.inp, a tie turned into contact by *CHANGE SURFACE BEHAVIOR (issue 65), pret2.inp,
# two CAX8 cells cut by a *PRE-TENSION SECTION, and plate.inp, two CPS8R cells each with an
# hourglass mode (its kernel from the matrix) pressed together, friction2.inp, a pressed block
# dragged back and forth over four steps until every friction row slides, bolt.inp, a CPS8R bolt
# through two CAX8R plates (bodies of mixed 2D formulations) by node surfaces under an
# exponential law. From tests/data/abaqus/: assembly_two_blocks.inp, Abaqus/CAE's layout of parts and instances (issue 63).
FUZZ_FOLDER_DECKS = {"punch_tet10.inp", "punch_c3d20r.inp", "rings_cax4.inp"}
ABAQUS_FOLDER_DECKS = {"assembly_two_blocks.inp"}
# Seeds made from another by an edit: contact1 with Coulomb friction (*FRICTION after the
# pressure-overclosure law, as tests/cli/deck_friction.sh adds it to CalculiX's decks).
# contactenergy with a density, for the body loads among the keyword mutations (*DLOAD GRAV,
# CENTRIF). contactenergy (small displacements) with J2 plasticity (issue 66: a yield stress its
# load passes, hardening then perfect beyond the table's end).
DECK_DERIVED = {"contact1_friction.inp": ("contact1.inp", "*SURFACE BEHAVIOR", "*FRICTION\n0.3, 1e6\n"),
                "contactenergy_density.inp": ("contactenergy.inp", "*ELASTIC", "*DENSITY\n7850.\n"),
                "contactenergy_plastic.inp": ("contactenergy.inp", "*ELASTIC", "*PLASTIC\n20., 0.\n40., 0.1\n")}
DECK_EXTREMES = EXTREMES + ["1e400", "-1e400", "NaN", "-nan", "Infinity", "1.5D3", "1d999",
                            "9223372036854775807", "9223372036854775808",
                            "-9223372036854775809", "-0", "1e-30", "1e30", "-1e30"]
# Words where the reader wants a number (and numbers it must refuse as such).
DECK_WORDS = ["abc", "", "NALL", "S1", "P5", "1.5.2", "1e", "--1", "0x10", "1 2", "+", "-",
              ".", "e5", "1d", "'1'", '"1"', "1_000", "\xb9", "1e5x", "EALL", "SMAST"]
# Keyword lines (with data) a deck may wrongly hold; NAME is replaced by a random name.
DECK_KEYWORDS = [
    "*FOO", "*", "* ", "*,", "*, NSET=A", "*NODE", "*NODE,", "*NODE, NSET", "*NODE, SYSTEM=R",
    "*ELEMENT", "*ELEMENT, TYPE=C3D20", "*ELEMENT, TYPE=C3D8\n1,1,2,3,4,5,6,7",
    "*ELEMENT, TYPE=CPE4, ELSET=EALL\n998,1,2,3,4", "*ELEMENT, TYPE=CAX8R\n997,1,2,3,4,5,6,7,8",
    "*ELEMENT, TYPE=CPS3\n996,3,2,1", "*SOLID SECTION, ELSET=EALL, MATERIAL=EL\n-1.",
    "*SOLID SECTION, ELSET=HUB, MATERIAL=STEEL, OFFSET=0.5\n0.01",
    "*ELEMENT, TYPE=C3D8R, ELSET=EALL\n999,1,2,3,4,5,6,7,8", "*STEP", "*END STEP", "*STATIC",
    "*STATIC\n1e-300,1e300", "*STATIC\n0,0", "*STATIC\n0.1, 1., 0.2",
    "*STATIC, DIRECT\n1e-6, 1.", "*BOUNDARY, OP=NEW\n1,1,1,0.5", "*BOUNDARY, OP=NEW",
    "*CHANGE SURFACE BEHAVIOR, INTERACTION=SI1\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TIED",
    "*CHANGE SURFACE BEHAVIOR, INTERACTION=NONE", "*NSET, NSET=X, FREQUENCY=1\n1", "*FRICTION\n0.3", "*DENSITY\n7.8e-9", "*INCLUDE",
    "*INCLUDE, INPUT=", "*INCLUDE, INPUT=.", "*MATERIAL, NAME=", "*MATERIAL, NAME=EL",
    "*ELASTIC\n1,0.3", "*ELASTIC\n1e30,0.49999999", "*heading\ntitle", "*SURFACE, NAME=@",
    "*SURFACE, NAME=@, TYPE=NODE", "*SURFACE, NAME=SMAST\n1,S1",
    "*CONTACT PAIR, INTERACTION=SI1", "*CONTACT PAIR, INTERACTION=SI1, TYPE=SURFACE TO SURFACE\nSSLAV,SMAST",
    "*BOUNDARY\n1,1,3,1e30", "*BOUNDARY\nNALL,1,3", "*BOUNDARY\nNALL,ENCASTRE", "*CLOAD\n1,3,-1e30",
    "*DLOAD\nEALL,P1,1e30", "*DSLOAD\nSMAST,P,1", "*DLOAD\nEALL,GRAV,9.81,0,0,-1",
    "*DLOAD\nEALL,GRAV,1e30,1,0,0", "*DLOAD\nEALL,CENTRIF,1e4,0,0,0,0,0,1", "*DLOAD\nEALL,CENTRIF,1e4,0,0,0",
    "*DENSITY\n0", "*DENSITY\n-1", "*NSET, NSET=@, GENERATE\n1,1000000000",
    "*NSET, NSET=@, GENERATE\n1,9223372036854775807,9223372036854775807",
    "*ELSET, ELSET=@, GENERATE\n1,2,0", "*ELSET, ELSET=@\n@", "*NSET, NSET=NALL\nNALL",
    "*EQUATION\n2\n1,1,1.", "*EQUATION\n1000\n1,1,1.", "*EQUATION\n2\n1,1,0.,2,1,1.",
    "*SOLID SECTION, ELSET=EALL, MATERIAL=EL", "*SOLID SECTION, ELSET=@, MATERIAL=@",
    "*SURFACE INTERACTION, NAME=SI1", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD",
    "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TIED", "*TIE, NAME=T2\n@,@", "*TIE, NAME=T2, POSITION TOLERANCE=1e30\nSUPPER_BOTTOM,SLOWER_TOP",
    "*TIE, NAME=T2, ADJUST=NO, POSITION TOLERANCE=1e-30\nSLOWER_TOP,SUPPER_BOTTOM", "*TIE, NAME=T2, CYCLIC SYMMETRY\n@,@", "*TIE\n@,@",
    "*TIE, NAME=T2\nSSLAV,SMAST", "*CHANGE FRICTION, INTERACTION=SI1\n*FRICTION\n0.5", "*CHANGE FRICTION, INTERACTION=@",
    "*CHANGE FRICTION\n*FRICTION\n0.1", "*CHANGE FRICTION, INTERACTION=SI1\n*FRICTION\n1e300,1e300", "*TIE, NAME=T2, POSITION TOLERANCE=0.5\nSMAST,SSLAV", "*NODE PRINT, NSET=@", "*EL FILE\nS,E,XYZ",
    "*PLASTIC\n20,0\n10,0.001", "*PLASTIC\n20,0.01", "*PLASTIC\n20,0\n30,0", "*PLASTIC\n-1,0",
    "*PLASTIC, HARDENING=KINEMATIC\n20,0", "*PLASTIC\n20,0,20\n30,1,100", "*PLASTIC", "*PLASTIC\n1e30,0\n1e-30,1e30",
    "*HYPERELASTIC, NEO HOOKE\n1e6,1e-8", "*HYPERELASTIC, MOONEY-RIVLIN\n1e6,1e5,1e-9", "*HYPERELASTIC\n-1,0,1e-8",
    "*HYPERELASTIC, NEO HOOKE\n1e6,0", "*HYPERELASTIC, OGDEN, N=3\n1,2,3", "*HYPERELASTIC, NEO HOOKE\n1e300,1e-300",
    "*HYPERELASTIC, NEO HOOKE\n1e-300,1e300", "*HYPERELASTIC, POLYNOMIAL, N=1\n1e6,1e6,1e-9,20\n1e6,1e6,1e-9,100",
    "*AMPLITUDE, NAME=A\n0,0,1,1", "*CLOAD, AMPLITUDE=A\n1,1,1", "*AMPLITUDE, NAME=A\n1,0,0,1",
    "*AMPLITUDE, NAME=A\n0", "*AMPLITUDE, NAME=A, TIME=TOTAL TIME, SHIFTX=1e300\n0,0,1,1e300",
    "*AMPLITUDE, NAME=A, SHIFTY=-1\n0,0,1,1,1,-1e30", "*STEP, AMPLITUDE=STEP", "*STEP, AMPLITUDE=@",
    "*BOUNDARY, AMPLITUDE=A\nNALL,1,3,1e-3", "*DLOAD, AMPLITUDE=@\nEALL,P1,1", "*DSLOAD, AMPLITUDE=A\nSMAST,P,1", "*CLOAD, OP=NEW",
    "*BOUNDARY, OP=NEW", "*DLOAD, OP=XYZ",
    "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n1e7,3", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n-1",
    "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n1e300,1e300,1e300", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR",
    "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL\n1e-7,6.7", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL\n0,0",
    "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL\n1e-300,1e300", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TABULAR\n0,0\n1e6,1e-3",
    "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TABULAR\n1,1\n0,0", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TABULAR\n5,0",
    "*CHANGE SURFACE BEHAVIOR, INTERACTION=SI1\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n1e6",
    # Parts and assemblies (issue 63, item 7).
    "*PART, NAME=P", "*PART, NAME=BLOCK", "*END PART", "*ASSEMBLY", "*END ASSEMBLY", "*END INSTANCE",
    "*INSTANCE, NAME=I, PART=BLOCK", "*INSTANCE, NAME=I, PART=@\n0,0,1\n0,0,0,0,0,1,45\n*END INSTANCE",
    "*INSTANCE, NAME=I, PART=PUNCH\n1e300,0,0\n0,0,0,0,0,0,1e300\n*END INSTANCE", "*NSET, NSET=X, INSTANCE=BASE\n1",
    "*NSET, NSET=X, INSTANCE=@\n1", "*ELSET, ELSET=X, INSTANCE=TOP-1, GENERATE\n1,9,1", "*BOUNDARY\nTOP-1.1,1,3",
    "*BOUNDARY\nBASE.99999,1,1", "*CLOAD\nTOP-1.20,3,-1", "*BOUNDARY\nTOP-1.9223372036854775807,1,1",
    # Local systems (*TRANSFORM) and finite-strain plasticity (issues 63 and 66).
    "*TRANSFORM, NSET=NALL, TYPE=C\n0,0,0,0,0,1", "*TRANSFORM, NSET=NALL\n1,1,0,-1,1,0", "*TRANSFORM, NSET=@, TYPE=C\n0,0,0,0,0,0",
    "*TRANSFORM, NSET=NALL, TYPE=R\n1e300,0,0,0,1e-300,0", "*TRANSFORM, NSET=NALL, TYPE=X\n1,0,0,0,1,0",
    "*NODE PRINT, NSET=NALL, GLOBAL=NO\nU,RF", "*STEP, NLGEOM", "*ENDSTEP", "*SOLIDSECTION, ELSET=EALL, MATERIAL=EL",
    "*CYCLIC SYMMETRY MODEL, N=12\n0,0,0,0,0,1", "*CYCLIC SYMMETRY MODEL, N=0, TIE=T2\n0,0,0,0,0,0",
    "*TIE, NAME=C, CYCLIC SYMMETRY\nSSLAV,SMAST\n*CYCLIC SYMMETRY MODEL, N=1e300\n0,0,0,1,1,1", "*CLOAD\n1,3,1\n1,3,2",
    "*DLOAD, AMPLITUDE=A\nEALL,P1,1\n*DLOAD\nEALL,P1,2",
    # Temperatures (issue 65, item 4).
    "*EXPANSION\n1.2e-5", "*EXPANSION, ZERO=20\n1e300", "*EXPANSION, TYPE=ORTHO\n1,2,3", "*EXPANSION\n-1e-5\n1e-5,100",
    "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL,20", "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL,-1e300",
    "*INITIAL CONDITIONS, TYPE=STRESS\n1,1", "*INITIAL CONDITIONS\nNALL,1", "*TEMPERATURE\nNALL,1e30",
    "*TEMPERATURE\nNALL,120", "*TEMPERATURE, OP=NEW\n1,120", "*TEMPERATURE, AMPLITUDE=A\nNALL,100",
    "*TEMPERATURE, AMPLITUDE=@\nNALL,100", "*TEMPERATURE\n@,1", "*TEMPERATURE, USER\nNALL,1",
    "*MODEL CHANGE, TYPE=CONTACT PAIR, REMOVE\nSSLAV,SMAST", "*MODEL CHANGE, TYPE=CONTACT PAIR, ADD\nSSLAV,SMAST",
    "*MODEL CHANGE, TYPE=CONTACT PAIR, REMOVE\n@,@", "*MODEL CHANGE, TYPE=ELEMENT, REMOVE\nEALL", "*MODEL CHANGE", "*NODE, NSET=@\n1,0,0,0", "*NODE\n0,1,2,3",
    "*NODE\n2147483647,0,0,0", "*NODE\n9223372036854775807,0,0,0",
    "*ELEMENT, TYPE=C3D8\n5,1,1,1,1,1,1,1,1", "*" + "A" * 5000, "*NODE, NSET=" + "N" * 5000,
    # Reference nodes and couplings (issue 63, item 5).
    "*NODE\n99999,0,0,0\n99998,0,0,0\n*RIGID BODY, NSET=@, REF NODE=99999, ROT NODE=99998",
    "*NODE\n99999,1e300,0,0\n*RIGID BODY, ELSET=@, REFNODE=99999", "*RIGID BODY, NSET=@", "*RIGID BODY, NSET=@, ELSET=@",
    "*RIGID BODY, NSET=NALL, REF NODE=1, ROT NODE=1", "*RIGID BODY, NSET=NALL, ROT NODE=2",
    "*NODE\n99999,0,0,0\n*COUPLING, REF NODE=99999, SURFACE=@, CONSTRAINT NAME=C\n*KINEMATIC\n1,3",
    "*NODE\n99999,0,0,0\n*COUPLING, REF NODE=99999, SURFACE=@\n*DISTRIBUTING\n1,6",
    "*NODE\n99999,0,0,0\n*COUPLING, REF NODE=99999, SURFACE=@\n*KINEMATIC\n2\n*CLOAD\n99999,6,1e300",
    "*COUPLING, REF NODE=1, SURFACE=@\n*KINEMATIC\n0,9", "*COUPLING, REF NODE=@, SURFACE=@", "*KINEMATIC\n1,3",
    "*DISTRIBUTING\n4,6", "*NODE\n99999,0,0,0\n*ELEMENT, TYPE=DCOUP3D, ELSET=DC\n99999,99999\n"
    "*DISTRIBUTING COUPLING, ELSET=DC\n@,1.\n*CLOAD\n99999,2,1e3", "*DISTRIBUTING COUPLING, ELSET=@\n@,0",
    "*ELEMENT, TYPE=DCOUP3D, ELSET=DC\n1", "*BOUNDARY\n99999,4,6,0.1", "*CLOAD\n1,5,1", "*CLOAD\n99999,4,1",
    # Sets that name themselves: each block multiplies the set's length.
    "*NSET, NSET=NALL\n" + "NALL," * 2000 + "NALL\n*NSET, NSET=NALL\n" + "NALL," * 2000 + "NALL",
    ("*ELSET, ELSET=EALL\n" + "EALL," * 1000 + "EALL\n") * 4 + "*DLOAD\nEALL,P1,1"]


def deck_is_keyword(line):
    stripped = line.lstrip(" \t")
    return stripped.startswith("*") and not stripped.startswith("**")


def deck_is_data(line):
    stripped = line.strip(" \t\r\n")
    return bool(stripped) and not stripped.startswith("*")


def deck_blocks(lines):
    """(first line, end line, upper-case keyword name) of every keyword block."""
    starts = [(i, line.lstrip(" \t")[1:].split(",")[0].strip().upper())
              for i, line in enumerate(lines) if deck_is_keyword(line)]
    return [(i, starts[k + 1][0] if k + 1 < len(starts) else len(lines), name)
            for k, (i, name) in enumerate(starts)]


def deck_lines(text):
    return [line if line.endswith("\n") else line + "\n" for line in text.splitlines(keepends=True)]


def deck_data_lines(lines, names):
    """Indices of the data lines of blocks named in `names`."""
    return [i for first, end, name in deck_blocks(lines) if name in names
            for i in range(first + 1, end) if deck_is_data(lines[i])]


def deck_names(text):
    names = re.findall(r"(?:NSET|ELSET|NAME)\s*=\s*(\w+)", text, re.I)
    return names or ["NALL"]


def deck_truncate_line(text, rng):
    lines = deck_lines(text)
    candidates = [i for i, line in enumerate(lines) if line.strip()]
    if not candidates:
        return None
    i = rng.choice(candidates)
    body = lines[i].rstrip("\r\n")
    cut = rng.randrange(len(body))
    lines[i] = body[:cut] + "\n"
    return "".join(lines), f"line {i + 1} cut after {cut} characters"


def deck_keyword(text, rng):
    lines = deck_lines(text)
    i = rng.randrange(len(lines) + 1)
    if rng.random() < 0.2:
        letters = "ABCDEFGHIJKLMNOPQRSTUVWXYZ -=,"
        keyword = "*" + "".join(rng.choice(letters) for _ in range(rng.randint(1, 20)))
    else:
        keyword = rng.choice(DECK_KEYWORDS).replace("@", rng.choice(deck_names(text) + ["X"]))
    if rng.random() < 0.2:
        keyword = keyword.lower()
    lines.insert(i, keyword + "\n")
    return "".join(lines), f"line {i + 1} inserted: {keyword[:80]!r}"


def deck_word(text, rng):
    return number_replacer(DECK_WORDS)(text, rng)


def deck_face(text, rng):
    matches = list(re.finditer(r"(?<=,)[ \t]*([SsPp])([1-6])\b", text))
    if not matches:
        return None
    m = rng.choice(matches)
    letter = m.group(1).upper()
    value = rng.choice([f"{letter}0", f"{letter}7", f"{letter}9", f"{letter}10", f"{letter}-1",
                        letter, "S" if letter == "P" else "P", f"{'SP'[letter == 'S']}{m.group(2)}",
                        f"{letter.lower()}{m.group(2)}", f"{letter} {m.group(2)}", "", "X1"])
    line = text.count("\n", 0, m.start()) + 1
    return text[:m.start()] + value + text[m.end():], f"face {m.group().strip()} on line {line} -> {value!r}"


def deck_absent_node(text, rng):
    lines = deck_lines(text)
    elements = deck_data_lines(lines, {"ELEMENT"})
    if not elements:
        return None
    labels = [int(m.group(1)) for i in deck_data_lines(lines, {"NODE"})
              for m in [re.match(r"\s*(\d+)", lines[i])] if m]
    i = rng.choice(elements)
    fields = lines[i].rstrip("\r\n").split(",")
    k = rng.randrange(len(fields)) if rng.random() < 0.2 else rng.randrange(1, max(2, len(fields)))
    k = min(k, len(fields) - 1)
    value = str(rng.choice([max(labels, default=0) + 1, 0, -1, 2147483647, 2147483648,
                            9223372036854775807, 99999999999999999999, "1.0", "1e3",
                            rng.choice(labels) if labels else 1]))
    old = fields[k].strip()
    fields[k] = value
    lines[i] = ",".join(fields) + "\n"
    return "".join(lines), f"element line {i + 1}: field {k + 1} {old!r} -> {value}"


def deck_empty_surface(text, rng):
    lines = deck_lines(text)
    surfaces = [b for b in deck_blocks(lines) if b[2] == "SURFACE"]
    sets = [b for b in deck_blocks(lines) if b[2] in ("NSET", "ELSET")]
    if not surfaces and not sets:
        return None
    if not surfaces or (sets and rng.random() < 0.3):
        first, end, name = rng.choice(sets)
        kept = [line for line in lines[first + 1:end] if not deck_is_data(line)]
        return ("".join(lines[:first + 1] + kept + lines[end:]),
                f"*{name} at line {first + 1} emptied")
    first, end, _ = rng.choice(surfaces)
    kept = [line for line in lines[first + 1:end] if not deck_is_data(line)]
    if rng.random() < 0.5:
        return "".join(lines[:first + 1] + kept + lines[end:]), f"*SURFACE at line {first + 1} emptied"
    node_based = "TYPE=NODE" in lines[first].upper().replace(" ", "")
    empty = ("*NSET, NSET=EMPTYSET\n" if node_based else "*ELSET, ELSET=EMPTYSET\n")
    data = "EMPTYSET\n" if node_based else "EMPTYSET, S3\n"
    return ("".join(lines[:first] + [empty, lines[first], data] + kept + lines[end:]),
            f"*SURFACE at line {first + 1} made of an empty set")


def deck_same_surface(text, rng):
    lines = deck_lines(text)
    pairs = deck_data_lines(lines, {"CONTACT PAIR"})
    if not pairs:
        return None
    i = rng.choice(pairs)
    fields = [f.strip() for f in lines[i].rstrip("\r\n").split(",")]
    a, b = (fields + [""])[:2]
    value = rng.choice([f"{a},{a}", f"{b},{b}", f"{b},{a}", a, f"{a},{b},{a}", f",{b}", f"{a},",
                        f"NOPE,{b}", f"{a.lower()},{a.upper()}", ","])
    lines[i] = value + "\n"
    return "".join(lines), f"contact pair line {i + 1} -> {value!r}"


def deck_scale_field(lines, indices, field, factor):
    """Multiplies field `field` of the given data lines by factor; returns how many changed."""
    changed = 0
    for i in indices:
        fields = lines[i].rstrip("\r\n").split(",")
        if field >= len(fields):
            continue
        try:
            value = float(fields[field].replace("d", "e").replace("D", "e"))
        except ValueError:
            continue
        fields[field] = f"{value * factor:.9e}"
        lines[i] = ",".join(fields) + "\n"
        changed += 1
    return changed


def deck_magnitude(text, rng):
    """Moduli, loads or coordinates scaled by 10^k, k in -30..30: all of a kind, or one."""
    lines = deck_lines(text)
    exponent = rng.choice([-30, 30, rng.randint(-30, 30)])
    factor = 10.0 ** exponent
    what = rng.choice(["moduli", "loads", "coordinates"])
    if what == "moduli":
        targets = [(deck_data_lines(lines, {"ELASTIC"}), 0)]
    elif what == "loads":
        targets = [(deck_data_lines(lines, {"CLOAD", "DLOAD", "DSLOAD"}), 2)]
    else:
        nodes = deck_data_lines(lines, {"NODE"})
        targets = [(nodes, k) for k in (1, 2, 3)]
    single = rng.random() < 0.3
    changed = 0
    for indices, field in targets:
        if single and indices:
            indices = [rng.choice(indices)]
        changed += deck_scale_field(lines, indices, field, factor)
        if single and changed:
            break
    if not changed:
        return None
    return "".join(lines), f"{'one of the' if single else 'all'} {what} times 1e{exponent}"


def deck_parameter(text, rng):
    lines = deck_lines(text)
    keywords = [i for i, line in enumerate(lines) if deck_is_keyword(line) and "," in line]
    if not keywords:
        return None
    i = rng.choice(keywords)
    parts = lines[i].rstrip("\r\n").split(",")
    change = rng.choice(["drop", "value", "value", "add", "repeat", "no value"])
    k = rng.randrange(1, len(parts))
    key = parts[k].split("=")[0]
    if change == "drop":
        del parts[k]
    elif change == "value":
        parts[k] = key + "=" + rng.choice(["", "C3D20", "NODE", "ELEMENT", "SURFACE TO SURFACE",
                                           "NODE TO SURFACE", "XYZ", "YES", "NEW", "MOD",
                                           "NALL", "EALL", "SI1", "EL", "=", "A B", "x" * 300])
    elif change == "add":
        parts.insert(rng.randrange(1, len(parts) + 1),
                     rng.choice(["FOO=1", "NSET=NALL", "TYPE=NODE", "INPUT=x.inp", "GENERATE", "OP=NEW",
                                 "AMPLITUDE=A", "NLGEOM", "DIRECT", "TOTALS=ONLY", " "]))
    elif change == "repeat":
        parts.insert(k + 1, key + "=" + rng.choice(["OTHER", "NALL", parts[k].split("=")[-1]]))
    else:
        parts[k] = key
    lines[i] = ",".join(parts) + "\n"
    return "".join(lines), f"keyword line {i + 1} ({change}) -> {lines[i].strip()[:80]!r}"


def deck_block(text, rng):
    lines = deck_lines(text)
    blocks = deck_blocks(lines)
    if not blocks:
        return None
    first, end, name = rng.choice(blocks)
    block = lines[first:end]
    rest = lines[:first] + lines[end:]
    change = rng.choice(["duplicate", "delete", "move", "data only"])
    if change == "duplicate":
        lines = lines[:end] + block + lines[end:]
    elif change == "delete":
        lines = rest
    elif change == "move":
        at = rng.randrange(len(rest) + 1)
        lines = rest[:at] + block + rest[at:]
    else:
        lines = lines[:first] + lines[first + 1:]
    return "".join(lines), f"*{name} block at line {first + 1}: {change}"


def deck_continuation(text, rng):
    lines = deck_lines(text)
    candidates = [i for i, line in enumerate(lines) if line.strip() and not line.lstrip().startswith("**")]
    if not candidates:
        return None
    i = rng.choice(candidates)
    body = lines[i].rstrip("\r\n")
    if rng.random() < 0.5 or "," not in body:
        lines[i] = body + ",\n"
        return "".join(lines), f"line {i + 1} ends with a comma"
    commas = [m.end() for m in re.finditer(",", body)]
    cut = rng.choice(commas)
    lines[i] = body[:cut] + "\n" + body[cut:] + "\n"
    return "".join(lines), f"line {i + 1} split after column {cut}"


def deck_case(text, rng):
    lines = deck_lines(text)
    if not lines:  # an earlier mutation (a truncation) emptied the file
        return None
    i = rng.randrange(len(lines))
    changed = lines[i].lower() if rng.random() < 0.5 else lines[i].swapcase()
    # Back to latin-1 (the deck's bytes): a junk byte may change case out of it ('\xff' to U+0178).
    lines[i] = changed.encode("latin-1", "replace").decode("latin-1")
    return "".join(lines), f"line {i + 1} case changed"


DECK_MUTATORS = [number_replacer(DECK_EXTREMES), deck_word, deck_truncate_line, deck_keyword,
                 deck_face, deck_absent_node, deck_empty_surface, deck_same_surface,
                 deck_magnitude, deck_magnitude, deck_parameter, deck_block, deck_continuation,
                 deck_case]


def deck_include(text, target, rng):
    """*INCLUDE: part of the deck moved to a file it includes (fine), or an include of a missing
    file, of itself, in a cycle, too deep, of a folder or of a file that is no deck."""
    lines = deck_lines(text)
    blocks = deck_blocks(lines)
    change = rng.choice(["split", "split", "missing", "self", "cycle", "deep", "folder", "empty",
                         "long line", "binary", "parent"])
    at = rng.choice([b[0] for b in blocks]) if blocks else 0
    files = {}
    if change in ("split", "cycle"):
        first, end, name = rng.choice(blocks) if blocks else (0, len(lines), "")
        part = lines[first:end]
        if change == "cycle":
            part.append(f"*INCLUDE, INPUT={rng.choice([target, 'part.inp'])}\n")
        files["part.inp"] = "".join(part)
        lines[first:end] = ["*INCLUDE, INPUT=part.inp\n"]
        return "".join(lines), files, f"*INCLUDE ({change}) of the *{name} block at line {first + 1}"
    if change == "deep":
        depth = rng.choice([5, 31, 32, 33, 100])
        for k in range(depth):
            files[f"part{k}.inp"] = f"*INCLUDE, INPUT=part{k + 1}.inp\n" if k + 1 < depth else ""
        include = "part0.inp"
    elif change == "empty":
        files["part.inp"] = rng.choice(["", "\n", "**\n", "\r\n", ","])
        include = "part.inp"
    elif change == "long line":
        files["part.inp"] = "1," * rng.choice([600000, 2000000])
        include = "part.inp"
    elif change == "binary":
        files["part.inp"] = "".join(chr(rng.randrange(256)) for _ in range(rng.choice([10, 5000])))
        include = "part.inp"
    else:
        include = {"missing": "missing.inp", "self": target, "folder": ".", "parent": "../" + target}[change]
    lines.insert(at, f"*INCLUDE, INPUT={include}\n")
    return "".join(lines), files, f"*INCLUDE, INPUT={include} ({change}) at line {at + 1}"


def mutate_deck(files, target, rng):
    """One to three mutations of the deck `target`, most of them of the deck format; returns the
    case's files (the deck and any files it now includes) and the descriptions."""
    text = files[target].decode("latin-1")
    extra = {}
    done = []
    wanted = rng.choice([1, 1, 1, 2, 3])
    while len(done) < wanted:
        roll = rng.random()
        if roll < 0.1:
            result = deck_include(text, target, rng)
            if result is not None:
                text, more, what = result
                extra.update(more)
                done.append(what)
            continue
        result = rng.choice(DECK_MUTATORS if roll < 0.7 else GENERIC)(text, rng)
        if result is not None:
            text, what = result
            done.append(what)
    out = dict(files)
    out[target] = text.encode("latin-1")
    out.update({name: data.encode("latin-1") for name, data in extra.items()})
    return out, done

SPECIFIC = {".yaml": YAML_MUTATORS, ".msh": MSH_MUTATORS, ".mtx": MM_MUTATORS}


def mutate(data, suffix, rng):
    """One to three mutations, half of them of the file's format; returns text, descriptions."""
    text = data.decode("latin-1")
    done = []
    wanted = rng.choice([1, 1, 1, 2, 3])
    while len(done) < wanted:
        pool = SPECIFIC[suffix] if rng.random() < 0.5 else GENERIC
        result = rng.choice(pool)(text, rng)
        if result is not None:
            text, what = result
            done.append(what)
    return text.encode("latin-1"), done


# ---- running and judging a mutant -----------------------------------------------------------------

def law_option(rng):
    """Half the runs solve the pairs' own contact laws (contact.law=deck), half hard contact."""
    return ["--set", "contact.law=deck"] if rng.random() < 0.5 else []


def make_case(kind, rng, source_dir):
    """Files of the case (name -> bytes), the mutated file's name, the command after FETICON."""
    seed_dir = os.path.join(source_dir, "tests", "data", "fuzz")
    if kind == "export":  # a deck or a problem file's case, exported instead of run
        files, target, command = make_case(rng.choice(["deck", "problem"]), rng, source_dir)
        return files, target, ["export", command[1], "--format", "calculix", "--output", "out",
                               "--set", "memory_limit=2e9"]
    if kind == "deck":
        name = rng.choice(DECK_SEEDS)
        folder = seed_dir if name in FUZZ_FOLDER_DECKS else os.path.join(
            source_dir, "tests", "data", "abaqus" if name in ABAQUS_FOLDER_DECKS else "calculix")
        files = {name: deck_seed(folder, name)}
        return files, name, ["run", name, "--output", "out"] + RUN_OPTIONS + law_option(rng)
    if kind == "mm":
        files = {name: read(seed_dir, name) for name in MM_FILES}
        target = rng.choices(MM_FILES, weights=[2, 1, 1])[0]
        return files, target, QP_COMMAND
    names = rng.choice(PROBLEM_SEEDS if kind == "problem" else PROBLEM_SEEDS[3:])
    files = {name: read(seed_dir, name) for name in names}
    target = names[0] if kind == "problem" else names[1]
    return files, target, ["run", names[0], "--output", "out"] + RUN_OPTIONS + law_option(rng)


def deck_seed(folder, name):
    """A deck seed's bytes: the file, or a DECK_DERIVED edit of one (text inserted after the data
    line of the keyword)."""
    if name not in DECK_DERIVED:
        return read(folder, name)
    source, keyword, insert = DECK_DERIVED[name]
    lines = read(folder, source).decode("latin-1").split("\n")
    at = next(k for k, line in enumerate(lines) if line.upper().startswith(keyword)) + 2
    return "\n".join(lines[:at] + insert.rstrip("\n").split("\n") + lines[at:]).encode("latin-1")


def read(folder, name):
    with open(os.path.join(folder, name), "rb") as f:
        return f.read()


def run(feticon, command, folder, timeout):
    """Runs in its own process group (an MPI singleton may fork); returns status, out, err."""
    with open(os.path.join(folder, "stdout.txt"), "wb") as out, \
            open(os.path.join(folder, "stderr.txt"), "wb") as err:
        process = subprocess.Popen([feticon] + command, cwd=folder, stdout=out, stderr=err,
                                   stdin=subprocess.DEVNULL, start_new_session=True)
        try:
            status = process.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()
            status = None
    return (status, read_text(os.path.join(folder, "stdout.txt")),
            read_text(os.path.join(folder, "stderr.txt")))


def read_text(path, limit=1 << 20):
    """The first MiB of a file: enough to judge it, and bounded when a mutant floods output."""
    with open(path, "rb") as f:
        return f.read(limit).decode("utf-8", "replace")


def non_finite_json(value):
    """nlohmann writes NaN and infinities as null, so null counts as non-finite."""
    if value is None:
        return True
    if isinstance(value, float):
        return not math.isfinite(value)
    if isinstance(value, dict):
        return any(non_finite_json(v) for v in value.values())
    if isinstance(value, list):
        return any(non_finite_json(v) for v in value)
    return False


def non_finite_text(text):
    for token in re.split(r"[,\s]+", text):
        try:
            if not math.isfinite(float(token)):
                return True
        except ValueError:
            pass
    return False


def non_finite_calculix(out):
    """A non-finite number in a data row of the .dat (a line of numbers only) or the .frd (a
    " -1" record line, whose fixed-width numbers may touch: any nan or inf in it)."""
    for name in os.listdir(out) if os.path.isdir(out) else []:
        path = os.path.join(out, name)
        if name.endswith(".dat"):
            for line in read_text(path).splitlines():
                try:
                    values = [float(token) for token in line.split()]
                except ValueError:
                    continue
                if not all(math.isfinite(v) for v in values):
                    return True
        elif name.endswith(".frd"):
            if any(line.startswith(" -1") and re.search(r"nan|inf", line, re.I)
                   for line in read_text(path, 64 << 20).splitlines()):
                return True
    return False


def parse_json(text):
    try:
        return json.loads(text, parse_constant=float)
    except ValueError:
        return None


def judge(kind, folder, status, stdout, stderr):
    """The outcome of one run: one of OUTCOMES."""
    if status is None:
        return "timeout"
    if status < 0 or status >= 128:
        return "signal"
    if status not in ((0, 1, 3) if kind == "mm" else (0, 1)):
        return "other exit"
    if kind == "mm":
        report = parse_json(stdout) if status != 1 else None
        x = os.path.join(folder, "x.mtx")
        if ((report is not None and non_finite_json(report)) or non_finite_text(stdout)
                or (os.path.exists(x) and non_finite_text(read_text(x)))):
            return "non-finite"
    elif kind == "export":
        deck = os.path.join(folder, "out", "feticon.inp")
        report = read_text(deck) if os.path.exists(deck) else None
        if report is not None and non_finite_text(report):
            return "non-finite"
    else:
        out = os.path.join(folder, "out")
        summary = os.path.join(out, "summary.json")
        report = parse_json(read_text(summary)) if os.path.exists(summary) else None
        csvs = [os.path.join(out, f) for f in os.listdir(out) if f.endswith(".csv")] \
            if os.path.isdir(out) else []
        if (report is not None and non_finite_json(report)) or \
                any(non_finite_text(read_text(f)) for f in csvs) or \
                (kind == "deck" and non_finite_calculix(out)):
            return "non-finite"
    # Lines as `wc -l` counts them (tests/cli/bad_inputs.sh): a '\r' echoed from the input
    # does not end a line. Warning lines (a deck's penalty law, ...) may precede the error: they
    # describe the model, and the error itself must still be one line.
    if status == 1 and sum(1 for line in stderr.split("\n")[:-1] if not line.startswith("warning: ")) != 1:
        return "multi-line error"
    if status != 1 and not isinstance(report, str if kind == "export" else dict):
        return "bad output"
    return f"exit {status}"


def keep_failure(keep, name, folder, files, seed_files, target, command, what, outcome, stderr):
    saved = os.path.join(keep, name)
    shutil.rmtree(saved, ignore_errors=True)
    shutil.copytree(folder, saved, ignore=shutil.ignore_patterns("out", "x.mtx"))
    diff = difflib.unified_diff(seed_files[target].decode("latin-1").splitlines(keepends=True),
                                files[target].decode("latin-1").splitlines(keepends=True),
                                f"seed/{target}", target)
    with open(os.path.join(saved, "diff.txt"), "w", encoding="latin-1") as f:
        f.write(f"# {outcome}: {'; '.join(what)}\n")
        f.writelines(line[:2000] + ("\n" if len(line) > 2000 else "") for line in diff)
    with open(os.path.join(saved, "command.sh"), "w") as f:
        f.write(f'#!/usr/bin/env bash\n# {outcome}; first line of stderr: '
                f'{(stderr.splitlines() or [""])[0][:200]}\n'
                f'cd "$(dirname "$0")" && rm -rf out && '
                f'"${{FETICON:-feticon}}" {shlex.join(command)}\n')
    return saved


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("feticon")
    parser.add_argument("source_dir")
    amount = parser.add_mutually_exclusive_group()
    amount.add_argument("--mutants", type=int, default=60)
    amount.add_argument("--minutes", type=float)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--kinds", default="problem,gmsh,mm,deck")
    parser.add_argument("--timeout", type=float, default=30)
    parser.add_argument("--keep")
    args = parser.parse_args()
    kinds = args.kinds.split(",")
    unknown = set(kinds) - {"problem", "gmsh", "mm", "deck", "export"}
    if unknown:
        parser.error(f"unknown kinds {sorted(unknown)}")
    feticon = os.path.abspath(args.feticon)
    keep = args.keep
    work = tempfile.mkdtemp(prefix="feticon-fuzz-run-")
    counts = {kind: dict.fromkeys(OUTCOMES, 0) for kind in kinds}
    failures = []
    start = time.monotonic()
    index = 0
    try:
        while (index < args.mutants if args.minutes is None
               else time.monotonic() - start < 60 * args.minutes):
            kind = kinds[index % len(kinds)]
            rng = random.Random(f"{args.seed}/{index}")
            seed_files, target, command = make_case(kind, rng, args.source_dir)
            if target.endswith(".inp"):
                files, what = mutate_deck(seed_files, target, rng)
            else:
                files = dict(seed_files)
                files[target], what = mutate(seed_files[target], os.path.splitext(target)[1], rng)
            folder = os.path.join(work, f"{kind}-{index:05d}")
            os.mkdir(folder)
            for name, data in files.items():
                with open(os.path.join(folder, name), "wb") as f:
                    f.write(data)
            status, stdout, stderr = run(feticon, command, folder, args.timeout)
            outcome = judge(kind, folder, status, stdout, stderr)
            counts[kind][outcome] += 1
            if outcome in FAILURES:
                keep = keep or tempfile.mkdtemp(prefix="feticon-fuzz-failures-")
                saved = keep_failure(keep, f"{kind}-{index:05d}", folder, files, seed_files,
                                     target, command, what, outcome, stderr)
                failures.append(saved)
                print(f"FAIL {kind} mutant {index} ({target}: {'; '.join(what)[:300]}): "
                      f"{outcome} (status {status}); saved in {saved}", flush=True)
            shutil.rmtree(folder)
            index += 1
    finally:
        shutil.rmtree(work, ignore_errors=True)

    elapsed = time.monotonic() - start
    shown = [o for o in OUTCOMES if any(counts[k][o] for k in kinds)] or OUTCOMES[:2]
    print(f"\n{index} mutants in {elapsed:.0f} s (seed {args.seed})")
    print(f"{'kind':10}" + "".join(f"{o:>18}" for o in shown) + f"{'total':>8}")
    for kind in kinds:
        print(f"{kind:10}" + "".join(f"{counts[kind][o]:>18}" for o in shown)
              + f"{sum(counts[kind].values()):>8}")
    if failures:
        print(f"{len(failures)} failing mutants saved in {keep} (FETICON=... bash "
              f"{keep}/NAME/command.sh reproduces one)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
