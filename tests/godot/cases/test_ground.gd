extends TestCase
## Ground sources: a field on a hilly HeightMapShape3D (rays at colliders) and on the same heights
## as an image (the core's bilinear height map) — every plant on the ground, the two agreeing within
## 2 cm; holes and ground that ends get no plants (counted); legend objects stand on the ground;
## the collider rays wait for the physics frame and hold no frame longer than the build budget.

## The terrain: SIDE × SIDE heights, one metre apart, centred on the body at TERRAIN_AT.
const SIDE: int = 41
const TERRAIN_AT: Vector3 = Vector3(10.0, -2.0, 10.0)
const LOW: float = -1.0
const HIGH: float = 5.0
## A 40 × 40-cell field (20 × 20 m) at the origin: inside the terrain, which spans −10 to 30 m.
const COLUMNS: int = 40

var terrain: StaticBody3D
var image: Image
var fields: Array[SunflowerField] = []
var stone: PackedScene


func before_each() -> void:
	image = _hills_image()
	terrain = _terrain_body(image)
	tree.root.add_child(terrain)
	var marker: Node3D = Node3D.new()
	marker.name = "Stone"
	stone = PackedScene.new()
	stone.pack(marker)
	marker.free()


func after_each() -> void:
	for field: SunflowerField in fields:
		if is_instance_valid(field):
			field.free()
	fields.clear()
	terrain.free()


## Rolling hills as red 0–1 (FORMAT_RF), the format HeightMapShape3D reads.
func _hills_image() -> Image:
	var hills: Image = Image.create(SIDE, SIDE, false, Image.FORMAT_RF)
	for z: int in SIDE:
		for x: int in SIDE:
			var value: float = 0.5 + 0.3 * sin(x * 0.16) * cos(z * 0.13) + 0.15 * sin(0.07 * (x + 2 * z))
			hills.set_pixel(x, z, Color(value, 0.0, 0.0))
	return hills


func _terrain_body(heights: Image) -> StaticBody3D:
	var shape: HeightMapShape3D = HeightMapShape3D.new()
	shape.update_map_data_from_image(heights, LOW, HIGH)
	var collision: CollisionShape3D = CollisionShape3D.new()
	collision.shape = shape
	var body: StaticBody3D = StaticBody3D.new()
	body.name = "Terrain"
	body.position = TERRAIN_AT
	body.add_child(collision)
	return body


func _map(text_rows: PackedStringArray) -> SunflowerFieldMap:
	var field_map: SunflowerFieldMap = SunflowerFieldMap.new()
	field_map.source_path = "user://ground_%d.field" % text_rows.size()
	field_map.text = ("%d %d\n" % [text_rows[0].length(), text_rows.size()] + "\n".join(text_rows)).to_utf8_buffer()
	return field_map


func _full_map() -> SunflowerFieldMap:
	var rows: PackedStringArray = []
	for row: int in COLUMNS:
		rows.append("*".repeat(COLUMNS))
	rows[20] = "*".repeat(19) + "S" + "*".repeat(20)  # a stone in the middle
	return _map(rows)


## A field on [param source], built and drawn (colliders: after their physics frame).
func _field(source: SunflowerField.GroundSource, at: Vector3 = Vector3.ZERO) -> SunflowerField:
	var field: SunflowerField = SunflowerField.new()
	field.ground_source = source
	field.legend = {"S": stone}
	field.position = at
	field.height_map = ImageTexture.create_from_image(image)
	field.height_range = Vector2(LOW, HIGH) + Vector2(TERRAIN_AT.y - at.y, TERRAIN_AT.y - at.y)
	# The terrain's heights in the field's space: the shape's lattice is centred on its body.
	var half: float = (SIDE - 1) * 0.5
	field.height_map_rect = Rect2(TERRAIN_AT.x - half - at.x, TERRAIN_AT.z - half - at.z, SIDE - 1.0, SIDE - 1.0)
	field.map = _full_map()
	tree.root.add_child(field)
	fields.append(field)
	return field


## The ground's height at (x, z) of the world, from the image alone (bilinear), as a check that
## does not use the core.
func _image_height(x: float, z: float) -> float:
	var u: float = x - (TERRAIN_AT.x - (SIDE - 1) * 0.5)
	var v: float = z - (TERRAIN_AT.z - (SIDE - 1) * 0.5)
	var i: int = mini(int(u), SIDE - 2)
	var j: int = mini(int(v), SIDE - 2)
	var fu: float = u - i
	var fv: float = v - j
	var near: float = lerpf(image.get_pixel(i, j).r, image.get_pixel(i + 1, j).r, fu)
	var far: float = lerpf(image.get_pixel(i, j + 1).r, image.get_pixel(i + 1, j + 1).r, fu)
	return TERRAIN_AT.y + LOW + (HIGH - LOW) * lerpf(near, far, fv)


