#!/usr/bin/env python3
"""Writes fields/plants.field: the demo's "Plants" map for its hills, mixing the Sapling test plants
(assets/test_plants) with sunflowers. 't' maple trees, 'b' bottlebrush bushes, 'g' grass clumps,
'*' sunflowers; cells of 0.5 m.

    tools/make_plants_field.py [OUT]

A meadow of grass clumps with scattered bushes, maples standing about 9 m apart (a cell's neighbours
left free under each crown), and a patch of sunflowers. Deterministic: the same run writes the same file.
"""
import random
import sys

COLUMNS, ROWS = 240, 240
TREE_SPACING = 18  # cells between maples, before jitter
CROWN = 4  # cells around a maple left free of bushes and sunflowers


def main():
    out_path = sys.argv[1] if len(sys.argv) > 1 else "fields/plants.field"
    rng = random.Random(7)
    grid = [[" "] * COLUMNS for _ in range(ROWS)]
    for r in range(ROWS):
        for c in range(COLUMNS):
            if rng.random() < 0.22:
                grid[r][c] = "g"
    for r in range(150, 200):  # the sunflower patch
        for c in range(30, 90):
            if (r - 175) ** 2 / 625 + (c - 60) ** 2 / 900 < 1.0:
                grid[r][c] = "*"
    for r in range(ROWS):
        for c in range(COLUMNS):
            if grid[r][c] != "*" and rng.random() < 0.012:
                grid[r][c] = "b"
    trees = []
    for r in range(TREE_SPACING // 2, ROWS, TREE_SPACING):
        for c in range(TREE_SPACING // 2, COLUMNS, TREE_SPACING):
            tr, tc = r + rng.randrange(-4, 5), c + rng.randrange(-4, 5)
            if 0 <= tr < ROWS and 0 <= tc < COLUMNS and grid[tr][tc] != "*" and rng.random() < 0.7:
                trees.append((tr, tc))
    for tr, tc in trees:
        for r in range(max(0, tr - CROWN), min(ROWS, tr + CROWN + 1)):
            for c in range(max(0, tc - CROWN), min(COLUMNS, tc + CROWN + 1)):
                if grid[r][c] in "b*":
                    grid[r][c] = "g"
        grid[tr][tc] = "t"
    counts = {s: sum(row.count(s) for row in grid) for s in "tbg*"}
    with open(out_path, "w", encoding="utf-8", newline="\n") as out:
        out.write("# Plants: %d x %d cells of 0.5 m for the demo's hills, written by tools/make_plants_field.py.\n"
                  % (COLUMNS, ROWS))
        out.write("# 't' maple, 'b' bottlebrush bush, 'g' grass clump (assets/test_plants, made by Blender's Sapling),\n")
        out.write("# '*' sunflower: %d / %d / %d / %d.\n" % (counts["t"], counts["b"], counts["g"], counts["*"]))
        out.write("%d %d\n" % (COLUMNS, ROWS))
        for row in grid:
            out.write("".join(row).rstrip() + "\n")
    print("%s: maples %d, bushes %d, grass %d, sunflowers %d" % (out_path, counts["t"], counts["b"], counts["g"],
                                                              counts["*"]))


if __name__ == "__main__":
    main()
