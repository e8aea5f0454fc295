@tool
extends RefCounted
## What the editor and saved scenes see of a [SunflowerField] beyond its properties: which settings
## the inspector shows, what they revert to and their range hints (the core's table), the scene
## tree's configuration warnings, and the names scenes saved by older versions still carry. The
## node's virtual methods ([code]_validate_property[/code], [code]_get_configuration_warnings[/code],
## [code]_set[/code] …) call these.

const Native: GDScript = preload("../native/native.gd")
const FieldGround: GDScript = preload("field_ground.gd")
const PartMeshes: GDScript = preload("../plant/part_meshes.gd")
const ProjectKnobs: GDScript = preload("field_project_settings.gd")

## The settings of one ground source, by the source they belong to (shown only for it).
const GROUND_SETTINGS: Dictionary = {
	&"ground_collision_mask": FieldGround.Source.COLLIDERS,
	&"ground_ray_above": FieldGround.Source.COLLIDERS,
	&"ground_ray_below": FieldGround.Source.COLLIDERS,
	&"height_map": FieldGround.Source.HEIGHT_MAP,
	&"height_map_rect": FieldGround.Source.HEIGHT_MAP,
	&"height_range": FieldGround.Source.HEIGHT_MAP,
}
## The node's properties that edit its wind (node property → wind property): stored there, so
## neither in the scene a second time nor in the inspector (the wind shows them).
const WIND_PROPERTIES: Dictionary = {
	&"wind_power": &"power", &"wind_direction": &"direction", &"wind_increment": &"increment"
}


## One place for each setting in the inspector: the wind's in the wind, each ground's own settings
## only while it is the ground (they stay stored); range hints from the core's table.
static func validate_property(field: Node3D, property: Dictionary, own_wind: SunflowerWind) -> void:
	var name: StringName = property["name"]
	if WIND_PROPERTIES.has(name) or (name == &"wind" and wind_is_default(field, own_wind)):
		property["usage"] &= ~PROPERTY_USAGE_STORAGE
	if WIND_PROPERTIES.has(name) or GROUND_SETTINGS.get(name, field.ground_source) != field.ground_source:
		property["usage"] &= ~PROPERTY_USAGE_EDITOR
	if property["hint"] == PROPERTY_HINT_RANGE:
		var row: String = (
			"SunflowerWind." + WIND_PROPERTIES[name] if WIND_PROPERTIES.has(name) else "SunflowerField." + name
		)
		property["hint_string"] = Native.range_hint(row, property["hint_string"])


## The wind settings revert to a new wind's; [code]wind[/code], while it is [param own_wind] (the one
## the node made itself) unchanged, reverts to itself (else the inspector, comparing it with no
## default, shows "Wind (1 change)").
static func can_revert(field: Node3D, property: StringName, own_wind: SunflowerWind) -> bool:
	return WIND_PROPERTIES.has(property) or (property == &"wind" and wind_is_default(field, own_wind))


## What [param property] reverts to (see [method can_revert]).
static func revert_value(field: Node3D, property: StringName, own_wind: SunflowerWind) -> Variant:
	if property == &"wind":
		return field.wind if wind_is_default(field, own_wind) else null
	return SunflowerWind.new().get(WIND_PROPERTIES[property]) if WIND_PROPERTIES.has(property) else null


## Whether the field's wind is [param own_wind], the one it made itself, still at its defaults (not
## saved then).
static func wind_is_default(field: Node3D, own_wind: SunflowerWind) -> bool:
	return field.wind == own_wind and field.wind.is_default()


## What the scene tree's warning sign says of [param field]: no library, no map or one that cannot
## be used, no observer, a scaled node, plant types whose parts do not stack.
static func configuration_warnings(field: Node3D, last_error: String, observer: Node3D) -> PackedStringArray:
	var warnings: PackedStringArray = []
	if not Native.is_available():
		warnings.append(Native.missing_message())
	if field.map == null:
		warnings.append("No map: import a .field file and assign it to 'map', or call load_map_file().")
	elif last_error != "":
		warnings.append("The map cannot be used: " + last_error)
	if not field.observer.is_empty() and not (field.get_node_or_null(field.observer) is Node3D):
		warnings.append("'observer' does not point to a Node3D; the active camera is used instead.")
	if field.is_inside_tree() and not Engine.is_editor_hint() and observer == null:
		warnings.append("No observer: set 'observer' or add a current Camera3D; the field keeps its last LOD.")
	if not field.scale.is_equal_approx(Vector3.ONE):
		warnings.append("Keep the field's scale at 1; size it with 'cell_size' and 'plant_height'.")
	for grown: SunflowerPlant in field.get_plant_types():
		warnings.append_array(grown.stacking_problems())
		if grown.stump_height > 0.0 and grown.drawn_whole():
			warnings.append(
				(
					(
						"SunflowerPlant '%s': stump_height is set, but the plant is drawn whole (no bottom part of its "
						+ "own): its cut plants leave no stump."
					)
					% grown.name
				)
			)
	return warnings


## A property of an older version's scene: its part meshes, saved as
## [code]"part_meshes/mesh_N/part"[/code] before plant types set them (the plant's mesh now), or
## null.
static func former_value(field: Node3D, property: StringName) -> Variant:
	var slot: Vector2i = PartMeshes.slot_of(property)
	return field.get_plant_types()[0].get_part_mesh(slot.x, slot.y) if slot.x >= 0 else null


## Takes a property of an older version's scene: a part mesh (set on the plant), or a setting that is
## a project setting now (warned about, not used). False for a property that never was one.
static func set_former(field: Node3D, property: StringName, value: Variant) -> bool:
	if ProjectKnobs.FORMER_PROPERTIES.has(property):
		push_warning(
			(
				"SunflowerField.%s is a project setting now (%s, in Project Settings): this field's %s is not used"
				% [property, ProjectKnobs.FORMER_PROPERTIES[property], value]
			)
		)
		return true
	var slot: Vector2i = PartMeshes.slot_of(property)
	if slot.x < 0:
		return false
	if value != null and not (value is Mesh):
		push_warning("SunflowerField.%s: %s is not a Mesh; the slot is left empty" % [property, value])
		value = null
	field.set_part_mesh(slot.x, slot.y, value as Mesh)
	return true
