#!/usr/bin/env python3
"""Checks that every file of a layer includes headers of its own layer or of layers above it
in docs/layout.md's table (data flows downward), and that the table names every layer folder.

Usage: check_layers.py SOURCE_DIR. Exit status 0 when the includes agree with the table."""
import pathlib
import re
import sys

top = pathlib.Path(sys.argv[1])
table = (top / "docs" / "layout.md").read_text()
order = re.findall(r"^\| (\w+)/? \| `(?:include/penumbra/\w+/|src/cli/)`", table, re.M)
rank = {layer: k for k, layer in enumerate(order)}
folders = {p.name for p in (top / "include" / "penumbra").iterdir() if p.is_dir()}
problems = [f"docs/layout.md: layer {name}/ is missing from the table"
            for name in sorted(folders - set(rank))]

include = re.compile(r'^#include "penumbra/(\w+)/', re.M)
for root, layer_of in ((top / "include" / "penumbra", lambda p: p.parts[0]),
                       (top / "src", lambda p: p.parts[0])):
    for path in sorted(root.rglob("*")):
        if path.suffix not in (".h", ".cpp"):
            continue
        layer = layer_of(path.relative_to(root))
        if layer not in rank:
            continue
        for used in include.findall(path.read_text()):
            if used in rank and rank[used] > rank[layer]:
                problems.append(f"{path.relative_to(top)}: the {layer}/ layer includes "
                                f"{used}/, a layer below it")

for problem in problems:
    print(problem)
print(f"{len(order)} layers, {len(problems)} problems")
sys.exit(1 if problems else 0)
