#!/usr/bin/env python3
"""Writes the generated blocks of doc/verification.md and doc/studies.md from runs of the built
`contactlab` (`make docs`), or checks that the committed blocks are what it would write
(--check, the `docs.current` test).

A block is the text between `<!-- generated:NAME:start -->` and `<!-- generated:NAME:end -->`;
BLOCKS (doc/doc_blocks.py) says which function writes each. The cases are the cheap ones (seconds each, about
three minutes in all on 2 shared cores, two cases at a time). The expensive blocks (`<!-- bench:NAME:... -->`) are written
by bench/run.sh and left alone; the `sources` block lists every block and what writes it.

--check writes the blocks into a copy of the pages (in memory) and the figures into the work
folder, and compares the blocks with the committed ones, line by line, naming the block and the line of the first difference:
text and integers (iteration counts, point counts) exactly, other numbers within NUMBER_RTOL or
one unit of their last printed digit (see numbers_agree). Figures are not compared (matplotlib's
output varies between versions); the check requires each PNG a page links to to exist and be
non-empty.

usage: doc/generate.py CONTACTLAB [--check] [--jobs N] [--ranks N] [--work DIR] [--only NAME ...]"""
import argparse
import os
import re
import shutil
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

from doc_blocks import BLOCKS, Runs, table  # doc/, the script's own folder

HERE = os.path.dirname(os.path.abspath(__file__))

PAGES = ("verification.md", "studies.md")

# A number of a checked block may move by this much, relative, and still agree. The cases are
# deterministic but for round-off: another BLAS kernel set (OPENBLAS_CORETYPE) or another rank
# count changes the sums' order, and the converged answers move at Newton's tolerance (1e-8
# relative) or the fixed point's (1e-6), far below the 4 significant digits printed. 1e-3 is
# a margin of three decades above that and still catches any change a reader would see.
NUMBER_RTOL = 1e-3
# Iteration counts that round-off moves, by block and column: a run whose path crosses a status
# switch within round-off (doc/algorithms.md, "Round-off"). Measured 2026-11-29 on the extremes
# (native, Prescott, Haswell, Sandy Bridge and Zen kernels): 7 of its 78 counts move, by up to
# 3 iterations or 17 % (r_n = 10 E/h under partial Newton: 18, and 21 under Sandy Bridge's); the
# quick comparison moved by one under Prescott's; the verification blocks' counts and the Hertz
# study's do not move (Haswell, Prescott, 2 ranks). These columns agree by iterations_agree;
# every other integer is compared exactly.
BANDED_COLUMNS = {"quick-comparison": ("Newton its",),
                  "extremes": ("generalized Newton", "partial Newton", "fixed point")}


def iterations_agree(a, b):
    """Two round-off-moved iteration counts agree: within 3, or 20 % of the larger for the long
    runs (kernel sets not measured here may move more)."""
    return abs(a - b) <= max(3, 0.2 * max(a, b))


NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


# The expensive blocks, written by bench/ (marker name: the command that writes it).
BENCH = {"ironing3d-small": "bench/run.sh ironing3d",
         "ironing3d": "bench/run.sh --large ironing3d",
         "normal-field": "bench/run.sh normal-field",
         "study-process": "bench/run.sh study-process",
         "fuzz:million": "bench/fuzz.sh"}
STUDIES_FIRST = ("extremes", "quick-comparison", "hertz-2d-study")  # the long ones start first


def markers(name, kind="generated"):
    return f"<!-- {kind}:{name}:start -->", f"<!-- {kind}:{name}:end -->"


def replace_block(text, name, body, page):
    start, end = markers(name)
    if text.count(start) != 1 or text.count(end) != 1:
        sys.exit(f"doc/{page} needs exactly one {start} ... {end}")
    head, rest = text.split(start)
    return head + start + "\n" + body + end + rest.split(end)[1]


def block_sources(texts):
    """Every marked block of the pages and what writes it."""
    rows = []
    for page in PAGES:
        found = re.findall(r"^<!-- (generated|bench):([\w-]+):start -->$", texts[page], re.M)
        for kind, name in found:
            if kind == "generated" and name in BLOCKS:
                rows.append([page, f"`generated:{name}`", f"`doc/generate.py` (`make docs`), "
                             f"from {BLOCKS[name][2]}; checked by the `docs.current` test"])
            elif kind == "bench":
                rows.append([page, f"`bench:{name}`", f"`{BENCH.get(name, 'bench/run.sh')}` "
                             "(not checked: minutes to hours)"])
        if "<!-- fuzz:million -->" in texts[page]:
            rows.append([page, "`fuzz:million`", f"`{BENCH['fuzz:million']}` (not checked)"])
    return table(["page", "block", "written by"], rows)


