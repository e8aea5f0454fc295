extends TestCase
## Placement by rules from the engine: SunflowerPlacementRules on a field in the tree (its paths,
## excluding bodies, legend and ground), the map it writes, and its errors. The filters' semantics
## are the core's tests (gdextension/tests/test_placement.cpp).

var nodes: Array[Node] = []


func after_each() -> void:
	for node: Node in nodes:
		if is_instance_valid(node):
			node.free()
	nodes.clear()


## A field of [param columns] × [param rows] empty cells of 0.5 m in the tree, with a legend plant 'g'.
func _field(columns: int, rows: int) -> SunflowerField:
	var field: SunflowerField = SunflowerField.new()
	field.name = "Field"
	var map: SunflowerFieldMap = SunflowerFieldMap.new()
	map.source_path = "rules.field"
	map.text = ("# A comment kept through generation.\n%d %d\n.....S\n" % [columns, rows]).to_utf8_buffer()
	field.legend = {"g": SunflowerPlant.default_plant(), "S": PackedScene.new()}
	field.map = map
	check_eq(map.check_format(), "", "the empty map reads")
	tree.root.add_child(field)
	nodes.append(field)
	return field


func _layer(plant: String, density: float = 1.0) -> SunflowerPlacementLayer:
	var layer: SunflowerPlacementLayer = SunflowerPlacementLayer.new()
	layer.plant = plant
	layer.density = density
	return layer


func _cell(field: SunflowerField, cells: PackedByteArray, column: int, row: int) -> int:
	return cells[row * field.map.columns + column]


