extends SceneTree
## GPU memory benchmark (numbers, not pass/fail; tools/bench.sh runs it under Xvfb, Vulkan): the
## render buffer memory the renderer reports (RENDERING_INFO_BUFFER_MEM_USED) before and after a
## million-plant field (1000 x 1000 cells) is built and drawn from far away (every plant in a
## static chunk), and per plant.

const SIDE: int = 1000


func _initialize() -> void:
	_run.call_deferred()


func _run() -> void:
	var camera: Camera3D = Camera3D.new()
	root.add_child(camera)
	camera.look_at_from_position(Vector3(250.0, 200.0, 900.0), Vector3(250.0, 0.0, 250.0))
	camera.make_current()
	for i: int in 10:
		await process_frame
	var before: int = RenderingServer.get_rendering_info(RenderingServer.RENDERING_INFO_BUFFER_MEM_USED)
	var lines: PackedStringArray = ["%d %d" % [SIDE, SIDE]]
	for row: int in SIDE:
		lines.append("*".repeat(SIDE))
	var field_map: SunflowerFieldMap = SunflowerFieldMap.new()
	field_map.source_path = "user://million.field"
	field_map.text = "\n".join(lines).to_utf8_buffer()
	var field: SunflowerField = SunflowerField.new()
	root.add_child(field)
	field.map = field_map
	field.finish_build()
	for i: int in 10:
		await process_frame
	var after: int = RenderingServer.get_rendering_info(RenderingServer.RENDERING_INFO_BUFFER_MEM_USED)
	var plants: int = field.get_plant_count()
	var counts: PackedInt32Array = field.get_lod_counts()
	var far: int = counts[3] + counts[4]
	print("| plants | far plants | render buffers before | after | per plant |")
	print("|---|---|---|---|---|")
	print(
		(
			"| %d | %d | %.1f MB | %.1f MB | %.1f B |"
			% [plants, far, before / 1048576.0, after / 1048576.0, float(after - before) / maxi(plants, 1)]
		)
	)
	field.free()
	quit(0)
