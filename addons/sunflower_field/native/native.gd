@tool
extends RefCounted
## The bridge to the native library: whether it loaded, new simulations, the facts it owns (bucket
## layout, counts, the plant's height in model units) and the core's rules for every value a user
## sets. The only script that names the native class, so every other script parses even where no
## library fits the platform; there, exactly one error says so and how to build one.

const CLASS: StringName = &"SunflowerSimulation"
## The native classes attached to a simulation: what it draws, and play's changes to its plants.
const DRAWING_CLASS: StringName = &"SunflowerDrawing"
const CHANGES_CLASS: StringName = &"SunflowerChanges"
## The native class of the core's parameter table (static methods only).
const PARAMETERS_CLASS: StringName = &"SunflowerParameters"
## The native class of placement by rules.
const PLACEMENT_CLASS: StringName = &"SunflowerPlacement"
## The native class of a map read and edited on its own.
const MAP_CLASS: StringName = &"SunflowerMap"
## The command that builds the libraries, for the missing-library error.
const BUILD_HINT: String = (
	"build it with 'scons platform=<linux|windows|macos> arch=<x86_64|arm64>' or 'tools/build.sh --all' "
	+ "from the addon's repository, or install a release zip that has it"
)

static var _reported: bool = false
static var _names: Dictionary = {}  # "Class.property" → its row, every row of the core's table


## Whether the native library is loaded (a build for this platform exists and loaded).
static func is_available() -> bool:
	return ClassDB.class_exists(CLASS)


## A new native simulation, or null (with the one missing-library error) when there is no library.
static func create_simulation() -> RefCounted:
	if not is_available():
		report_missing()
		return null
	return ClassDB.instantiate(CLASS) as RefCounted


## A new native object of [param native_class] (a class attached to a simulation, [constant
## DRAWING_CLASS] or [constant CHANGES_CLASS]) attached to [param simulation].
static func attach(native_class: StringName, simulation: RefCounted) -> RefCounted:
	var attached: RefCounted = ClassDB.instantiate(native_class) as RefCounted
	attached.attach(simulation)
	return attached


## A new native placement (rules to cells), or null (with the one missing-library error).
static func create_placement() -> RefCounted:
	if not is_available():
		report_missing()
		return null
	return ClassDB.instantiate(PLACEMENT_CLASS) as RefCounted


## A new native map (read, painted, resized and written without a simulation), or null (with the one
## missing-library error).
static func create_map() -> RefCounted:
	if not is_available():
		report_missing()
		return null
	return ClassDB.instantiate(MAP_CLASS) as RefCounted


## Prints, once per run, that no native library fits this platform and how to make one.
static func report_missing() -> void:
	if _reported:
		return
	_reported = true
	push_error("Sunflower Field: " + missing_message())


## The missing-library message, also the node's configuration warning.
static func missing_message() -> String:
	return (
		"no native library for %s %s in addons/sunflower_field/bin/, so fields draw nothing; %s."
		% [OS.get_name(), Engine.get_architecture_name(), BUILD_HINT]
	)


## An integer constant of the native classes ([code]BUCKET_COUNT[/code], [code]MAX_SPECIES[/code]…,
## each defined by one of them); 0 without the library (when nothing is drawn anyway).
static func constant(name: StringName) -> int:
	if not is_available():
		return 0
	for native_class: StringName in [CLASS, DRAWING_CLASS, PARAMETERS_CLASS]:
		if ClassDB.class_has_integer_constant(native_class, name):
			return ClassDB.class_get_integer_constant(native_class, name)
	push_error("Sunflower Field: no native class has the constant %s" % name)
	return 0


## The bucket of a mesh level's part in the native buckets ([code]level × parts + part[/code] there).
static func mesh_bucket(level: int, part: int) -> int:
	return ClassDB.class_call_static(DRAWING_CLASS, &"mesh_bucket", level, part) if is_available() else -1


## The value the core accepts for [param property] (e.g. [code]"SunflowerWind.power"[/code]) when
## [param value] is asked for while [param current] is set; warns, naming the property, when that
## differs from [param value]. The core's table is the only place the limits are written.
static func accept(property: String, value: float, current: float) -> float:
	var judged: Array = judge(property, value, current)
	if not judged[1].is_empty():
		push_warning("%s: %s" % [property, judged[1]])
	return judged[0]


## The core's table on [param value] for [param property] while [param current] is set: the value
## it takes, and why that differs from [param value] ("" when it does not, or without the library).
static func judge(property: String, value: float, current: float) -> Array:
	if not is_available():
		return [value, ""]
	var used: float = ClassDB.class_call_static(PARAMETERS_CLASS, &"sanitize_parameter", property, value, current)
	if used == value:  # (NaN equals nothing: explained)
		return [used, ""]
	return [used, ClassDB.class_call_static(PARAMETERS_CLASS, &"explain_parameter", property, value, used)]


## [method accept] for integer properties.
static func accept_int(property: String, value: int, current: int) -> int:
	return int(accept(property, value, current))


