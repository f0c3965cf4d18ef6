#!/usr/bin/env python3
"""Writes the generated Nastran test data: one small model in every bulk data format variant the
reader supports, for tests/unit/fe_io/nastran_reader_test.cc (all variants must
read to the same mesh):

  nastran/variants/small.bdf    small field (8 columns), explicit +name
                                continuations, compact reals ("1.-3", ".3"),
                                executive and case control before BEGIN BULK
  nastran/variants/large.bdf    large field (GRID*, 16 columns, * continuations),
                                reals with a D exponent ("2.1D+11")
  nastran/variants/free.bdf     free field (commas), continuations with a blank
                                or + first field, plain reals
  nastran/variants/tabs.bdf     tab-separated small field, lower-case names,
                                implicit (blank) continuations, E exponents
  nastran/variants/include.bdf  small field split over INCLUDEd files (a quoted
                                name continued over two lines, a nested include
                                relative to the including file)

and a cantilever strip for the frequency test:

  nastran/strip.bdf             20 x 2 CQUAD4, 1 m x 50 mm x 5 mm steel,
                                clamped at x = 0 (SPC1)

Usage: /usr/bin/python3 make_nastran_data.py  (writes next to this script)
"""
from decimal import Decimal
import os

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "nastran", "variants")

# the model: (name, [fields 2..]) with int, float, str or None (blank);
# reals use few digits so that every notation denotes the same decimal
CARDS = [
    ("CORD2R", [1, 0, 1.0, 2.0, 3.0, 1.0, 2.0, 4.0, 1.0, 3.0, 3.0]),
    ("CORD2R", [2, 1, 0.5, 0.0, 0.0, 0.5, 0.0, 1.0, 1.5, 1.0, 0.0]),
    ("MAT1", [1, 2.1e11, None, 0.3, 7850.0]),
    ("MAT1", [2, 7.0e10, 2.6e10, None, 2700.0]),
    ("PSHELL", [10, 1, 0.002, 1, None, 1, None, 0.5]),
    ("PBARL", [20, 1, None, "BOX", None, None, None, None, 0.05, 0.04, 0.004, 0.003, 0.1]),
    ("PBEAM", [30, 2, 0.0012, 2.5e-6, 1.5e-6, 0.0, 3.0e-6, 0.0,
               0.01, 0.02, None, None, None, None, None, None,
               0.85, 0.85]),
    ("PSOLID", [40, 2]),
] + [
    ("GRID", [1 + i + 3 * j, None, 0.1 * i, 0.1 * j, 0.0]) for j in range(3) for i in range(3)
] + [
    ("GRID", [10, 1, 0.1, -0.2, 0.5]),
    ("GRID", [19, 2, -0.25, 0.001, 0.75]),
] + [
    ("GRID", [11 + k, None, 0.5 + 0.05 * (k % 2 if k < 4 else (k - 4) % 2),
              0.05 * ((k % 4) // 2), 0.05 * (k // 4)]) for k in range(8)
] + [
    ("CQUAD4", [101, 10, 1, 2, 5, 4]),
    ("CQUAD4", [102, 10, 4, 5, 8, 7, 0.0, 0.001]),
    ("CQUAD4", [105, 10, 5, 6, 9, 8, None, None, None, None, 0.002, 0.002, None, 0.002]),
    ("CTRIA3", [103, 10, 2, 3, 6]),
    ("CTRIA3", [104, 10, 2, 6, 5, 15.0, -0.0005]),
    ("CBAR", [201, 20, 1, 3, 0.0, 0.0, 1.0, None, None, None, 0.0, 0.0, 0.01, 0.0, 0.0, 0.01]),
    ("CBEAM", [202, 30, 7, 9, 1, None, None, "BGG"]),
    ("CHEXA", [301, 40, 11, 12, 14, 13, 15, 16, 18, 17]),
    ("CTETRA", [302, 40, 11, 12, 13, 15]),
    ("CONM2", [401, 9, None, 2.5, 0.01, 0.0, -0.02, None, 0.1, 0.01, 0.2, 0.0, 0.02, 0.3]),
    ("CONM2", [402, 10, -1, 1.5, 1.0, 2.0, 3.5]),
    ("RBE2", [501, 19, 123456, 7, "THRU", 9]),
    ("SPC1", [1, 123456, 1, "THRU", 3]),
    ("SPC1", [2, 3, 4]),
    ("ASET1", [123456, 7, 8, 9]),
    ("SET1", [5, 1, 2, 3, "THRU", 6]),
    ("PARAM", ["POST", -1]),
    ("EIGRL", [1, None, None, 10]),
]


def decimal_parts(v):
    """sign, digit string, exponent of the shortest decimal of v, as d.ddd x 10^e"""
    d = Decimal(repr(float(v))).normalize()
    sign, digits, exp = d.as_tuple()
    digits = "".join(map(str, digits))
    return ("-" if sign else ""), digits, exp + len(digits) - 1


def real_small(v):
    if v == 0.0:
        return "0."
    s, digits, e = decimal_parts(v)
    if -2 <= e <= 4:
        # fixed: "7850.", ".3", "-.005"
        if e >= 0:
            ip = digits[: e + 1].ljust(e + 1, "0")
            return s + ip + "." + digits[e + 1:]
        return s + "." + "0" * (-e - 1) + digits
    text = s + digits[0] + "." + digits[1:] + ("+" if e > 0 else "-") + str(abs(e))
    assert len(text) <= 8, text
    return text


def real_large(v):
    if v == 0.0:
        return "0.0D0"
    s, digits, e = decimal_parts(v)
    return s + digits[0] + "." + (digits[1:] or "0") + "D" + ("+" if e >= 0 else "-") + str(abs(e))


def real_e(v):
    if v == 0.0:
        return "0.0"
    s, digits, e = decimal_parts(v)
    return s + digits[0] + "." + digits[1:] + "e" + str(e)


def real_free(v):
    return repr(float(v))


def text(value, real):
    if value is None:
        return ""
    if isinstance(value, float):
        return real(value)
    return str(value)


def rows(fields, per_line):
    return [fields[k:k + per_line] for k in range(0, max(len(fields), 1), per_line)]


def small_card(name, fields, real, marker):
    lines = []
    chunks = rows([text(f, real) for f in fields], 8)
    for k, chunk in enumerate(chunks):
        head = name if k == 0 else "+" + marker + str(k)
        line = head.ljust(8) + "".join(t.rjust(8) for t in chunk)
        if k + 1 < len(chunks):
            line = line.ljust(72) + ("+" + marker + str(k + 1))
        lines.append(line.rstrip())
    return lines


def large_card(name, fields):
    lines = []
    chunks = rows([text(f, real_large) for f in fields], 4)
    if len(chunks) % 2:
        chunks.append([])
    for k, chunk in enumerate(chunks):
        head = (name + "*") if k == 0 else "*L" + str(k)
        line = head.ljust(8) + "".join(t.ljust(16) for t in chunk)
        if k + 1 < len(chunks):
            line = line.ljust(72) + "*L" + str(k + 1)
        lines.append(line.rstrip())
    return lines


def free_card(name, fields):
    lines = []
    for k, chunk in enumerate(rows([text(f, real_free) for f in fields], 8)):
        head = name if k == 0 else ("" if k % 2 else "+")
        lines.append(",".join([head] + chunk))
    return lines


def tab_card(name, fields):
    lines = []
    for k, chunk in enumerate(rows([text(f, real_e) for f in fields], 8)):
        head = name.lower() if k == 0 else ""
        line = head
        for t in [None] + chunk:
            if t is not None:
                assert len(t) < 8, t
                line += t
            line += "\t"
        lines.append(line.rstrip("\t"))
    return lines


EXECUTIVE = """$ executive and case control are skipped by the reader
SOL 103
CEND
TITLE = format variant test
SPC = 1
METHOD = 1
BEGIN BULK
"""


def write(name, text_lines):
    with open(os.path.join(OUT, name), "w") as f:
        f.write("\n".join(text_lines) + "\n")


def main():
    os.makedirs(os.path.join(OUT, "sub"), exist_ok=True)
    small = EXECUTIVE.splitlines() + ["$ small field"]
    for n, (name, fields) in enumerate(CARDS):
        small += small_card(name, fields, real_small, chr(ord("A") + n % 26))
    small += ["ENDDATA", "GRID    999             junk after ENDDATA is ignored"]
    write("small.bdf", small)

    large = ["$ large field, no executive section"]
    for name, fields in CARDS:
        large += large_card(name, fields)
    write("large.bdf", large)

    free = ["$ free field", "BEGIN BULK"]
    for name, fields in CARDS:
        free += free_card(name, fields)
    free += ["ENDDATA"]
    write("free.bdf", free)

    tabs = ["$ tabs"]
    for name, fields in CARDS:
        tabs += tab_card(name, fields)
    write("tabs.bdf", tabs)

    # the same cards split over three files
    head, middle, tail = CARDS[:8], CARDS[8:25], CARDS[25:]
    main_lines = EXECUTIVE.splitlines()
    for name, fields in head:
        main_lines += small_card(name, fields, real_small, "M")
    main_lines += ["INCLUDE 'sub/", "   part_a.bdf'  $ a quoted name continued on the next line"]
    main_lines += ["ENDDATA"]
    write("include.bdf", main_lines)
    part_a = ["$ included from include.bdf"]
    for name, fields in middle:
        part_a += small_card(name, fields, real_small, "A")
    part_a += ['include "part_b.bdf"']
    write(os.path.join("sub", "part_a.bdf"), part_a)
    part_b = ["$ included from sub/part_a.bdf, relative to it"]
    for name, fields in tail:
        part_b += small_card(name, fields, real_small, "B")
    write(os.path.join("sub", "part_b.bdf"), part_b)


def quad_strip(nx, ny, length, width, number):
    """GRID and CQUAD4 cards (free field, PSHELL 1) of a flat strip length x width in z = 0 of
    nx x ny quads, node ids 1 + i + (nx + 1) j; coordinates written by number(x).
    Returns the cards and the node id function gid(i, j)."""
    gid = lambda i, j: 1 + i + (nx + 1) * j
    lines = []
    for j in range(ny + 1):
        for i in range(nx + 1):
            lines.append("GRID,%d,,%s,%s,0." % (gid(i, j), number(length * i / nx), number(width * j / ny)))
    eid = 1
    for j in range(ny):
        for i in range(nx):
            lines.append("CQUAD4,%d,1,%d,%d,%d,%d" % (eid, gid(i, j), gid(i + 1, j), gid(i + 1, j + 1), gid(i, j + 1)))
            eid += 1
    return lines, gid


def strip():
    nx, ny = 20, 2
    lines = ["$ cantilever strip: L = 1 m, b = 50 mm, t = 5 mm, steel; clamped at x = 0",
             "BEGIN BULK",
             "MAT1,1,2.1+11,,0.3,7850.",
             "PSHELL,1,1,0.005,1,,1"]
    cards, gid = quad_strip(nx, ny, 1.0, 0.05, repr)
    lines += cards
    lines.append("SPC1,1,123456," + ",".join(str(gid(0, j)) for j in range(ny + 1)))
    lines.append("ENDDATA")
    with open(os.path.join(HERE, "nastran", "strip.bdf"), "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    strip()
    main()
