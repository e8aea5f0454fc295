class_name NativeBaseline
extends Node3D
## A benchmark baseline: the field drawn the Godot-native way, without the addon's LOD and wind.
## Whole plants (the three level-1 parts merged into one mesh, with the engine's automatic mesh
## LODs generated) in one MultiMeshInstance3D per square chunk, each with a visibility-range
## cut-off. Plant positions come from the addon's layout, so both draw the same field.

## Side of the chunks, metres.
const CHUNK_SIZE: float = 16.0
## Chunks farther than this are not drawn, unless the build is given another cut-off.
const CUT_OFF: float = 100.0


## Builds the baseline for [param field_map]; chunks are not drawn past [param cut_off] metres (0:
## always drawn). Returns the number of plants.
func build(field_map: SunflowerFieldMap, field: SunflowerField, cut_off: float = CUT_OFF) -> int:
	var simulation: SunflowerSimulation = SunflowerSimulation.new()
	var error: String = simulation.load_map(field_map.text, field_map.source_path, "", "", 0)
	if not error.is_empty():
		push_error("NativeBaseline: " + error)
		return 0
	simulation.set_layout(field.cell_size, field.seed, field.independent_jitter, CHUNK_SIZE)
	var mesh: ArrayMesh = _whole_plant_mesh(field)
	# Parts are one model unit each, stacked three high.
	var scale_factor: float = field.plant_height / SunflowerSimulation.PART_COUNT
	var chunks: Dictionary = {}
	for i: int in simulation.get_plant_count():
		var position: Vector3 = simulation.get_plant_position(i)
		var key: Vector2i = Vector2i(floori(position.x / CHUNK_SIZE), floori(position.z / CHUNK_SIZE))
		if not chunks.has(key):
			chunks[key] = []  # an Array, which is shared by reference (a packed array would be copied)
		(chunks[key] as Array).append(position)
	for key: Vector2i in chunks:
		var positions: Array = chunks[key]
		var multimesh: MultiMesh = MultiMesh.new()
		multimesh.transform_format = MultiMesh.TRANSFORM_3D
		multimesh.mesh = mesh
		multimesh.instance_count = positions.size()
		for k: int in positions.size():
			var origin: Vector3 = positions[k]
			multimesh.set_instance_transform(k, Transform3D(Basis.from_scale(Vector3.ONE * scale_factor), origin))
		var node: MultiMeshInstance3D = MultiMeshInstance3D.new()
		node.multimesh = multimesh
		node.visibility_range_end = cut_off
		add_child(node)
	return simulation.get_plant_count()


func _whole_plant_mesh(field: SunflowerField) -> ArrayMesh:
	var importer: ImporterMesh = ImporterMesh.new()
	for part: int in 3:
		var source: Mesh = field.get_part_mesh(0, part)
		for surface: int in source.get_surface_count():
			var arrays: Array = source.surface_get_arrays(surface)
			var vertices: PackedVector3Array = arrays[Mesh.ARRAY_VERTEX]
			for v: int in vertices.size():
				vertices[v].y += part
			arrays[Mesh.ARRAY_VERTEX] = vertices
			importer.add_surface(Mesh.PRIMITIVE_TRIANGLES, arrays, [], {}, source.surface_get_material(surface))
	importer.generate_lods(25.0, 60.0, [])
	return importer.get_mesh()
