extends TestCase
## The addon loads: the native class, the node, the resources and the imported demo map.

const ProjectKnobs: GDScript = preload("res://addons/sunflower_field/runtime/field_project_settings.gd")
const FieldFace: GDScript = preload("res://addons/sunflower_field/runtime/field_face.gd")
const NATIVE_CLASSES: PackedStringArray = [
	"SunflowerSimulation",
	"SunflowerDrawing",
	"SunflowerChanges",
	"SunflowerParameters",
	"SunflowerMap",
	"SunflowerPlacement"
]


func test_native_class_is_registered() -> void:
	check(ClassDB.class_exists("SunflowerSimulation"), "SunflowerSimulation is not registered")
	check(ClassDB.is_parent_class("SunflowerSimulation", "RefCounted"), "SunflowerSimulation is not a RefCounted")
	check_eq(SunflowerDrawing.BUCKET_COUNT, 10, "bucket constant")


## The native classes' docs (gdextension/doc_classes/, the editor's help and the source of the
## generated native_field.gd) name exactly the methods each class registers, with their arguments,
## types and return types, and its constants with their values. No class has more than 36 methods.
func test_the_native_docs_are_the_registration() -> void:
	var folder: String = ProjectSettings.globalize_path("res://").path_join("../../gdextension/doc_classes")
	for native_class: String in NATIVE_CLASSES:
		var documented: Dictionary = _documented(folder.path_join(native_class + ".xml"))
		var registered: Dictionary = {}
		for method: Dictionary in ClassDB.class_get_method_list(native_class, true):
			var args: PackedStringArray = []
			for arg: Dictionary in method["args"]:
				args.append("%s: %s" % [arg["name"], _type_name(arg)])
			registered["method " + method["name"]] = "(%s) -> %s" % [", ".join(args), _type_name(method["return"])]
		for constant: String in ClassDB.class_get_integer_constant_list(native_class, true):
			registered["constant " + constant] = str(ClassDB.class_get_integer_constant(native_class, constant))
		for key: String in registered:
			check_eq(documented.get(key, "(not documented)"), registered[key], "%s %s" % [native_class, key])
		for key: String in documented:
			check(registered.has(key), "%s documents %s, which it does not register" % [native_class, key])
		var methods: int = ClassDB.class_get_method_list(native_class, true).size()
		check(methods <= 36, "%s has %d methods" % [native_class, methods])


## An object argument is checked for what it is: a drawing attached to no simulation, to an object of
## another class or to a simulation freed since says so and draws nothing, and crashes nothing.
func test_a_drawing_without_its_simulation_says_so() -> void:
	var drawing: SunflowerDrawing = SunflowerDrawing.new()
	drawing.draw()
	expect_engine_error("draw: no simulation to draw")
	drawing.call(&"attach", SunflowerMap.new())  # (a typed call does not parse: the argument's class is bound)
	expect_engine_error("attach: takes a SunflowerSimulation")
	var simulation: SunflowerSimulation = SunflowerSimulation.new()
	check_eq(simulation.load_map("2 2\n**\n**\n".to_utf8_buffer(), "two.field", "", "", 0), "", "a small map")
	drawing.attach(simulation)
	check_eq(drawing.get_chunk_count(), 1, "the drawing reads the simulation attached")
	var changes: SunflowerChanges = SunflowerChanges.new()
	changes.attach(simulation)
	check_eq(changes.change_cells(PackedInt32Array([0]), 2, 0.0), PackedInt32Array([0]), "a cell cut")
	simulation = null  # (the last reference: freed)
	check_eq(drawing.get_chunk_count(), 0, "nothing once the simulation is gone")
	expect_engine_error("get_chunk_count: no simulation to draw")
	check_eq(changes.get_change_count(), 0, "no changes once the simulation is gone")
	expect_engine_error("get_change_count: no simulation to change")