func test_plants_stand_on_a_hilly_collider_and_on_its_height_map_alike() -> void:
	var on_colliders: SunflowerField = _field(SunflowerField.GroundSource.COLLIDERS)
	var on_image: SunflowerField = _field(SunflowerField.GroundSource.HEIGHT_MAP)
	on_image.finish_build()
	check(on_colliders.is_building(), "the collider rays wait for the physics frame")
	var waited: int = await frames_until(func() -> bool: return not on_colliders.is_building(), 300)
	check(waited < 300, "the collider build completes")
	var plants: int = COLUMNS * COLUMNS - 1
	check_eq(on_colliders.get_plant_count(), plants, "every cell has ground under it")
	check_eq(on_image.get_plant_count(), plants, "every cell has ground under it")
	var worst_pair: float = 0.0
	var worst_image: float = 0.0
	var lowest: float = INF
	var highest: float = -INF
	for i: int in plants:
		var ray_root: Vector3 = on_colliders.get_plant_info(i).position
		var map_root: Vector3 = on_image.get_plant_info(i).position
		check(Vector2(ray_root.x, ray_root.z).is_equal_approx(Vector2(map_root.x, map_root.z)), "the same plants")
		worst_pair = maxf(worst_pair, absf(ray_root.y - map_root.y))
		worst_image = maxf(worst_image, absf(map_root.y - _image_height(map_root.x, map_root.z)))
		lowest = minf(lowest, map_root.y)
		highest = maxf(highest, map_root.y)
	print(
		(
			"     ground: colliders vs height map, worst %.4f m; height map vs the image, worst %.5f m"
			% [worst_pair, worst_image]
		)
	)
	check(worst_pair <= 0.02, "every plant's root on the two grounds within 2 cm (worst %.4f m)" % worst_pair)
	check(worst_image <= 0.001, "the height map is the image, bilinear (worst %.5f m)" % worst_image)
	check(highest - lowest > 2.0, "the ground is hilly (%.2f m from lowest to highest root)" % (highest - lowest))
	# The parts stand on the root; the stone stands on the ground at its cell's centre.
	var info: Dictionary = on_colliders.get_plant_info(123)
	check((info.parts[0] as Transform3D).origin.is_equal_approx(info.position), "the bottom part starts at the root")
	for field: SunflowerField in [on_colliders, on_image]:
		var stones: Array[Node] = field.get_children(true).filter(
			func(n: Node) -> bool: return n.name.begins_with("Stone")
		)
		check_eq(stones.size(), 1, "the legend's stone is placed")
		if stones.size() == 1:
			var at: Vector3 = (stones[0] as Node3D).position
			check_near(at.y, _image_height(at.x, at.z), 0.02, "the stone stands on the ground")
	var stats: Dictionary = on_colliders.get_build_stats()
	check(stats.ground_ray_ms > 0.0, "the rays' time is in the build stats")
	check_eq(stats.cells_without_ground, 0, "no cell without ground")


func test_the_field_moves_with_its_node_and_the_ground_stays_where_it_is() -> void:
	var moved: SunflowerField = _field(SunflowerField.GroundSource.COLLIDERS, Vector3(-3.0, 1.5, 2.0))
	await frames_until(func() -> bool: return not moved.is_building(), 300)
	check_eq(moved.get_plant_count(), COLUMNS * COLUMNS - 1)
	var worst: float = 0.0
	for i: int in range(0, moved.get_plant_count(), 7):
		var world: Vector3 = moved.to_global(moved.get_plant_info(i).position)
		worst = maxf(worst, absf(world.y - _image_height(world.x, world.z)))
	check(worst <= 0.02, "roots on the terrain from a moved field (worst %.4f m)" % worst)


