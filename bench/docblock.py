#!/usr/bin/env python3
"""Replaces the text between <!-- bench:NAME:start --> and <!-- bench:NAME:end --> in a
Markdown file by "Measured DATE by `SOURCE`:" and a table.

usage: docblock.py DOC NAME SOURCE TABLE_FILE      (or import docblock.write)"""
import datetime, re, sys

import runs


def write(doc, name, source, table):
    start, end = f"<!-- bench:{name}:start -->", f"<!-- bench:{name}:end -->"
    text = open(doc).read()
    if start not in text or end not in text:
        sys.exit(f"{doc} has no {start} ... {end} markers")
    block = f"{start}\nMeasured {datetime.date.today()} by `{source}`:\n\n{table}{end}"
    text = re.sub(re.escape(start) + ".*?" + re.escape(end), lambda _: block, text, flags=re.S)
    open(doc, "w").write(text)


if __name__ == "__main__":
    doc, name, source, table = runs.positional(__doc__, 4)
    write(doc, name, source, open(table).read())
