extends SceneTree
## Ground benchmark (numbers, not pass/fail; tools/bench.sh runs it headless): a million plants
## (1000 x 1000 cells, 500 x 500 m) on a 1025 x 1025 hilly terrain, built once on its height map and
## once on its collision, with the default 8 ms build budget. Prints the build figures of each.

const Maps: GDScript = preload("res://runner/maps.gd")
const SIDE: int = 1025


func _initialize() -> void:
	_run.call_deferred()


func _run() -> void:
	var image: Image = Image.create(SIDE, SIDE, false, Image.FORMAT_RF)
	for z: int in SIDE:
		for x: int in SIDE:
			image.set_pixel(x, z, Color(0.5 + 0.4 * sin(x * 0.011) * cos(z * 0.013), 0.0, 0.0))
	var shape: HeightMapShape3D = HeightMapShape3D.new()
	shape.update_map_data_from_image(image, -5.0, 5.0)
	var collision: CollisionShape3D = CollisionShape3D.new()
	collision.shape = shape
	var terrain: StaticBody3D = StaticBody3D.new()
	terrain.scale = Vector3(0.5, 1.0, 0.5)  # half a metre between heights: 512 m
	terrain.position = Vector3(250.0, 0.0, 250.0)
	terrain.add_child(collision)
	root.add_child(terrain)
	var field_map: SunflowerFieldMap = Maps.filled(1000, 1000, "user://million.field")
	print("| ground | plants | worker ms | rays ms (main thread) | frames | longest step ms | total ms |")
	print("|---|---|---|---|---|---|---|")
	for source: SunflowerField.GroundSource in [
		SunflowerField.GroundSource.HEIGHT_MAP, SunflowerField.GroundSource.COLLIDERS
	]:
		var field: SunflowerField = SunflowerField.new()
		field.ground_source = source
		field.height_map = ImageTexture.create_from_image(image)
		field.height_map_rect = Rect2(-6.0, -6.0, 512.0, 512.0)
		field.height_range = Vector2(-5.0, 5.0)
		field.map = field_map
		root.add_child(field)
		await process_frame
		while field.is_building():
			await process_frame
		var stats: Dictionary = field.get_build_stats()
		print(
			(
				"| %s | %d | %.0f | %.0f | %d | %.2f | %.0f |"
				% [
					"height map" if source == SunflowerField.GroundSource.HEIGHT_MAP else "colliders",
					field.get_plant_count(),
					stats.worker_ms,
					stats.ground_ray_ms,
					stats.frames,
					stats.longest_step_ms,
					stats.total_ms,
				]
			)
		)
		field.free()
	quit()