func test_the_node_names_the_cores_indices() -> void:
	check_eq(SunflowerField.Part.size(), SunflowerDrawing.PART_COUNT, "parts")
	check_eq(SunflowerField.Lod.size(), SunflowerDrawing.LOD_COUNT, "levels")
	check_eq(
		SunflowerField.Lod.SPRITE, SunflowerDrawing.MESH_LEVEL_COUNT, "the first impostor level follows the meshes"
	)
	check_eq(SunflowerField.PartMeshes.PART_NAMES.size(), SunflowerDrawing.PART_COUNT, "part names")
	check_eq(SunflowerPlant.PartMeshes.LEVELS, SunflowerDrawing.MESH_LEVEL_COUNT, "a plant's levels")
	check_eq(SunflowerDrawing.mesh_bucket(2, SunflowerField.Part.HEAD), 8, "the last mesh bucket")
	check_eq(SunflowerDrawing.BUCKET_IMPOSTOR, 9, "the impostors follow the mesh buckets")


## The impostor shader decodes far records with the library's numbers: every RECORD_X constant of
## shaders/records.gdshaderinc equals the library's FAR_X.
func test_the_shaders_record_layout_is_the_librarys() -> void:
	var path: String = "res://addons/sunflower_field/shaders/records.gdshaderinc"
	var text: String = FileAccess.get_file_as_string(path)
	var pattern: RegEx = RegEx.create_from_string("(?m)^const (?:float|uint|int) RECORD_(\\w+) = ([0-9.]+)u?;")
	var found: int = 0
	for match: RegExMatch in pattern.search_all(text):
		var name: String = "FAR_" + match.get_string(1)
		found += 1
		if check(
			ClassDB.class_has_integer_constant(&"SunflowerDrawing", name), "the library has no %s for %s" % [name, path]
		):
			check_eq(
				match.get_string(2).to_float(),
				float(ClassDB.class_get_integer_constant(&"SunflowerDrawing", name)),
				"%s in %s" % [name, path]
			)
	check(found >= 4, "%s defines the record's numbers (%d found)" % [path, found])


## Every value the inspector shows a default for is defined once, in the core's table: the
## defaults of the node and of the wind resource equal the core's.
func test_inspector_defaults_equal_the_cores() -> void:
	var field: SunflowerField = SunflowerField.new()
	var owners: Dictionary = {
		"SunflowerField": field, "SunflowerWind": SunflowerWind.new(), "SunflowerPlant": SunflowerPlant.new()
	}
	var names: PackedStringArray = SunflowerField.Native.parameter_names()
	check(names.size() >= 20, "the core lists its parameters (%d)" % names.size())
	for qualified: String in names:
		var pieces: PackedStringArray = qualified.split(".")
		if pieces[0] == "ProjectSettings":  # a machine-wide setting: one the addon registers
			check(pieces[1] in ProjectKnobs.TABLE_SETTINGS, "%s is no setting the addon registers" % qualified)
			continue
		var object: Object = owners.get(pieces[0])
		if not check(object != null and pieces[1] in object, "%s is no inspector property" % qualified):
			continue
		var shown: Variant = object.get_script().get_property_default_value(pieces[1])
		var core: float = SunflowerField.Native.default_of(qualified)
		# A row of several values: the default is its first one's (SunflowerWind.direction,
		# SunflowerField.lod_distances), every one's for a Vector3 (SunflowerPlant.part_lengths).
		var agrees: bool = false
		if shown is Vector3:
			agrees = shown.is_equal_approx(Vector3.ONE * core)
		elif shown is Vector2 or shown is PackedFloat32Array:
			agrees = is_equal_approx(float(shown[0]), core)
		else:
			agrees = is_equal_approx(float(shown), core)
		check(agrees, "%s: the inspector shows %s, the core %s" % [qualified, shown, core])
	field.free()


func test_imported_map_is_a_field_map_resource() -> void:
	var field_map: SunflowerFieldMap = load("res://fields/demo.field") as SunflowerFieldMap
	if not check(field_map != null, "res://fields/demo.field did not import as a SunflowerFieldMap"):
		return
	check_eq(field_map.columns, 40, "columns")
	check_eq(field_map.rows, 30, "rows")
	check_eq(field_map.plant_count, 1103, "plants")


