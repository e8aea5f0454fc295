@tool
extends RefCounted
## Part addresses: a mesh level (0–2) and a part (0–2: bottom, middle, head), their check, and the
## [code]part_meshes/mesh_N/part[/code] property names scenes saved before plant types used.

## The parts and the mesh levels, as the library counts them (PART_COUNT, MESH_LEVEL_COUNT: a test
## compares them; these are constants so that plants load without the library).
const PART_NAMES: PackedStringArray = ["bottom", "middle", "head"]
const LEVELS: int = 3
const PREFIX: String = "part_meshes/mesh_"


## Whether [param level] / [param part] names a part; if not, an error naming [param function].
static func check(level: int, part: int, function: String) -> bool:
	if level >= 0 and level < LEVELS and part >= 0 and part < PART_NAMES.size():
		return true
	push_error("SunflowerField.%s: lod %d / part %d is out of range (0–2 each)" % [function, level, part])
	return false


## The (level, part) of a [code]part_meshes/mesh_N/part[/code] property, or (-1, -1).
static func slot_of(property: StringName) -> Vector2i:
	var text: String = property
	if not text.begins_with(PREFIX):
		return Vector2i(-1, -1)
	var pieces: PackedStringArray = text.trim_prefix(PREFIX).split("/")
	if pieces.size() != 2 or not pieces[0].is_valid_int():
		return Vector2i(-1, -1)
	var level: int = pieces[0].to_int() - 1
	var part: int = PART_NAMES.find(pieces[1])
	if level < 0 or level >= LEVELS or part < 0:
		return Vector2i(-1, -1)
	return Vector2i(level, part)