func test_holes_and_ground_that_ends_get_no_plants_and_are_counted() -> void:
	# A hole in the image: a transparent block of pixels.
	var holed: Image = image.duplicate() as Image
	holed.convert(Image.FORMAT_RGBAF)
	for z: int in range(18, 22):
		for x: int in range(18, 22):
			holed.set_pixel(x, z, Color(0.5, 0.0, 0.0, 0.0))
	var on_image: SunflowerField = _field(SunflowerField.GroundSource.HEIGHT_MAP)
	on_image.height_map = ImageTexture.create_from_image(holed)
	on_image.finish_build()
	var missing: int = COLUMNS * COLUMNS - 1 - on_image.get_plant_count()
	check(missing > 0, "plants over the hole are gone (%d)" % missing)
	check_eq(on_image.get_build_stats().cells_without_ground, missing, "and counted")
	for i: int in on_image.get_plant_count():
		var root: Vector3 = on_image.get_plant_info(i).position
		var u: float = root.x - (TERRAIN_AT.x - (SIDE - 1) * 0.5)
		var v: float = root.z - (TERRAIN_AT.z - (SIDE - 1) * 0.5)
		if u > 17.0 and u < 22.0 and v > 17.0 and v < 22.0:
			check(false, "no plant within the cells around the hole's pixels: %s" % root)
			break
	# Colliders that end: the field reaches 5 m past the terrain's edge.
	var past_edge: SunflowerField = _field(SunflowerField.GroundSource.COLLIDERS, Vector3(15.0, 0.0, 0.0))
	await frames_until(func() -> bool: return not past_edge.is_building(), 300)
	var expected_missing: int = 0
	for i: int in past_edge.get_simulation().get_ground_points().size() / 2 - 1:
		var x: float = 15.0 + past_edge.get_simulation().get_ground_points()[2 * i]
		if x > TERRAIN_AT.x + (SIDE - 1) * 0.5:
			expected_missing += 1
	check(expected_missing > 0)
	check_eq(past_edge.get_build_stats().cells_without_ground, expected_missing, "the cells past the terrain")
	check_eq(past_edge.get_plant_count(), COLUMNS * COLUMNS - 1 - expected_missing)
	# The holed image's stone stood in the hole: it is left out, with a warning.
	check(warned("1 of 1 objects have no ground under them"), "the stone over the hole is reported")


func test_a_height_map_without_an_image_is_a_clear_error_and_the_field_stays() -> void:
	var field: SunflowerField = _field(SunflowerField.GroundSource.HEIGHT_MAP)
	field.finish_build()
	var plants: int = field.get_plant_count()
	allow_error("no height map is set")
	field.height_map = null
	field.finish_build()
	check_eq(field.get_plant_count(), plants, "the previous field stays")
	check(" ".join(field._get_configuration_warnings()).contains("height_map"), "the warning names the property")


func test_collider_rays_keep_frames_within_the_build_budget() -> void:
	var rows: PackedStringArray = []
	for row: int in 200:
		rows.append("*".repeat(200))
	var field: SunflowerField = _field(SunflowerField.GroundSource.COLLIDERS)
	set_project_setting("sunflower_field/performance/build_budget_ms", 4.0)
	field.map = _map(rows)
	await frames(1)
	var waited: int = await frames_until(func() -> bool: return not field.is_building(), 2000)
	check(waited < 2000, "a 200 × 200 map on colliders builds")
	check_eq(field.get_simulation().get_map_columns(), 200)
	check_eq(field.get_plant_count() + field.get_build_stats().cells_without_ground, 40000, "every cell asked")
	var stats: Dictionary = field.get_build_stats()
	print(
		(
			"     colliders: 40 000 rays %.1f ms over %d frames, longest step %.2f ms (budget 4)"
			% [stats.ground_ray_ms, stats.frames, stats.longest_step_ms]
		)
	)
	check(stats.frames > 2, "the rays were spread over frames")


func test_the_painters_brush_sits_on_the_height_map() -> void:
	var field: SunflowerField = _field(SunflowerField.GroundSource.HEIGHT_MAP)
	field.finish_build()
	var painter: RefCounted = load("res://addons/sunflower_field/editor/field_painter.gd").new(null)
	painter.edit(field)
	var camera: Camera3D = Camera3D.new()
	tree.root.add_child(camera)
	camera.look_at_from_position(Vector3(4.0, 25.0, 30.0), Vector3(10.0, 0.0, 10.0))
	var worst: float = 0.0
	for target: Vector3 in [Vector3(5.0, 0.0, 5.0), Vector3(12.0, 0.0, 8.0), Vector3(17.0, 0.0, 14.0)]:
		target.y = _image_height(target.x, target.z)
		var hit: Variant = painter.ground_point(camera, camera.unproject_position(target))
		if not check(hit != null, "the brush finds the ground under %s" % target):
			continue
		worst = maxf(worst, (hit as Vector3).distance_to(target))
	check(worst < 0.05, "the brush is where the ray meets the hills (worst %.3f m)" % worst)
	painter.release()
	camera.free()
