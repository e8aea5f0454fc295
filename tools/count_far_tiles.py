#!/usr/bin/env python3
"""Counts the far tiles the engine draws from 40 m outside a square field (the demo's "outside40"
view), per tile level, for a tiling: a model of FieldSimulation's tiles and ranges, to weigh tile
sizes without the engine (README, "Does another tile size meet it?").

A tile is counted when its range (FieldSimulation::get_tile_range: from its merge distance less its
reach to the next level's plus its reach, measured to the box's centre) holds the camera, or with
--box when its box reaches into the distances its level draws, and its box reaches into the view
(107 degrees across, Godot's 75-degree camera at 16:9). Usage:

    tools/count_far_tiles.py [--tile-chunks 4] [--floor 1.5] [--box] SIDE...
"""
import argparse
import math

CHUNK = 16.0  # metres, the default chunk size
MERGE = 200.0  # the default tile merge distance
HALF_VIEW = math.radians(53.5)


def tiles(side: float, tile_chunks: int) -> tuple[list[tuple[int, float, float, float, float]], int]:
    """(level, x0, z0, x1, z1) of every tile of a side × side field, and the top level."""
    out = []
    level, size = 0, tile_chunks * CHUNK
    while True:
        count = math.ceil(side / size)
        for i in range(count):
            for j in range(count):
                out.append((level, i * size, j * size, min((i + 1) * size, side), min((j + 1) * size, side)))
        if count == 1:
            return out, level
        level, size = level + 1, size * 2


def merge_distance(level: int, tile_chunks: int, floor: float) -> float:
    if level == 0:
        return 0.0
    return max(MERGE * 2 ** (level - 1), floor * tile_chunks * CHUNK * 2**level)


def in_view(camera: tuple[float, float], box: tuple[float, float, float, float]) -> bool:
    x0, z0, x1, z1 = box
    for a in range(9):
        for b in range(9):
            dx = x0 + (x1 - x0) * a / 8 - camera[0]
            dz = camera[1] - (z0 + (z1 - z0) * b / 8)
            if dz > 0 and abs(math.atan2(dx, dz)) < HALF_VIEW:
                return True
    return False


def count(side: float, tile_chunks: int, floor: float, by_box: bool) -> dict[int, int]:
    all_tiles, top = tiles(side, tile_chunks)
    camera = (side / 2, side + 40.0)
    drawn: dict[int, int] = {}
    for level, x0, z0, x1, z1 in all_tiles:
        if not in_view(camera, (x0, z0, x1, z1)):
            continue
        begin = merge_distance(level, tile_chunks, floor)
        end = merge_distance(level + 1, tile_chunks, floor) if level < top else math.inf
        if by_box:
            near = math.hypot(max(x0 - camera[0], 0, camera[0] - x1), max(z0 - camera[1], 0, camera[1] - z1))
            far = max(math.hypot(x - camera[0], z - camera[1]) for x in (x0, x1) for z in (z0, z1))
            shown = far >= begin and near < end
        else:
            reach = 0.5 * math.hypot(x1 - x0, z1 - z0)
            centre = math.hypot((x0 + x1) / 2 - camera[0], (z0 + z1) / 2 - camera[1])
            shown = (level == 0 or centre >= begin - reach) and centre <= end + reach
        if shown:
            drawn[level] = drawn.get(level, 0) + 1
    return drawn


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("sides", type=float, nargs="+", help="field sides in metres (1000: a million plants)")
    parser.add_argument("--tile-chunks", type=int, default=4, help="chunks along a level-0 tile's side")
    parser.add_argument("--floor", type=float, default=1.5, help="a merge distance's least multiple of the side")
    parser.add_argument("--box", action="store_true", help="show a tile by its box's distances, not its centre's")
    args = parser.parse_args()
    for side in args.sides:
        drawn = count(side, args.tile_chunks, args.floor, args.box)
        levels = ", ".join(f"level {level}: {n}" for level, n in sorted(drawn.items()))
        print(f"{side:.0f} m field: {sum(drawn.values())} tiles ({levels})")


if __name__ == "__main__":
    main()
