extends SceneTree
## GPU memory benchmark (numbers, not pass/fail; tools/bench.sh runs it under Xvfb, Vulkan): the
## render buffer memory the renderer reports (RENDERING_INFO_BUFFER_MEM_USED) before and after a
## million-plant field (1000 x 1000 cells) is built and drawn from far away (every plant in a
## static chunk), and per plant.

const Maps: GDScript = preload("res://runner/maps.gd")
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
	var field: SunflowerField = SunflowerField.new()
	root.add_child(field)
	field.map = Maps.filled(SIDE, SIDE, "user://million.field")
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
