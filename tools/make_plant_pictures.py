#!/usr/bin/env python3
"""Puts docs/plants.md's pictures of the Sapling test plants together from the pictures the engine
tests write (tests/artifacts), so that each is the current one:

  docs/test_plant_fields.jpg  each plant's field from head height, from 40 m outside and from 25 m up
                              at 45°, beside the 45° view with every plant at mesh 1
  docs/test_plant_lone.png    each plant alone at mesh 1 beside its impostor, close up, where
                              impostors begin and twice as far, pixels enlarged

Run the tests first, then this (with the project's Python, which has Pillow):
  tools/test.sh --suite engine --filter 'test_scene_plant.test_each_test_plants_lone*'
  tools/test.sh --suite engine --filter 'test_scene_plant.test_a_field_of_each*'
  .cache/venv/bin/python tools/make_plant_pictures.py
"""
import pathlib
import sys

from PIL import Image, ImageDraw

ROOT = pathlib.Path(__file__).resolve().parent.parent
ARTIFACTS = ROOT / "tests" / "artifacts"
DOCS = ROOT / "docs"
PLANTS = ["maple_tree", "bottlebrush_bush", "grass_clump"]
FIELD_COLUMNS = [
    ("inside_auto", "head height"),
    ("outside40_auto", "40 m outside"),
    ("above45_auto", "25 m up at 45°"),
    ("above45_mesh1", "45°, every plant at mesh 1"),
]
FIELD_TILE = (320, 180)
LABEL_HEIGHT = 20
LONE_TILE = 150  # pixels a side of one enlarged plant


def artifact(name):
    path = ARTIFACTS / name
    if not path.exists():
        sys.exit("make_plant_pictures: %s is missing; run the tests this script's help names first" % path)
    return Image.open(path).convert("RGB")


def fields():
    width = FIELD_TILE[0] * len(FIELD_COLUMNS)
    sheet = Image.new("RGB", (width, LABEL_HEIGHT + FIELD_TILE[1] * len(PLANTS)), "white")
    draw = ImageDraw.Draw(sheet)
    for column, (_, label) in enumerate(FIELD_COLUMNS):
        draw.text((column * FIELD_TILE[0] + 6, 4), label, fill="black")
    for row, plant in enumerate(PLANTS):
        for column, (view, _) in enumerate(FIELD_COLUMNS):
            picture = artifact("scene_field_%s_%s.png" % (plant, view)).resize(FIELD_TILE, Image.LANCZOS)
            sheet.paste(picture, (column * FIELD_TILE[0], LABEL_HEIGHT + row * FIELD_TILE[1]))
    sheet.save(DOCS / "test_plant_fields.jpg", quality=88)


def lone_pictures(plant):
    """The plant's four lone pictures (mesh 1 and impostor, near and far), each cropped to the square
    about what either draws and enlarged with whole pixels."""
    found = sorted(ARTIFACTS.glob("lone_cover_%s_*m_mesh1.png" % plant), key=lambda p: int(p.name.split("_")[-2][:-1]))
    if not found:
        sys.exit("make_plant_pictures: no lone pictures of %s in %s" % (plant, ARTIFACTS))
    tiles = []
    for mesh_path in found:
        distance = mesh_path.name.split("_")[-2]
        pair = [artifact(mesh_path.name), artifact(mesh_path.name.replace("_mesh1.png", "_impostor.png"))]
        box = None
        for picture in pair:
            used = picture.convert("L").point(lambda v: 255 if v > 4 else 0).getbbox()
            if used:
                box = used if box is None else (min(box[0], used[0]), min(box[1], used[1]), max(box[2], used[2]), max(box[3], used[3]))
        if box is None:
            sys.exit("make_plant_pictures: %s draws nothing" % mesh_path.name)
        side = max(box[2] - box[0], box[3] - box[1]) + 4
        centre = ((box[0] + box[2]) // 2, (box[1] + box[3]) // 2)
        square = (centre[0] - side // 2, centre[1] - side // 2, centre[0] - side // 2 + side, centre[1] - side // 2 + side)
        for way, picture in zip(("mesh 1", "impostor"), pair):
            tiles.append(("%s %s" % (distance, way), picture.crop(square).resize((LONE_TILE, LONE_TILE), Image.NEAREST)))
    return tiles


def lone():
    rows = [lone_pictures(plant) for plant in PLANTS]
    columns = max(len(tiles) for tiles in rows)
    sheet = Image.new("RGB", (LONE_TILE * columns, (LABEL_HEIGHT + LONE_TILE) * len(PLANTS)), "white")
    draw = ImageDraw.Draw(sheet)
    for row, (plant, tiles) in enumerate(zip(PLANTS, rows)):
        top = row * (LABEL_HEIGHT + LONE_TILE)
        for column, (label, tile) in enumerate(tiles):
            draw.text((column * LONE_TILE + 4, top + 4), "%s, %s" % (plant.split("_")[0], label), fill="black")
            sheet.paste(tile, (column * LONE_TILE, top + LABEL_HEIGHT))
    sheet.save(DOCS / "test_plant_lone.png")


if __name__ == "__main__":
    fields()
    lone()
    print("make_plant_pictures: wrote docs/test_plant_fields.jpg and docs/test_plant_lone.png")
