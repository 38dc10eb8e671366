#!/usr/bin/env python3
"""doc/scenes.md embeds `contactlab list` between markers: check that it is current, or rewrite
it with --update (`make docs`).

usage: check_scenes_doc.py CONTACTLAB DOC [--update]"""
import subprocess, sys

exe, doc = sys.argv[1], sys.argv[2]
start, end = "<!-- contactlab list:start -->", "<!-- contactlab list:end -->"
listing = subprocess.run([exe, "list"], capture_output=True, text=True, check=True).stdout
listing = listing.split("\n", 2)[2]  # drop the title line
text = open(doc).read()
head, rest = text.split(start, 1)
current, tail = rest.split(end, 1)
wanted = head + start + "\n" + listing + end + tail
if "--update" in sys.argv:
    open(doc, "w").write(wanted)
    print(f"{doc} updated")
elif text != wanted:
    print(f"{doc} does not match `contactlab list`: run `make docs` and commit the result")
    sys.exit(1)
else:
    print(f"{doc} matches `contactlab list`")