## The core's default for [param property] (tests compare the inspector's defaults with it).
static func default_of(property: String) -> float:
	return ClassDB.class_call_static(PARAMETERS_CLASS, &"get_parameter_default", property)


## [param hint_string], a range hint of [param property] ([code]"min,max,step[,flags]"[/code] of its
## [code]@export_range[/code]), with the limits of the core's table: its min (or [code]or_less[/code]
## when it has none), and its max (or [code]or_greater[/code] when it has none). An annotation with
## [code]or_greater[/code] below the table's max keeps its slider's span: the setter holds a larger
## value to the table's max, with a warning. Degrees for [code]radians_as_degrees[/code]. The
## annotation gives the step, the suffix and a slider's span; the table alone gives the limits.
## Unchanged without the library.
static func range_hint(property: String, hint_string: String) -> String:
	if not is_available() or not _parameters().has(property):
		return hint_string
	var parts: PackedStringArray = hint_string.split(",")
	var flags: PackedStringArray = parts.slice(3)
	var degrees: bool = flags.has("radians_as_degrees") or flags.has("radians")
	var unbounded: float = 1e30  # the table's largest finite float stands for "no limit"
	for side: int in 2:
		var limit: float = ClassDB.class_call_static(PARAMETERS_CLASS, &"get_parameter_limit", property, side == 1)
		var flag: String = "or_less" if side == 0 else "or_greater"
		var shown: float = rad_to_deg(limit) if degrees else limit
		if side == 1 and flags.has(flag) and float(parts[1]) < shown:
			continue  # a slider's span below the table's max
		flags.erase(flag)
		if absf(limit) >= unbounded:
			flags.append(flag)
		else:
			parts[side] = String.num(shown, 4)  # (4 places: the table's float π is 180.000005°)
	return ",".join(parts.slice(0, 3) + flags)


static func _parameters() -> Dictionary:
	if _names.is_empty() and is_available():
		var names: PackedStringArray = parameter_names()
		for row: int in names.size():
			_names[names[row]] = row
	return _names


## The row of [param property] ([code]"Class.property"[/code]) in the core's table, or -1.
static func parameter_row(property: String) -> int:
	return _parameters().get(property, -1)


## What a change of [param property] costs by the core's table: 0 nothing more than the value, 1 a
## rebuild of the field (the layout depends on it); -1 for a property the table does not have.
static func parameter_cost(property: String) -> int:
	return ClassDB.class_call_static(PARAMETERS_CLASS, &"get_parameter_cost", property) if is_available() else -1


## Every property the core's table knows, as [code]"Class.property"[/code].
static func parameter_names() -> PackedStringArray:
	return String(ClassDB.class_call_static(PARAMETERS_CLASS, &"get_parameter_names")).split(",")


## Parses a map's [param text] without laying it out: an empty string when it is valid, else
## [code]"source:line:column: message"[/code]. [param symbols] are the legend's (objects and plant
## types alike); with [param any_symbol] every printable symbol is accepted (the importer's check).
static func check_map(
	text: PackedByteArray, source: String, symbols: String, any_symbol: bool, max_plants: int
) -> String:
	if not is_available():
		return missing_message()
	return ClassDB.class_call_static(MAP_CLASS, &"check", text, source, symbols, "", max_plants, any_symbol)


## The columns, rows and sunflowers of a valid map (see [method check_map]); empty otherwise.
static func map_figures(text: PackedByteArray, max_plants: int) -> PackedInt32Array:
	return (
		ClassDB.class_call_static(MAP_CLASS, &"get_figures", text, max_plants) if is_available() else PackedInt32Array()
	)


## What is wrong with these LOD switch distances, or an empty string.
static func check_lod_distances(distances: PackedFloat32Array) -> String:
	return ClassDB.class_call_static(PARAMETERS_CLASS, &"check_lod_distances", distances) if is_available() else ""


## The wind direction the core uses for [param direction] (a zero vector means +x).
static func sanitize_wind_direction(direction: Vector2) -> Vector2:
	return (
		ClassDB.class_call_static(PARAMETERS_CLASS, &"sanitize_wind_direction", direction)
		if is_available()
		else direction
	)


## Transforms from the native instance layout: 12 floats each, the 3 × 4 matrix [basis | origin]
## row by row (the RenderingServer's MultiMesh layout).
static func unpack_transforms(flat: PackedFloat32Array) -> Array[Transform3D]:
	var transforms: Array[Transform3D] = []
	for o: int in range(0, flat.size() - 11, 12):
		transforms.append(
			Transform3D(
				Vector3(flat[o], flat[o + 4], flat[o + 8]),
				Vector3(flat[o + 1], flat[o + 5], flat[o + 9]),
				Vector3(flat[o + 2], flat[o + 6], flat[o + 10]),
				Vector3(flat[o + 3], flat[o + 7], flat[o + 11])
			)
		)
	return transforms