func test_a_road_and_a_building_stay_clear_and_grass_keeps_off_the_trees() -> void:
	var field: SunflowerField = _field(80, 60)
	# A road across the field (its curve in the field's space: the field sits at the origin).
	var road: Path3D = Path3D.new()
	road.name = "Road"
	road.curve = Curve3D.new()
	road.curve.add_point(Vector3(0.0, 0.0, 5.0))
	road.curve.add_point(Vector3(40.0, 0.0, 25.0))
	field.add_child(road)
	# A building on physics layer 2, turned 30°.
	var building: StaticBody3D = StaticBody3D.new()
	building.collision_layer = 2
	var shape: CollisionShape3D = CollisionShape3D.new()
	shape.shape = BoxShape3D.new()
	(shape.shape as BoxShape3D).size = Vector3(6.0, 4.0, 3.0)
	building.add_child(shape)
	building.position = Vector3(30.0, 0.0, 8.0)
	building.rotation.y = deg_to_rad(30.0)
	tree.root.add_child(building)
	nodes.append(building)
	# A round rock, 2.5 m across its footprint: the corners of its square are not excluded.
	var rock: StaticBody3D = StaticBody3D.new()
	rock.collision_layer = 2
	var round_shape: CollisionShape3D = CollisionShape3D.new()
	round_shape.shape = SphereShape3D.new()
	(round_shape.shape as SphereShape3D).radius = 2.5
	rock.add_child(round_shape)
	rock.position = Vector3(10.0, 0.0, 22.0)
	tree.root.add_child(rock)
	nodes.append(rock)
	var trees: SunflowerPlacementLayer = _layer("g", 0.05)
	var grass: SunflowerPlacementLayer = _layer("*", 0.9)
	grass.mode = SunflowerPlacementLayer.Mode.FILL
	grass.spacing_use = true
	grass.spacing_layer = 1
	grass.spacing_distance = 1.5
	for layer: SunflowerPlacementLayer in [trees, grass]:
		layer.paths_use = true
		layer.paths_nodes = [NodePath("Road")]
		layer.paths_half_width = 2.0
		layer.paths_falloff = 0.0
		layer.exclusion_use = true
		layer.exclusion_layers = 2
	var rules: SunflowerPlacementRules = SunflowerPlacementRules.new()
	rules.layers = [trees, grass]
	field.placement_rules = rules
	var cells: PackedByteArray = rules.generate_cells(field)
	check_eq(cells.size(), 80 * 60, "a cell each")
	var on_road: int = 0
	var in_building: int = 0
	var tree_cells: Array[Vector2i] = []
	var to_building: Transform3D = building.global_transform.affine_inverse()
	for row: int in 60:
		for column: int in 80:
			var centre: Vector3 = Vector3((column + 0.5) * 0.5, 0.0, (row + 0.5) * 0.5)
			var near: Vector3 = Geometry3D.get_closest_point_to_segment(centre, Vector3(0, 0, 5), Vector3(40, 0, 25))
			var inside: Vector3 = to_building * centre
			var plant: int = _cell(field, cells, column, row)
			if centre.distance_to(near) <= 2.0 and plant != 0:
				on_road += 1
			if absf(inside.x) < 3.0 and absf(inside.z) < 1.5 and plant != 0:
				in_building += 1
			if plant == 2:
				tree_cells.append(Vector2i(column, row))
	check_eq(on_road, 0, "no plant within the road's half width")
	check_eq(in_building, 0, "no plant inside the building's footprint")
	check(tree_cells.size() > 50, "trees placed (%d)" % tree_cells.size())
	var grass_at_trunks: int = 0
	for at: Vector2i in tree_cells:
		for dr: int in range(-3, 4):
			for dc: int in range(-3, 4):
				var c: Vector2i = at + Vector2i(dc, dr)
				if (dr != 0 or dc != 0) and c.x >= 0 and c.y >= 0 and c.x < 80 and c.y < 60:
					if (dr * dr + dc * dc) * 0.25 <= 2.25 and _cell(field, cells, c.x, c.y) == 1:
						grass_at_trunks += 1
	check_eq(grass_at_trunks, 0, "no grass within 1.5 m of a tree")
	# A region alone is the same region of the whole.
	var part: PackedByteArray = rules.generate_cells(field, Rect2i(10, 7, 30, 20))
	var same: bool = part.size() == 600
	for row: int in 20 if same else 0:
		for column: int in 30:
			same = same and part[row * 30 + column] == _cell(field, cells, 10 + column, 7 + row)
	check(same, "a region generated alone equals the same region of the whole")
	# Every cell but the rock's and the building's, for the rock's outline: none in its circle, all in
	# the corners of its square.
	var everywhere: SunflowerPlacementLayer = _layer("*")
	everywhere.exclusion_use = true
	everywhere.exclusion_layers = 2
	rules.layers = [everywhere]
	cells = rules.generate_cells(field)
	var in_rock: int = 0
	var corners: Array[int] = [0, 0]  # planted, all
	for row: int in 60:
		for column: int in 80:
			var from_rock: Vector2 = Vector2((column + 0.5) * 0.5 - 10.0, (row + 0.5) * 0.5 - 22.0)
			var plant: int = _cell(field, cells, column, row)
			in_rock += 1 if from_rock.length() < 2.5 and plant != 0 else 0
			if from_rock.length() > 2.55 and absf(from_rock.x) < 2.5 and absf(from_rock.y) < 2.5:
				corners[0] += 1 if plant != 0 else 0
				corners[1] += 1
	check_eq(in_rock, 0, "no plant inside the round rock's footprint")
	check(
		corners[1] > 10 and corners[0] == corners[1],
		"every cell in the corners of the rock's square planted (%d of %d): its outline, not its box" % corners
	)


func test_the_generated_map_keeps_the_maps_comments_and_objects_and_the_field_draws_it() -> void:
	var field: SunflowerField = _field(40, 20)
	var rules: SunflowerPlacementRules = SunflowerPlacementRules.new()
	rules.layers = [_layer("*", 0.5)]
	var made: SunflowerFieldMap = rules.generate_map(field)
	check(made != null, "a map")
	if made == null:
		return
	var text: String = made.text.get_string_from_utf8()
	check(
		text.begins_with("# A comment kept through generation.\n40 20\n"),
		"the comment and the size: %s" % text.left(60)
	)
	check_eq(text.split("\n")[2].substr(5, 1), "S", "the object stays in its cell")
	check_eq(made.check(field.legend.keys()[1] + "g"), "", "it reads with the field's legend")
	field.map = made
	field.finish_build()
	check_eq(field.get_plant_count(), made.plant_count, "the field draws what the rules placed")
	check(
		warned("'S' names a scene that makes no node (an empty scene); cell (5, 0) stays empty"),
		"the empty scene named"
	)
	check(made.plant_count > 300 and made.plant_count < 500, "about half of 800 cells: %d" % made.plant_count)
	# Another seed, another field; the same seed, the same map byte for byte.
	check_eq(rules.generate_map(field).text, made.text, "the same rules and seed: the same text")
	rules.seed = 2
	check(rules.generate_map(field).text != made.text, "another seed: another field")


