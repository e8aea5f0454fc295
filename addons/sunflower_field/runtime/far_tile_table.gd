@tool
extends RefCounted
## The far tiles of one native simulation as the nodes need them (where each lies, what it draws,
## its box, level, parent and distances), read from the library in three calls when a field's tile
## nodes are made, instead of several calls per tile.

const Native: GDScript = preload("../native/native.gd")
const NativeField: GDScript = preload("../native/native_field.gd")

## Tiles in the field.
var count: int = 0
var _ids: PackedInt64Array = []  # Native TILE_IDS a tile: key, signature, species, level, parent
var _places: PackedFloat32Array = []  # TILE_PLACES a tile: box position, box size, begin, shown from
var _merge_rule: PackedFloat32Array = []  # top level, where level 1 begins, the fade's octave share
var _id_stride: int = 0
var _place_stride: int = 0


## The table of [param simulation]'s tiles as they are now.
func _init(simulation: NativeField) -> void:
	_ids = simulation.get_tile_ids()
	_places = simulation.get_tile_places()
	_merge_rule = simulation.get_tile_merge_rule()
	_id_stride = Native.constant(&"TILE_IDS")
	_place_stride = Native.constant(&"TILE_PLACES")
	count = _ids.size() / _id_stride if _id_stride > 0 else 0


## Where [param tile] lies: equal in any layout of the map's size.
func key(tile: int) -> int:
	return _ids[tile * _id_stride]


## What [param tile] draws: two tiles with equal keys and signatures draw the same.
func signature(tile: int) -> int:
	return _ids[tile * _id_stride + 1]


## The plant type (species) of [param tile]'s plants.
func species(tile: int) -> int:
	return _ids[tile * _id_stride + 2]


## [param tile]'s merge level (0: a tile of chunks; each level above covers 2 × 2 of the one below).
func level(tile: int) -> int:
	return _ids[tile * _id_stride + 3]


## The tile of the next level covering [param tile], or -1.
func parent(tile: int) -> int:
	return _ids[tile * _id_stride + 4]


## The box that holds [param tile]'s plants.
func aabb(tile: int) -> AABB:
	var i: int = tile * _place_stride
	return AABB(
		Vector3(_places[i], _places[i + 1], _places[i + 2]), Vector3(_places[i + 3], _places[i + 4], _places[i + 5])
	)


## The distance from the observer at which a far plant's place turns to [param tile]'s level.
func begin(tile: int) -> float:
	return _places[tile * _place_stride + 6]


## The camera distance (to the box's centre) from which [param tile] may be drawn.
func shown_from(tile: int) -> float:
	return _places[tile * _place_stride + 7]


## The impostor shader's [code]tile_merge[/code] for [param tile]: its level, the top level, where
## level 1 begins, the fade's share of an octave.
func merge(tile: int) -> Vector4:
	return Vector4(level(tile), _merge_rule[0], _merge_rule[1], _merge_rule[2])
