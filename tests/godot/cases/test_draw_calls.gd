extends TestCase
## What the field sends the GPU: an empty near bucket is not a draw call.

var field: SunflowerField
var camera: Camera3D


func before_each() -> void:
	camera = Camera3D.new()
	camera.name = "Camera"
	field = field_in_tree(camera, load("res://fields/demo.field") as SunflowerFieldMap)
	camera.current = true


func after_each() -> void:
	field.free()
	camera.free()


## Draw calls, objects and primitives of the last frame drawn.
func _frame_info() -> Vector3i:
	return Vector3i(
		RenderingServer.get_rendering_info(RenderingServer.RENDERING_INFO_TOTAL_DRAW_CALLS_IN_FRAME),
		RenderingServer.get_rendering_info(RenderingServer.RENDERING_INFO_TOTAL_OBJECTS_IN_FRAME),
		RenderingServer.get_rendering_info(RenderingServer.RENDERING_INFO_TOTAL_PRIMITIVES_IN_FRAME)
	)


func test_empty_near_buckets_are_not_drawn() -> void:
	# Far outside the field, looking at it: every plant is in a static chunk, no bucket holds one.
	camera.look_at_from_position(Vector3(10.0, 30.0, 120.0), Vector3(10.0, 0.0, 7.5))
	await frames(4)
	var with_field: Vector3i = _frame_info()
	field.visible = false
	await frames(4)
	var without: Vector3i = _frame_info()
	field.visible = true
	var chunk_nodes: int = 0
	for node: Node in field.get_children(true):
		chunk_nodes += 1 if node.name.begins_with("Chunk") and (node as MultiMeshInstance3D).is_visible_in_tree() else 0
	print("     draw calls: %d with the field, %d without; %d chunk nodes" % [with_field.x, without.x, chunk_nodes])
	check(
		with_field.x - without.x <= chunk_nodes / 2,
		"only the chunks draw: %d calls for %d chunks" % [with_field.x - without.x, chunk_nodes / 2]
	)