func test_rules_that_cannot_run_say_which_layer_and_why() -> void:
	var field: SunflowerField = _field(10, 10)
	var rules: SunflowerPlacementRules = SunflowerPlacementRules.new()
	rules.layers = [_layer("*"), _layer("x")]
	allow_error("layer 2: its plant 'x' is neither '*' nor a plant symbol")
	check(rules.generate_cells(field).is_empty(), "an unknown plant symbol: no cells")
	rules.layers[1] = _layer("g")
	rules.layers[1].slope_use = true
	rules.layers[1].slope_min = 40.0
	rules.layers[1].slope_max = 10.0
	allow_error("layer 2: slope: its low end is above its high end")
	check(rules.generate_cells(field).is_empty(), "a slope range upside down: no cells")
	rules.layers[1].slope_use = false
	rules.layers[1].paths_use = true
	rules.layers[1].paths_nodes = [NodePath("Nowhere")]
	allow_error("layer 2: its path Nowhere is not a Path3D")
	check(rules.generate_cells(field).is_empty(), "a missing path: no cells")
	field.map = null
	allow_error("has no map")
	check(rules.generate_cells(field).is_empty(), "no map: no cells")


func test_slope_follows_the_fields_height_map_ground() -> void:
	# A ramp: red rises along x from 0 to 1 over 32 px, heights 0 to 16 m over 31 m: about 27°, and
	# a level strip at the top.
	var image: Image = _ramp_image()
	var field: SunflowerField = _field(62, 62)
	field.ground_source = SunflowerField.GroundSource.HEIGHT_MAP
	field.height_map = ImageTexture.create_from_image(image)
	field.height_range = Vector2(0.0, 10.0)
	field.height_map_rect = Rect2(0.0, 0.0, 31.0, 31.0)
	field.finish_build()
	_check_the_ramp_is_steep(field)


func test_a_brush_following_a_rule_paints_only_where_the_rule_lets_plants_grow() -> void:
	# The ramp field: a layer for level ground only (slope up to 10°), with grass kept 1.5 m off
	# the trees of layer 1 ('g').
	var field: SunflowerField = _field(62, 62)
	field.ground_source = SunflowerField.GroundSource.HEIGHT_MAP
	field.height_map = ImageTexture.create_from_image(_ramp_image())
	field.height_range = Vector2(0.0, 10.0)
	field.height_map_rect = Rect2(0.0, 0.0, 31.0, 31.0)
	field.finish_build()
	var trees: SunflowerPlacementLayer = _layer("g", 0.0)
	var level: SunflowerPlacementLayer = _layer("*", 0.01)  # its own density is not the brush's
	level.slope_use = true
	level.slope_max = 10.0
	level.spacing_use = true
	level.spacing_layer = 1
	level.spacing_distance = 1.5
	field.placement_rules = SunflowerPlacementRules.new()
	field.placement_rules.layers = [trees, level]
	var brush: RefCounted = load("res://addons/sunflower_field/editor/rule_brush.gd").new()
	check_eq(brush.problem(field), "", "no layer followed: nothing in the way")
	await brush.follow(field, 1)
	check_eq(brush.problem(field), "", "the ground is read")
	# A tree at cell (50, 30) in the map the stroke begins on.
	var native: GDScript = load("res://addons/sunflower_field/native/native.gd")
	var editor: RefCounted = native.create_map()
	var text: String = "62 62\n" + "\n".repeat(30) + ".".repeat(50) + "g\n"
	check_eq(editor.load(text.to_utf8_buffer(), "brush.field", "S", "g", 0), "", "the map reads")
	check_eq(brush.begin(field, editor.write()), "", "the stroke follows the rule")
	check(brush.is_following(), "following")
	# One dab over the whole field, the brush's density 1.
	var weights: Array = brush.weights_at(Vector2(31.0, 31.0), 50.0)
	check_eq(weights[1], Rect2i(0, 0, 62, 62), "the dab's cells, clipped to the map")
	var changed: PackedInt32Array = editor.paint(
		Vector2(31.0, 31.0), 50.0, "*", 1.0, 1, weights[0], brush.rect_cells(weights[1])
	)
	brush.note_changed(changed, "*")
	brush.end()
	var reader: RefCounted = native.create_placement()
	var cells: PackedByteArray = reader.read_map_cells(editor.write(), "g")
	var ramp: int = 0
	var top: int = 0
	for row: int in range(4, 58):
		ramp += _cell(field, cells, 20, row)  # x 10.25 m: the 27° ramp
		top += 1 if _cell(field, cells, 56, row) == 1 else 0  # x 28.25 m: level
	check_eq(ramp, 0, "nothing painted on the ramp")
	check_eq(top, 54, "every level cell painted, whatever the layer's own density")
	check_eq(_cell(field, cells, 50, 30), 2, "the tree stays")
	check_eq(_cell(field, cells, 52, 30), 0, "no sunflower 1 m from the tree")
	check_eq(_cell(field, cells, 54, 30), 1, "one 2 m from it")
	# The map resized since the ground was read: read again for the next stroke.
	var bigger: SunflowerFieldMap = SunflowerFieldMap.new()
	bigger.source_path = "rules.field"
	bigger.text = "70 66\n".to_utf8_buffer()
	field.map = bigger
	check_eq(brush.begin(field, bigger.text), "", "a stroke on the resized map")
	check_eq(brush.weights_at(Vector2(35.0, 33.0), 100.0)[1], Rect2i(0, 0, 70, 66), "the resized map's cells")
	brush.end()
	# A rule that is gone, and a ground that cannot be read, are refused with a reason.
	field.placement_rules.layers = [trees]
	check(brush.begin(field, editor.write()).contains("no placement rule 2"), "a layer that is gone")
	field.placement_rules.layers = [trees, level]
	tree.root.remove_child(field)
	allow_error("the field must be in the scene tree to read its ground")
	await brush.follow(field, 1)
	check(brush.begin(field, editor.write()).contains("could not be read"), "no ground read")
	tree.root.add_child(field)