func test_default_part_meshes_are_unit_height_and_near_thesis_triangle_counts() -> void:
	var field: SunflowerField = SunflowerField.new()
	var expected: Array[int] = [4030, 2083, 1145]  # thesis Table 1
	for lod: int in 3:
		var triangles: int = 0
		for part: int in 3:
			var mesh: Mesh = field.get_part_mesh(lod, part)
			if not check(mesh != null, "no default mesh for level %d part %d" % [lod, part]):
				continue
			var box: AABB = mesh.get_aabb()
			check(
				box.position.y >= -0.01 and box.position.y <= 0.02,
				"part %d/%d does not start at its root (y %s)" % [lod, part, box.position.y]
			)
			check(box.end.y <= 1.05, "part %d/%d is taller than 1 unit (%s)" % [lod, part, box.end.y])
			for surface: int in mesh.get_surface_count():
				triangles += mesh.surface_get_arrays(surface)[Mesh.ARRAY_INDEX].size() / 3
		check(
			absf(triangles - expected[lod]) < expected[lod] * 0.15,
			"level %d has %d triangles, thesis %d" % [lod + 1, triangles, expected[lod]]
		)
	field.free()


## A new field stores nothing in its scene but its script until a setting changes (the inspector then
## shows no change nobody made); a changed wind is stored once, as the wind resource.
func test_a_new_field_stores_only_what_was_changed() -> void:
	var root: Node3D = Node3D.new()
	var field: SunflowerField = SunflowerField.new()
	root.add_child(field)
	field.owner = root
	check_eq(_stored(root), PackedStringArray(["script"]), "a new field's scene")
	field.wind_power = 3.0
	field.lod_hysteresis = 1.0
	check_eq(_stored(root), PackedStringArray(["script", "wind", "lod_hysteresis"]), "after two changes")
	var reloaded: SunflowerField = _packed(root).instantiate().get_child(0) as SunflowerField
	check_eq(reloaded.wind_power, 3.0, "the wind power comes back from the stored wind")
	check_eq(reloaded.lod_hysteresis, 1.0, "the hysteresis comes back")
	reloaded.get_parent().free()
	for property: StringName in FieldFace.WIND_PROPERTIES:
		check(field.property_can_revert(property), "%s offers a revert" % property)
	check_eq(field.property_get_revert(&"wind_power"), 1.0, "wind_power reverts to the wind's default")
	root.free()


## The inspector counts a property as changed when it differs from its revert value, or from the
## script's default when there is none: a new field's wind group showed "Wind (1 change)".
func test_a_new_field_shows_no_change() -> void:
	var field: SunflowerField = SunflowerField.new()
	var changed: PackedStringArray = []
	for property: Dictionary in field.get_property_list():
		if property["usage"] & PROPERTY_USAGE_EDITOR and _shows_changed(field, property["name"]):
			changed.append(property["name"])
	check_eq(changed, PackedStringArray(), "properties a new field shows changed")
	field.wind_power = 2.0
	check(_shows_changed(field, &"wind"), "a changed wind shows changed")
	field.free()


func _shows_changed(object: Object, property: StringName) -> bool:
	var value: Variant = object.get(property)
	var default: Variant = (
		object.property_get_revert(property)
		if object.property_can_revert(property)
		else object.get_script().get_property_default_value(property)
	)
	var declared: bool = object.get_script().get_script_property_list().any(
		func(p: Dictionary) -> bool: return p["name"] == property
	)
	if not declared and not object.property_can_revert(property):
		return false  # the engine's own properties: not this test's business
	return typeof(value) != typeof(default) or value != default


func _packed(root: Node) -> PackedScene:
	var scene: PackedScene = PackedScene.new()
	scene.pack(root)
	return scene


