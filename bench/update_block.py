#!/usr/bin/env python3
"""Replaces the generated block NAME of a Markdown file with standard input:
the lines between `<!-- begin NAME -->` and `<!-- end NAME -->`, so that a
hand-written page can hold figures a script regenerates.

usage: update_block.py FILE NAME < CONTENT"""
import sys


def main():
    path, name = sys.argv[1], sys.argv[2]
    begin, end = f"<!-- begin {name} -->", f"<!-- end {name} -->"
    text = open(path).read()
    if begin not in text or end not in text:
        sys.exit(f"update_block: {path} has no block {name}")
    head, rest = text.split(begin, 1)
    _, tail = rest.split(end, 1)
    body = sys.stdin.read().strip("\n")
    open(path, "w").write(f"{head}{begin}\n{body}\n{end}{tail}")


if __name__ == "__main__":
    main()
