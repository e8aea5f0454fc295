#!/usr/bin/env python3
"""Counts the far tiles the engine draws from 40 m outside a square field (the demo's "outside40"
view), per tile level, for a tiling: a model of FieldSimulation's tiles and the nodes' ranges, to
weigh tile sizes without the engine (docs/performance.md, the one miss).

By default the model is the addon's cut: a tile is drawn when the camera's distance to
its box's centre reaches its range's begin (FieldSimulation::get_tile_shown_from: its merge distance
plus its reach) and that of no tile above it does (the nodes' visibility parents). With --overlap it
is an earlier rule: each tile drawn from its merge distance less its reach to the next
level's plus its reach, two levels overlapping around each merge distance. Either way a tile must
also reach into the view (107 degrees across, Godot's 75-degree camera at 16:9). Prints the tiles
drawn and the instances they draw (square metres of plants times the density of the lowest level
its plants may be given: FieldSimulation::get_tile_visible_count), whose vertex shader runs
whether the level draws them or not. Usage:

    tools/count_far_tiles.py [--tile-chunks 8] [--floor 0] [--overlap] SIDE...
"""
import argparse
import math

CHUNK = 16.0  # metres, the default chunk size
MERGE = 200.0  # the default tile merge distance
HALF_VIEW = math.radians(53.5)

Tile = tuple[int, float, float, float, float]  # level, x0, z0, x1, z1


def tiles(side: float, tile_chunks: int) -> list[Tile]:
    """Every tile of a side × side field, level by level until one covers it."""
    out = []
    level, size = 0, tile_chunks * CHUNK
    while True:
        count = math.ceil(side / size)
        for i in range(count):
            for j in range(count):
                out.append((level, i * size, j * size, min((i + 1) * size, side), min((j + 1) * size, side)))
        if count == 1:
            return out
        level, size = level + 1, size * 2


def merge_distance(level: int, tile_chunks: int, floor: float) -> float:
    if level == 0:
        return 0.0
    return max(MERGE * 2 ** (level - 1), floor * tile_chunks * CHUNK * 2**level)


def in_view(camera: tuple[float, float], tile: Tile) -> bool:
    _, x0, z0, x1, z1 = tile
    for a in range(9):
        for b in range(9):
            dx = x0 + (x1 - x0) * a / 8 - camera[0]
            dz = camera[1] - (z0 + (z1 - z0) * b / 8)
            if dz > 0 and abs(math.atan2(dx, dz)) < HALF_VIEW:
                return True
    return False


def count(side: float, tile_chunks: int, floor: float, overlap: bool) -> tuple[dict[int, int], float]:
    all_tiles = tiles(side, tile_chunks)
    top = all_tiles[-1][0]
    camera = (side / 2, side + 40.0)

    def centre(tile: Tile) -> float:
        return math.hypot((tile[1] + tile[3]) / 2 - camera[0], (tile[2] + tile[4]) / 2 - camera[1])

    def reach(tile: Tile) -> float:
        return 0.5 * math.hypot(tile[3] - tile[1], tile[4] - tile[2])

    def parent(tile: Tile) -> Tile | None:
        level, x0, z0 = tile[0], tile[1], tile[2]
        size = 2 * tile_chunks * CHUNK * 2**level
        for other in all_tiles:
            if other[0] == level + 1 and other[1] <= x0 < other[1] + size and other[2] <= z0 < other[2] + size:
                return other
        return None

    def in_range(tile: Tile) -> bool:
        return tile[0] == 0 or centre(tile) >= merge_distance(tile[0], tile_chunks, floor) + reach(tile)

    drawn: dict[int, int] = {}
    instances = 0.0
    for tile in all_tiles:
        if not in_view(camera, tile):
            continue
        level = tile[0]
        if overlap:
            begin = merge_distance(level, tile_chunks, floor) - reach(tile)
            end = merge_distance(level + 1, tile_chunks, floor) + reach(tile) if level < top else math.inf
            shown = (level == 0 or centre(tile) >= begin) and centre(tile) <= end
        else:
            shown = in_range(tile)
            above = parent(tile)
            while shown and above is not None:
                shown = not in_range(above)
                above = parent(above)
        if shown:
            drawn[level] = drawn.get(level, 0) + 1
            nearest = math.hypot(max(tile[1] - camera[0], 0, camera[0] - tile[3]), max(tile[2] - camera[1], 0, camera[1] - tile[4]))
            kept = level
            while kept < top and nearest >= merge_distance(kept + 1, tile_chunks, floor):
                kept += 1
            instances += (tile[3] - tile[1]) * (tile[4] - tile[2]) * 4.0**-kept
    return drawn, instances


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("sides", type=float, nargs="+", help="field sides in metres (1000: a million plants)")
    parser.add_argument("--tile-chunks", type=int, default=8, help="chunks along a level-0 tile's side")
    parser.add_argument("--floor", type=float, default=0.0, help="a merge distance's least multiple of the side")
    parser.add_argument("--overlap", action="store_true", help="sessions 17-26's overlapping ranges")
    args = parser.parse_args()
    for side in args.sides:
        drawn, instances = count(side, args.tile_chunks, args.floor, args.overlap)
        levels = ", ".join(f"level {level}: {n}" for level, n in sorted(drawn.items()))
        print(f"{side:.0f} m field: {sum(drawn.values())} tiles ({levels}), {instances / 1e3:.0f} k m² of instances")


if __name__ == "__main__":
    main()
