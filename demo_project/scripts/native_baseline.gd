class_name NativeBaseline
extends Node3D
## A benchmark baseline: the field drawn the Godot-native way, without the addon's LOD and wind, as a
## Godot user would build it by hand. Per square chunk two MultiMeshInstance3D nodes swapped by
## visibility ranges: near, whole plants (the three level-1 parts merged into one mesh, with the
## engine's automatic mesh LODs generated); far, from the field's switch to impostors
## (lod_distances[2]) to the cut-off, one camera-facing quad a plant (a Y billboard of
## StandardMaterial3D, alpha scissor) showing one picture: the plant's front view from its baked
## impostor atlas. Plant positions come from the addon's layout, so both draw the same field.
## Built with [code]far_quads[/code] false (the demo's [code]--baseline native-whole[/code]), whole
## plants are drawn at every distance (the baseline of the draw-call tables). Built with
## [code]hashed[/code] (the demo's [code]--baseline native-hashed[/code]), the far quads' alpha test is
## hashed (TRANSPARENCY_ALPHA_HASH), as a user would set it once they saw the alpha-scissored field
## thin out to bare ground with distance (mipmaps average the alpha away): the far field keeps its
## cover.

## Side of the chunks, metres.
const CHUNK_SIZE: float = 16.0
## Chunks farther than this are not drawn, unless the build is given another cut-off.
const CUT_OFF: float = 100.0


## Builds the baseline for [param field_map]; chunks are not drawn past [param cut_off] metres (0:
## always drawn); with [param far_quads] false every chunk is whole plants. Returns the number of plants
## (0 after an error, which it reports).
func build(
	field_map: SunflowerFieldMap,
	field: SunflowerField,
	cut_off: float = CUT_OFF,
	far_quads: bool = true,
	hashed: bool = false
) -> int:
	var simulation: SunflowerSimulation = SunflowerSimulation.new()
	# The layout's settings go in before the map (by their rows of the core's table).
	var rows: PackedStringArray = SunflowerParameters.get_parameter_names().split(",")
	var layout: PackedInt32Array = [rows.find("SunflowerField.cell_size"), rows.find("SunflowerField.chunk_size")]
	simulation.set_settings(0, layout, PackedFloat32Array([field.cell_size, CHUNK_SIZE]))
	simulation.set_layout_seed(field.seed, field.independent_jitter)
	var error: String = simulation.load_map(field_map.text, field_map.source_path, "", "", 0)
	if not error.is_empty():
		push_error("NativeBaseline: " + error)
		return 0
	var mesh: ArrayMesh = _whole_plant_mesh(field)
	var plant: SunflowerPlant = field.plant if field.plant != null else SunflowerPlant.default_plant()
	if far_quads and plant.impostor_views == null:
		push_error("NativeBaseline: the plant '%s' has no baked impostor views for its far quads" % plant.name)
		return 0
	var far_mesh: QuadMesh = _front_view_quad(plant, hashed) if far_quads else null
	var far_from: float = field.lod_distances[2] if far_quads else cut_off
	# Parts are one model unit each, stacked three high.
	var scale_factor: float = field.plant_height / SunflowerDrawing.PART_COUNT
	var chunks: Dictionary = {}
	for i: int in simulation.get_plant_count():
		var position: Vector3 = simulation.get_plant_position(i)
		var key: Vector2i = Vector2i(floori(position.x / CHUNK_SIZE), floori(position.z / CHUNK_SIZE))
		if not chunks.has(key):
			chunks[key] = []  # an Array, which is shared by reference (a packed array would be copied)
		(chunks[key] as Array).append(position)
	for key: Vector2i in chunks:
		var positions: Array = chunks[key]
		var near: MultiMeshInstance3D = _chunk(positions, mesh, scale_factor)
		near.visibility_range_end = minf(far_from, cut_off) if cut_off > 0.0 else far_from
		add_child(near)
		if far_quads and (cut_off <= 0.0 or cut_off > far_from):
			var far: MultiMeshInstance3D = _chunk(positions, far_mesh, scale_factor)
			far.visibility_range_begin = far_from
			far.visibility_range_end = cut_off
			add_child(far)
	return simulation.get_plant_count()


func _chunk(positions: Array, mesh: Mesh, scale_factor: float) -> MultiMeshInstance3D:
	var multimesh: MultiMesh = MultiMesh.new()
	multimesh.transform_format = MultiMesh.TRANSFORM_3D
	multimesh.mesh = mesh
	multimesh.instance_count = positions.size()
	for k: int in positions.size():
		var origin: Vector3 = positions[k]
		multimesh.set_instance_transform(k, Transform3D(Basis.from_scale(Vector3.ONE * scale_factor), origin))
	var node: MultiMeshInstance3D = MultiMeshInstance3D.new()
	node.multimesh = multimesh
	return node


## A quad the size of [param plant]'s impostor square (model units), its centre where the views' is,
## showing the front view (column 0, elevation 0 of the atlas), colours made straight from premultiplied.
func _front_view_quad(plant: SunflowerPlant, hashed: bool) -> QuadMesh:
	var atlas: Image = plant.impostor_views.get_image()
	if atlas.is_compressed():
		atlas.decompress()
	atlas.convert(Image.FORMAT_RGBA8)
	var cell: Vector2i = Vector2i(
		atlas.get_width() / SunflowerPlant.ATLAS_VIEWS.x, atlas.get_height() / SunflowerPlant.ATLAS_VIEWS.y
	)
	var front: Image = atlas.get_region(Rect2i(Vector2i.ZERO, cell))
	for y: int in cell.y:
		for x: int in cell.x:
			var colour: Color = front.get_pixel(x, y)
			if colour.a > 0.0:
				front.set_pixel(x, y, Color(colour.r / colour.a, colour.g / colour.a, colour.b / colour.a, colour.a))
	front.generate_mipmaps()
	var material: StandardMaterial3D = StandardMaterial3D.new()
	material.albedo_texture = ImageTexture.create_from_image(front)
	material.transparency = (
		BaseMaterial3D.TRANSPARENCY_ALPHA_HASH if hashed else BaseMaterial3D.TRANSPARENCY_ALPHA_SCISSOR
	)
	material.billboard_mode = BaseMaterial3D.BILLBOARD_FIXED_Y
	material.billboard_keep_scale = true
	material.cull_mode = BaseMaterial3D.CULL_DISABLED
	var frame: Vector2 = plant.impostor_frame()
	var quad: QuadMesh = QuadMesh.new()
	quad.size = Vector2(frame.x, frame.x)
	quad.center_offset = Vector3(0.0, frame.y, 0.0)
	quad.material = material
	return quad


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