# ---------------------------------------------------------------- the check

def numbers_agree(a, b):
    """Two printed numbers agree: integers exactly; others within NUMBER_RTOL relative or one
    unit of the last digit either was printed with (a value on a rounding boundary flips it)."""
    if re.fullmatch(r"[-+]?\d+", a) and re.fullmatch(r"[-+]?\d+", b):
        return int(a) == int(b)

    def last_digit(s):
        mantissa, _, exponent = s.lower().partition("e")
        decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
        return 10.0 ** (int(exponent or 0) - decimals)

    x, y = float(a), float(b)
    return abs(x - y) <= max(NUMBER_RTOL * max(abs(x), abs(y)), last_digit(a), last_digit(b))


def lines_agree(committed, generated, banded=()):
    """The same text between the numbers, and the numbers agreeing; in a table row, the cells
    of the columns BANDED (indices) hold iteration counts compared by iterations_agree."""
    if banded and committed.startswith("|") and generated.startswith("|"):
        old, new = committed.split("|"), generated.split("|")
        chaotic = len(old) > 1 and old[1].strip() in CHAOTIC_ROWS
        return len(old) == len(new) and all(
            (outcome_of_chaotic_run(a) and outcome_of_chaotic_run(b) if chaotic
             else cells_agree(a, b)) if i in banded else lines_agree(a, b)
            for i, (a, b) in enumerate(zip(old, new)))
    if NUMBER.split(committed) != NUMBER.split(generated):
        return False
    pairs = zip(NUMBER.findall(committed), NUMBER.findall(generated))
    return all(numbers_agree(a, b) for a, b in pairs)


# Failures that round-off picks between on a degenerate run, accepted for one another in the
# BANDED_COLUMNS: the extremes' pad touching without load has every point at the status switch,
# and a Newton iterate whose points all open leaves the pad held by nothing (singular-tangent)
# where another cycles to the limit (max-iterations); measured: the cell moved from the one to
# the other when the linear elements' force became K u (the same numbers to round-off). Since
# Newton gives up on a residual that repeats a two-iterate cycle ("Newton cycles", failure
# 'diverged'; doc/algorithms.md "Stalled Newton"), statuses that flip at ||R|| = 0 end so
# instead of spending Max Iterations: measured on this machine, the grazing pad under partial
# Newton and the pad at r_n = 1e8 E/h went from max-iterations to diverged.
INTERCHANGEABLE_FAILURES = {"max-iterations", "singular-tangent", "diverged"}
# Rows of such a degenerate run where round-off also picks between converging and those failures:
# the grazing pad under partial Newton converged in 34 iterations on the machine that wrote the
# page, fails with max-iterations (||R|| = 0, the statuses still flipping) on an AMD EPYC with
# its default kernels and with Prescott's, Haswell's and Zen's, converges in 20 with
# Sandybridge's. Their banded cells agree when both are a convergence ("✓ N") or one of
# INTERCHANGEABLE_FAILURES; any other failure (a NaN, a crash) still differs.
CHAOTIC_ROWS = {"grazing: touching, no press"}


def outcome_of_chaotic_run(cell):
    cell = cell.strip()
    return cell in INTERCHANGEABLE_FAILURES or re.fullmatch(r"✓ \d+", cell) is not None


def cells_agree(committed, generated):
    """Table cells of iteration counts: the same text, the integers by iterations_agree; two
    INTERCHANGEABLE_FAILURES agree."""
    if {committed.strip(), generated.strip()} <= INTERCHANGEABLE_FAILURES:
        return True
    a, b = NUMBER.findall(committed), NUMBER.findall(generated)
    return (NUMBER.split(committed) == NUMBER.split(generated)
            and all(iterations_agree(int(x), int(y)) if re.fullmatch(r"\d+", x + y)
                    else numbers_agree(x, y) for x, y in zip(a, b)))


def banded_cells(name, header):
    """The indices, in a row split at "|", of the block's iteration columns that round-off
    moves."""
    cells = [c.strip() for c in header.split("|")]
    return {i for i, c in enumerate(cells) if c in BANDED_COLUMNS.get(name, ())}


