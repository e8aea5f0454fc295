@tool
extends RefCounted
## The plant's part meshes: the mesh chosen for each mesh level's bottom, middle and head (none: the
## default model shipped with the addon), and their inspector properties
## [code]part_meshes/mesh_N/bottom|middle|head[/code].

const Native: GDScript = preload("native.gd")
const FieldNodes: GDScript = preload("field_nodes.gd")
const DEFAULT_MESHES: String = "res://addons/sunflower_field/meshes/sunflower_lod%d_%s.res"
const PREFIX: String = "part_meshes/mesh_"

## Chosen meshes by [code]level × parts + part[/code]; null entries use the default models.
var _chosen: Array[Mesh] = []
var _parts: int = FieldNodes.PART_NAMES.size()


func _init() -> void:
	_chosen.resize(Native.constant(&"MESH_LEVEL_COUNT") * _parts)


## Whether [param level] / [param part] names a part; if not, an error naming [param function].
func check(level: int, part: int, function: String) -> bool:
	if level >= 0 and part >= 0 and part < _parts and level * _parts + part < _chosen.size():
		return true
	push_error("SunflowerField.%s: lod %d / part %d is out of range (0–2 each)" % [function, level, part])
	return false


## Chooses [param mesh] for a part (null: the default model).
func choose(level: int, part: int, mesh: Mesh) -> void:
	_chosen[level * _parts + part] = mesh


## The mesh drawn for a part: the chosen one, else the default model.
func get_mesh(level: int, part: int) -> Mesh:
	var mesh: Mesh = _chosen[level * _parts + part]
	return mesh if mesh else load(DEFAULT_MESHES % [level + 1, FieldNodes.PART_NAMES[part]]) as Mesh


## Every part's mesh as drawn, by [code]level × parts + part[/code].
func get_all() -> Array[Mesh]:
	var meshes: Array[Mesh] = []
	for slot: int in _chosen.size():
		meshes.append(get_mesh(slot / _parts, slot % _parts))
	return meshes


## The inspector properties, one per part, in a "Part meshes" group.
func list_properties() -> Array[Dictionary]:
	var properties: Array[Dictionary] = [
		{"name": "Part meshes", "type": TYPE_NIL, "usage": PROPERTY_USAGE_GROUP, "hint_string": "part_meshes/"}
	]
	for slot: int in _chosen.size():
		var property: Dictionary = {
			"name": PREFIX + "%d/%s" % [slot / _parts + 1, FieldNodes.PART_NAMES[slot % _parts]],
			"type": TYPE_OBJECT,
			"hint": PROPERTY_HINT_RESOURCE_TYPE,
			"hint_string": "Mesh",
			"usage": PROPERTY_USAGE_DEFAULT,
		}
		properties.append(property)
	return properties


## The slot of a [code]part_meshes/…[/code] property, or -1 for any other name.
func slot_of(property: StringName) -> int:
	var text: String = property
	if not text.begins_with(PREFIX):
		return -1
	var pieces: PackedStringArray = text.trim_prefix(PREFIX).split("/")
	if pieces.size() != 2 or not pieces[0].is_valid_int():
		return -1
	var level: int = pieces[0].to_int() - 1
	var part: int = FieldNodes.PART_NAMES.find(pieces[1])
	if level < 0 or part < 0 or level * _parts + part >= _chosen.size():
		return -1
	return level * _parts + part


## The mesh chosen in a slot (null: the default model).
func get_chosen(slot: int) -> Mesh:
	return _chosen[slot]


## How many parts there are per mesh level.
func get_parts_per_level() -> int:
	return _parts
