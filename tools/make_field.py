#!/usr/bin/env python3
"""Writes a sunflower field map (fields/FORMAT.md) of any size.

    tools/make_field.py COLUMNS ROWS OUT [--seed N] [--paths EVERY] [--clearings N]

A field of '*' crossed by north-south and east-west paths every EVERY cells (0: none), with N round
clearings placed from the seed. Deterministic: the same arguments write the same file.
"""
import argparse
import random


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("columns", type=int)
    parser.add_argument("rows", type=int)
    parser.add_argument("out")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--paths", type=int, default=0, help="a 2-cell path every this many cells")
    parser.add_argument("--clearings", type=int, default=0)
    args = parser.parse_args()
    if args.columns <= 0 or args.rows <= 0:
        parser.error("COLUMNS and ROWS must be positive")
    rng = random.Random(args.seed)
    clearings = [(rng.randrange(args.columns), rng.randrange(args.rows), rng.uniform(3, 12) ** 2)
                 for _ in range(args.clearings)]
    plants = 0
    with open(args.out, "w", encoding="utf-8", newline="\n") as out:
        out.write(f"# {args.columns} x {args.rows} cells, written by tools/make_field.py "
                  f"(seed {args.seed}, paths {args.paths}, clearings {args.clearings})\n")
        out.write(f"{args.columns} {args.rows}\n")
        for r in range(args.rows):
            row = bytearray(b"*" * args.columns)
            if args.paths and r % args.paths in (0, 1):
                row = bytearray(b" " * args.columns)
            elif args.paths:
                for c in range(0, args.columns, args.paths):
                    row[c:c + 2] = b"  "
            for cx, cy, radius_sq in clearings:
                if (r - cy) ** 2 < radius_sq:
                    half = int((radius_sq - (r - cy) ** 2) ** 0.5)
                    lo, hi = max(0, cx - half), min(args.columns, cx + half + 1)
                    row[lo:hi] = b"." * (hi - lo)
            plants += row.count(b"*")
            out.write(row.decode("ascii").rstrip() + "\n")
    print(f"{args.out}: {args.columns} x {args.rows}, {plants} sunflowers")


if __name__ == "__main__":
    main()
