@tool
extends RefCounted
## A field's settings by their rows of the core's parameter table ([code]parameters.h[/code]): a
## property is a row when the table has one named after its class and itself
## ([code]"SunflowerWind.power"[/code] is a [SunflowerWind]'s [code]power[/code]). Read from the
## node, its wind and its plant types when asked, never kept: what a build gives its new simulation
## and what a change sends to the simulation drawn. The core routes each row to the unit that owns
## it and says what a change costs; rows no unit of the core owns (drawing, ground rays, budgets) it
## ignores, and the node applies them itself. A new float the core uses needs its table row, an
## export of the same name and the unit that uses it; nothing here (CONTRIBUTING.md shows one).

const Native: GDScript = preload("../native/native.gd")
const NativeField: GDScript = preload("../native/native_field.gd")

## What a change costs (the table's [code]ParameterSpec::Cost[/code]): taken at the next update.
const FREE: int = 0
## What a change costs: the layout depends on it, so the field is built anew.
const REBUILD: int = 1

## The field's rows and its wind's (row name → value).
var field_rows: Dictionary = {}
## Each plant type's rows (species 0: the node's plant, then the legend's).
var plant_rows: Array[Dictionary] = []


## The settings of [param field] (a SunflowerField), its wind and [param plants] (a SunflowerPlant
## per species) as they are now.
static func of(field: Node3D, plants: Array) -> RefCounted:
	var settings: RefCounted = new()
	settings.field_rows = rows_of(field, "SunflowerField")
	settings.field_rows.merge(rows_of(field.wind, "SunflowerWind"))
	for species_plant: Resource in plants:
		settings.plant_rows.append(rows_of(species_plant, "SunflowerPlant"))
	return settings


## The rows [param object] holds as class [param table_class] of the table, by their names. An object
## whose value for the core differs from the property's (a plant's lengths without its empty slots)
## says so in [code]_row_value(property, value)[/code].
static func rows_of(object: Object, table_class: String) -> Dictionary:
	var rows: Dictionary = {}
	if object == null:
		return rows
	var adjusts: bool = object.has_method(&"_row_value")
	for property: Dictionary in object.get_property_list():
		if not property["usage"] & PROPERTY_USAGE_SCRIPT_VARIABLE:
			continue
		var row: String = table_class + "." + property["name"]
		if Native.parameter_row(row) >= 0:
			var value: Variant = object.get(property["name"])
			rows[row] = object.call(&"_row_value", property["name"], value) if adjusts else value
	return rows


## Sends [param rows] to [param simulation] in one call, a plant type's as [param species]'s; returns
## what the change costs ([constant FREE] or [constant REBUILD]: the rows that need a rebuild were
## not applied), or -1 when the simulation refused them (an error says why).
static func send(simulation: NativeField, rows: Dictionary, species: int = 0) -> int:
	var indices: PackedInt32Array = []
	var values: PackedFloat32Array = []
	for row: String in rows:
		indices.append(Native.parameter_row(row))
		var value: Variant = rows[row]
		match typeof(value):
			TYPE_VECTOR2:
				values.append_array([value.x, value.y])
			TYPE_VECTOR3:
				values.append_array([value.x, value.y, value.z])
			TYPE_PACKED_FLOAT32_ARRAY:
				values.append_array(value)
			_:
				values.append(float(value))
	return simulation.set_settings(species, indices, values)


## Gives [param simulation] every row: the field's and its wind's, then each plant type's. Returns the
## largest cost.
func apply_to(simulation: NativeField) -> int:
	var cost: int = send(simulation, field_rows)
	for species: int in plant_rows.size():
		cost = maxi(cost, send(simulation, plant_rows[species], species))
	return cost