func _stored(root: Node) -> PackedStringArray:
	var state: SceneState = _packed(root).get_state()
	var names: PackedStringArray = []
	for index: int in state.get_node_property_count(1):
		names.append(state.get_node_property_name(1, index))
	return names


## The drop button in a field's inspector never widens the dock (its text was 170 px wider than the
## dock's default width), whatever step of an import it shows.
func test_the_drop_button_fits_a_narrow_dock() -> void:
	var button: Button = load("res://addons/sunflower_field/editor/scene_drop_button.gd").new()
	for label: String in (
		[button.text] + Array(load("res://addons/sunflower_field/editor/scene_plant_inspector.gd").STEPS)
	):
		button.text = label
		check(button.get_minimum_size().x <= 120.0, "'%s' asks for %.0f px" % [label, button.get_minimum_size().x])
	button.free()


## The inspector's range hints give the limits of the core's table, for every row of it that the
## inspector shows as a range (on the node, its wind and its plant, and the node's wind proxies): 6 of
## 46 hints differed from the table when they were typed twice.
func test_the_inspectors_ranges_are_the_tables() -> void:
	var objects: Dictionary = {
		"SunflowerField": SunflowerField.new(),
		"SunflowerWind": SunflowerWind.new(),
		"SunflowerPlant": SunflowerPlant.new()
	}
	var checked: int = 0
	ProjectKnobs.register()  # (the editor plugin does): Project Settings show their limits too
	for property: Dictionary in ProjectSettings.get_property_list():
		if property["name"] in ProjectKnobs.TABLE_SETTINGS:
			checked += 1
			_check_range("ProjectSettings." + property["name"], property["name"], property["hint_string"])
	for row: String in SunflowerField.Native.parameter_names():
		if row.begins_with("ProjectSettings."):
			continue
		var owner: Object = objects[row.get_slice(".", 0)]
		var names: Array = [row.get_slice(".", 1)]
		if owner is SunflowerWind:
			names.append_array(
				FieldFace.WIND_PROPERTIES.keys().filter(
					func(proxy: StringName) -> bool: return FieldFace.WIND_PROPERTIES[proxy] == names[0]
				)
			)
		for name: String in names:
			var shown: Object = objects["SunflowerField"] if name != names[0] else owner
			for property: Dictionary in shown.get_property_list():
				if property["name"] == name and property["hint"] == PROPERTY_HINT_RANGE:
					checked += 1
					_check_range(row, name, property["hint_string"])
	check(checked >= 40, "%d ranges checked" % checked)
	objects["SunflowerField"].free()


func _check_range(row: String, name: String, hint: String) -> void:
	var parts: PackedStringArray = hint.split(",")
	var degrees: bool = parts.has("radians_as_degrees")
	for side: int in 2:
		var limit: float = ClassDB.class_call_static(&"SunflowerParameters", &"get_parameter_limit", row, side == 1)
		var flag: String = "or_less" if side == 0 else "or_greater"
		var expected: float = rad_to_deg(limit) if degrees else limit
		if absf(limit) >= 1e30:
			check(parts.has(flag), "%s (%s): the table has no %s, the hint says '%s'" % [name, row, flag, hint])
		elif side == 1 and parts.has(flag) and float(parts[1]) < expected:
			pass  # a slider's span below the table's max: the setter holds larger values to it
		else:
			check(
				is_equal_approx(float(parts[side]), expected) and not parts.has(flag),
				"%s (%s): the table's %s is %s, the hint says '%s'" % [name, row, ["min", "max"][side], expected, hint]
			)