## A ramp as a height image: red rising along x from 0 to 1 over 20 px, then level.
func _ramp_image() -> Image:
	var image: Image = Image.create(32, 32, false, Image.FORMAT_RF)
	for z: int in 32:
		for x: int in 32:
			image.set_pixel(x, z, Color(minf(x / 20.0, 1.0), 0.0, 0.0))
	return image


## Rules placing plants where the slope is 20° or more, on [param field] (62 × 62 cells of 0.5 m over
## a ramp rising 10 m over its first 20 m, then level): every cell of the ramp (26.6°) and none of
## the level top.
func _check_the_ramp_is_steep(field: SunflowerField) -> void:
	var steep: SunflowerPlacementLayer = _layer("*")
	steep.slope_use = true
	steep.slope_min = 20.0
	steep.slope_max = 90.0
	var rules: SunflowerPlacementRules = SunflowerPlacementRules.new()
	rules.layers = [steep]
	var cells: PackedByteArray = rules.generate_cells(field)
	check_eq(cells.size(), 62 * 62, "a cell each")
	if cells.size() != 62 * 62:
		return
	var ramp: int = 0
	var level: int = 0
	for row: int in range(4, 58):
		ramp += _cell(field, cells, 20, row)  # x 10.25 m
		level += _cell(field, cells, 50, row)  # x 25.25 m
	check_eq(ramp, 54, "every cell of the 27° ramp is steep enough")
	check_eq(level, 0, "no cell of the level top is")


func test_slope_follows_a_collider_ground_through_rays() -> void:
	var image: Image = _ramp_image()
	var shape: HeightMapShape3D = HeightMapShape3D.new()
	shape.update_map_data_from_image(image, 0.0, 10.0)
	var body: StaticBody3D = StaticBody3D.new()
	var collision: CollisionShape3D = CollisionShape3D.new()
	collision.shape = shape
	body.add_child(collision)
	body.position = Vector3(15.5, 0.0, 15.5)  # the shape's lattice is centred on its body
	tree.root.add_child(body)
	nodes.append(body)
	await tree.physics_frame
	await tree.physics_frame
	var field: SunflowerField = _field(62, 62)
	field.ground_source = SunflowerField.GroundSource.COLLIDERS
	_check_the_ramp_is_steep(field)