def block_lines(text, name):
    """The block's lines and the page line number of the first one."""
    start, end = markers(name)
    head, rest = text.split(start)
    return rest.split(end)[0].split("\n")[1:], head.count("\n") + 2


def compare_block(page, name, committed, generated):
    """The first difference of block NAME as a sentence, or None."""
    if markers(name)[0] not in committed:
        return f"doc/{page}: block {name} is missing (its markers were removed)"
    old, first = block_lines(committed, name)
    new, _ = block_lines(generated, name)
    banded = banded_cells(name, old[0]) if old else set()
    for i in range(max(len(old), len(new))):
        a = old[i] if i < len(old) else "(nothing)"
        b = new[i] if i < len(new) else "(nothing)"
        if not lines_agree(a, b, banded):
            return (f"doc/{page}:{first + i}: block {name} differs from what doc/generate.py "
                    f"writes:\n  committed: {a}\n  generated: {b}")
    return None


def missing_figures(texts):
    """The PNGs the pages link to that are absent or empty."""
    bad = []
    for page in PAGES:
        for png in re.findall(r"\]\((figures/[^)]+\.png)\)", texts[page]):
            path = os.path.join(HERE, png)
            if not os.path.exists(path) or os.path.getsize(path) == 0:
                bad.append(f"doc/{page} links to {png}, absent or empty")
    return bad


# ---------------------------------------------------------------- main

def generate(exe, work, names, jobs, figures, ranks=1):
    """The bodies of the blocks NAMES, run JOBS at a time."""
    runs = Runs(exe, work, ranks)
    order = sorted(names, key=lambda n: n not in STUDIES_FIRST)
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = {n: pool.submit(BLOCKS[n][1], runs, figures) for n in order}
        return {n: f.result() for n, f in futures.items()}


def check(committed, generated, names):
    """Exits with 1, saying where, when a block NAMES (or `sources`) of the committed pages
    differs from the generated one or a linked figure is missing."""
    problems = []
    for name in names + ["sources"]:
        page = BLOCKS[name][0] if name in BLOCKS else "verification.md"
        problems.append(compare_block(page, name, committed[page], generated[page]))
    problems = [p for p in problems if p] + missing_figures(committed)
    for p in problems:
        print(p)
    if problems:
        print("run `make docs` and commit the pages (or explain why the numbers moved)")
        sys.exit(1)
    print(f"{len(names) + 1} generated blocks of doc/{' and doc/'.join(PAGES)} current")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("exe", help="the built contactlab")
    ap.add_argument("--check", action="store_true",
                    help="compare with the committed pages instead of rewriting them")
    ap.add_argument("--jobs", type=int, default=2, help="cases run at a time (default 2)")
    ap.add_argument("--work", help="folder for the runs (default: a temporary one, removed)")
    ap.add_argument("--ranks", type=int, default=1,
                    help="ranks of each single run (not the studies'): the blocks must not "
                         "depend on it")
    ap.add_argument("--only", nargs="+", choices=sorted(BLOCKS), help="only these blocks")
    ap.add_argument("--doc-dir", default=HERE,
                    help="the folder of the pages read (and rewritten); default doc/")
    args = ap.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="contactlab-docs-")
    figures = os.path.join(work, "figures") if args.check else os.path.join(HERE, "figures")
    os.makedirs(figures, exist_ok=True)
    texts = {p: open(os.path.join(args.doc_dir, p)).read() for p in PAGES}
    bodies = generate(os.path.abspath(args.exe), work, args.only or list(BLOCKS), args.jobs,
                      figures, args.ranks)
    new = dict(texts)
    for name, body in bodies.items():
        page = BLOCKS[name][0]
        new[page] = replace_block(new[page], name, body, page)
    new["verification.md"] = replace_block(new["verification.md"], "sources",
                                           block_sources(new), "verification.md")
    if not args.work:
        shutil.rmtree(work, ignore_errors=True)
    if args.check:
        check(texts, new, list(bodies))
        return
    for page in PAGES:
        open(os.path.join(args.doc_dir, page), "w").write(new[page])
    print("\n".join(f"{BLOCKS[n][0]}: generated:{n}" for n in bodies))
    print(f"doc/{' and doc/'.join(PAGES)} rewritten")


if __name__ == "__main__":
    main()