## A new field's inspector shows on its first screen (outside the folded "Advanced: …" groups) at
## most 15 settings, what a first field needs, with each ground's own settings only while it is the
## ground, and no setting twice (the wind's power lives in its wind). It showed 47 in 9 groups.
func test_a_new_fields_first_screen_shows_what_a_first_field_needs() -> void:
	var needed: PackedStringArray = [
		"map", "cell_size", "seed", "legend", "plant", "wind", "ground_source", "max_draw_distance", "observer"
	]
	var own: Dictionary = {
		SunflowerField.GroundSource.FLAT: [],
		SunflowerField.GroundSource.COLLIDERS: ["ground_collision_mask"],
		SunflowerField.GroundSource.HEIGHT_MAP: ["height_map", "height_map_rect", "height_range"],
	}
	for source: int in own:
		var field: SunflowerField = SunflowerField.new()
		field.ground_source = source
		var shown: PackedStringArray = _first_screen(field)
		print("     ground %d: %d on the first screen: %s" % [source, shown.size(), ", ".join(shown)])
		check(shown.size() <= 15, "at most 15 (%d)" % shown.size())
		for name: String in needed + PackedStringArray(own[source]):
			check(shown.has(name), "ground %d: %s on the first screen" % [source, name])
		for other: int in own:
			for name: String in own[other] if other != source else []:
				check(not _shown_anywhere(field, name), "ground %d: %s (another ground's) hidden" % [source, name])
		for name: StringName in FieldFace.WIND_PROPERTIES:
			check(not _shown_anywhere(field, name), "%s only in the wind" % name)
		field.free()


## The script's editor properties outside any group, in order.
func _first_screen(object: Object) -> PackedStringArray:
	var shown: PackedStringArray = []
	var in_script: bool = false
	var grouped: bool = false
	for property: Dictionary in object.get_property_list():
		if property["usage"] & PROPERTY_USAGE_CATEGORY:
			in_script = (
				str(property["hint_string"]).ends_with("sunflower_field.gd") or property["name"] == "SunflowerField"
			)
			grouped = false
		elif property["usage"] & (PROPERTY_USAGE_GROUP | PROPERTY_USAGE_SUBGROUP):
			grouped = not str(property["name"]).is_empty()
		elif in_script and not grouped and property["usage"] & PROPERTY_USAGE_EDITOR:
			shown.append(property["name"])
	return shown


func _shown_anywhere(object: Object, name: String) -> bool:
	for property: Dictionary in object.get_property_list():
		if property["name"] == name:
			return property["usage"] & PROPERTY_USAGE_EDITOR != 0
	return false


## A class's docs as "method name" → "(arg: Type, …) -> Type" and "constant NAME" → its value.
func _documented(path: String) -> Dictionary:
	var out: Dictionary = {}
	var parser: XMLParser = XMLParser.new()
	if not check_eq(parser.open(path), OK, "the docs " + path):
		return out
	var method: String = ""
	var args: Dictionary = {}  # index → "name: Type"
	var returns: String = "void"
	while parser.read() == OK:
		var kind: XMLParser.NodeType = parser.get_node_type()
		if kind != XMLParser.NODE_ELEMENT and kind != XMLParser.NODE_ELEMENT_END:
			continue
		var node: String = parser.get_node_name()
		if kind == XMLParser.NODE_ELEMENT_END and node == "method":
			var ordered: PackedStringArray = []
			for index: int in args.size():
				ordered.append(args.get(index, "?"))
			out["method " + method] = "(%s) -> %s" % [", ".join(ordered), returns]
			continue
		if kind == XMLParser.NODE_ELEMENT_END:
			continue
		if node == "method":
			method = parser.get_named_attribute_value("name")
			args = {}
			returns = "void"
			if parser.is_empty():
				out["method " + method] = "() -> void"
		elif node == "return" and not method.is_empty():
			returns = parser.get_named_attribute_value("type")
		elif node == "param":
			args[parser.get_named_attribute_value("index").to_int()] = (
				"%s: %s" % [parser.get_named_attribute_value("name"), parser.get_named_attribute_value("type")]
			)
		elif node == "constant":
			out["constant " + parser.get_named_attribute_value("name")] = parser.get_named_attribute_value("value")
	return out


## A registered argument's or return's type as the docs write it.
func _type_name(info: Dictionary) -> String:
	if info["type"] == TYPE_NIL:
		return "void"
	if info["type"] == TYPE_OBJECT:
		return info["class_name"]
	return type_string(info["type"])
