@tool
@icon("icons/placement_rules.svg")
class_name SunflowerPlacementRules
extends Resource
## Placement by rules: an ordered list of [SunflowerPlacementLayer]s that turn a field's cells into
## plants (grass where the slope allows, trees by noise and away from a road, flowers in the
## meadows). Give it to a field's [member SunflowerField.placement_rules] and press "Generate from
## rules" above the field's inspector: the result is written into the field's map file, which stays
## a map you can read, diff and paint; cells painted by hand after a generation are kept at the next
## one. At run time, [method SunflowerPlacementRules.generate_map] makes the map in memory.
##
## The rules run in the native core on worker threads (a million cells in about 0.1 s here), and
## the same rules and seed give the same map on every platform.

const Native: GDScript = preload("native/native.gd")
const FieldLegend: GDScript = preload("runtime/field_legend.gd")
const FieldGround: GDScript = preload("runtime/field_ground.gd")
## Main-thread time a frame the editor spends reading a field's ground for its rules (a ray a cell on
## colliders), when Generate runs them or a brush follows one.
const GROUND_READ_BUDGET_USEC: int = 20_000


## Reads the ground's height at every cell's centre (empty for flat ground): from the field's height
## map through its built simulation, row by row, or from rays cast onto its colliders by the field's
## own ground ([code]field_ground.gd[/code], as its build casts them). No ground under a cell: 0,
## where the build lays out no plant anyway.
class HeightReader:
	extends RefCounted
	var heights: PackedFloat32Array = PackedFloat32Array()
	var _field: SunflowerField
	var _simulation: RefCounted
	var _rays: RefCounted  # the FieldGround casting the rays, on colliders
	var _rows_read: int = 0

	## Readies the reader for [param field]; returns what is wrong, or "".
	func start(field: SunflowerField) -> String:
		_field = field
		if field.ground_source == FieldGround.Source.FLAT:
			_rows_read = field.map.rows
		elif field.ground_source == FieldGround.Source.COLLIDERS:
			var centres: PackedFloat32Array = PackedFloat32Array()
			centres.resize(field.map.columns * field.map.rows * 2)
			var i: int = 0
			for row: int in field.map.rows:
				for column: int in field.map.columns:
					centres[i] = (column + 0.5) * field.cell_size
					centres[i + 1] = (row + 0.5) * field.cell_size
					i += 2
			_rays = FieldGround.for_field(field)
			_rays.set_ray_points(centres)
			_rays.start_rays(field, field.ground_ray_above, field.ground_ray_below, field.ground_collision_mask)
		else:
			if field.is_building():
				field.finish_build()
			_simulation = field.get_simulation()
			if _simulation == null or _simulation.get_map_columns() != field.map.columns:
				return "the field %s is not built on its height map yet; build it first" % field.name
			heights.resize(field.map.columns * field.map.rows)
		return ""

	## Reads until [param budget_usec] is spent (negative: all of it, now). True when all is read.
	func read(budget_usec: int) -> bool:
		if _rays:
			var none: Array[RID] = []  # (the stalk colliders the build passes by are not known here)
			if not _rays.cast_rays(budget_usec, none):
				return false
			heights = _rays.get_ray_heights()
			for i: int in heights.size():
				if not is_finite(heights[i]):
					heights[i] = 0.0
			_rays = null
			return true
		var start: int = Time.get_ticks_usec()
		var columns: int = _field.map.columns
		while _rows_read < _field.map.rows:
			var z: float = (_rows_read + 0.5) * _field.cell_size
			for column: int in columns:
				var height: float = _simulation.get_ground_height(Vector2((column + 0.5) * _field.cell_size, z))
				heights[_rows_read * columns + column] = height if is_finite(height) else 0.0
			_rows_read += 1
			if budget_usec >= 0 and Time.get_ticks_usec() - start >= budget_usec:
				break
		return _rows_read >= _field.map.rows

	## How much is read, 0 to 1.
	func progress() -> float:
		return _rays.get_ray_progress() if _rays else float(_rows_read) / maxi(_field.map.rows, 1)


## The layers, first to last: a later layer places over an earlier one, fills what it left empty
## or empties cells, as its [member SunflowerPlacementLayer.mode] says.
@export var layers: Array[SunflowerPlacementLayer] = []
## The seed every layer's randomness follows: another seed, another field from the same rules.
@export var seed: int = 1


## The native placement of these rules for [param field] (its map's size, cell size, ground,
## legend, paths and excluding bodies as they are now), ready for its [code]generate()[/code]; null
## after an error naming what is wrong. Reads the scene: call it on the main thread.
func prepare(field: SunflowerField) -> RefCounted:
	var reader: HeightReader = _reader(field)
	if reader == null:
		return null
	reader.read(-1)
	return placement_for(field, reader.heights)


## [method prepare] a few milliseconds a frame while it reads the ground (a ray a cell on colliders:
## seconds for a million cells), calling [param progress] with the share read (0–1) between frames;
## when it returns false, stops and gives null without an error. Await it.
func prepare_in_steps(field: SunflowerField, budget_usec: int, progress: Callable) -> RefCounted:
	var heights: Variant = await read_ground_in_steps(field, budget_usec, progress)
	return placement_for(field, heights) if heights is PackedFloat32Array and is_instance_valid(field) else null


## The ground's height at the centre of every cell of [param field]'s map, row by row (empty for
## flat ground), read [param budget_usec] a frame as [method prepare_in_steps] reads it; null after
## an error or when [param progress] returned false. Await it. With [method placement_for], what a
## brush following the rules keeps between strokes.
func read_ground_in_steps(field: SunflowerField, budget_usec: int, progress: Callable) -> Variant:
	var reader: HeightReader = _reader(field)
	if reader == null:
		return null
	while not reader.read(budget_usec):
		if not progress.call(reader.progress()):
			return null
		await Engine.get_main_loop().process_frame
	return reader.heights


## The reader of [param field]'s ground for these rules, or null after an error.
func _reader(field: SunflowerField) -> HeightReader:
	var problem: String = _field_problem(field)
	if not problem.is_empty():
		push_error("%s: %s" % [_name(), problem])
		return null
	var reader: HeightReader = HeightReader.new()
	problem = reader.start(field)
	if not problem.is_empty():
		push_error("%s: %s" % [_name(), problem])
		return null
	return reader


## The native placement of these rules for [param field] on the ground's [param heights] (as
## [method read_ground_in_steps] gives them); null after an error naming what is wrong.
func placement_for(field: SunflowerField, heights: PackedFloat32Array) -> RefCounted:
	var placement: RefCounted = Native.create_placement()
	if placement == null:
		return null
	placement.set_field(field.map.columns, field.map.rows, field.cell_size, seed)
	placement.set_heights(heights)
	var names: PackedStringArray = String(placement.get_layer_fields()).split(",")
	var plant_symbols: String = FieldLegend.plant_symbols(field.legend)
	for i: int in layers.size():
		var layer: SunflowerPlacementLayer = layers[i]
		var made: String = _add_layer(placement, layer, names, plant_symbols, field) if layer else "it is empty"
		if not made.is_empty():
			push_error("%s: layer %d: %s" % [_name(), i + 1, made])
			return null
	var checked: String = placement.check()
	if not checked.is_empty():
		push_error("%s: %s" % [_name(), checked])
		return null
	return placement


## The cells of [param region] (default: the whole map) as the rules place them for [param field],
## row by row: 0 for an empty cell, 1 + the plant type for a plant ([code]*[/code] is type 0, the
## legend's plants 1, 2, … in order). Empty after an error.
func generate_cells(field: SunflowerField, region: Rect2i = Rect2i()) -> PackedByteArray:
	var placement: RefCounted = prepare(field)
	if placement == null:
		return PackedByteArray()
	if region == Rect2i():
		region = Rect2i(0, 0, field.map.columns, field.map.rows)
	var cells: PackedByteArray = placement.generate(
		region.position.x, region.position.y, region.size.x, region.size.y, 0
	)
	if cells.is_empty():
		push_error(
			(
				"%s: the region %s is not inside the field's %d x %d cells"
				% [_name(), region, field.map.columns, field.map.rows]
			)
		)
	return cells


## A new map of [param field]'s size with the plants the rules place, keeping the comments and
## objects of the field's map (for a field generated at run time: [code]field.map =
## rules.generate_map(field)[/code]). Null after an error.
func generate_map(field: SunflowerField) -> SunflowerFieldMap:
	var cells: PackedByteArray = generate_cells(field)
	if cells.is_empty():
		return null
	var made: SunflowerFieldMap = SunflowerFieldMap.new()
	made.source_path = field.map.source_path
	made.text = map_text(cells, field, field.map.text)
	return made


## [param cells] of [param field]'s map size as map text: '*' and the legend's plant symbols, the
## comment lines and objects of the map text [param previous] kept (or a comment naming these rules).
func map_text(cells: PackedByteArray, field: SunflowerField, previous: PackedByteArray) -> PackedByteArray:
	var placement: RefCounted = Native.create_placement()
	if placement == null:
		return PackedByteArray()
	var header: String = (
		"# Generated from placement rules%s; see docs/placement.md."
		% (" " + resource_path if not resource_path.is_empty() else "")
	)
	return placement.write_map(
		cells, field.map.columns, field.map.rows, FieldLegend.plant_symbols(field.legend), header, previous
	)


func _name() -> String:
	return "Placement rules" + (" " + resource_path if not resource_path.is_empty() else "")


func _field_problem(field: SunflowerField) -> String:
	if field == null:
		return "needs a field"
	if field.map == null:
		return "the field %s has no map: give it one (New map… above its inspector) of the size to fill" % field.name
	if field.map.columns == 0 and not field.map.check_format().is_empty():
		return "the field's map %s does not read" % field.map.source_path
	if field.ground_source != FieldGround.Source.FLAT and not field.is_inside_tree():
		return "the field must be in the scene tree to read its ground"
	if field.ground_source == FieldGround.Source.COLLIDERS and field.get_world_3d() == null:
		return "the field has no world to cast its ground rays in"
	return ""


## Adds [param layer] to [param placement]; returns what is wrong, or "".
func _add_layer(
	placement: RefCounted,
	layer: SunflowerPlacementLayer,
	names: PackedStringArray,
	symbols: String,
	field: SunflowerField
) -> String:
	var species: int = 0 if layer.plant == "*" else symbols.find(layer.plant) + 1
	if (
		layer.mode != SunflowerPlacementLayer.Mode.ERASE
		and (layer.plant.length() != 1 or species < 1 and layer.plant != "*")
	):
		return "its plant '%s' is neither '*' nor a plant symbol of the field's legend ('%s')" % [layer.plant, symbols]
	var mask: PackedByteArray = PackedByteArray()
	var mask_size: Vector2i = Vector2i.ZERO
	if layer.mask_use:
		var image: Image = layer.mask_texture.get_image() if layer.mask_texture else null
		if image == null or image.is_empty():
			return "its mask has no texture (or the texture has no image to read)"
		image = image.duplicate() as Image
		if image.is_compressed():
			image.decompress()
		image.clear_mipmaps()
		image.convert(Image.FORMAT_RGBA8)
		mask = image.get_data()
		mask_size = image.get_size()
	var rect: Rect2 = layer.mask_rect
	if rect.size == Vector2.ZERO:
		rect = Rect2(Vector2.ZERO, Vector2(field.map.columns, field.map.rows) * field.cell_size)
	var lines: PackedFloat32Array = PackedFloat32Array()
	if layer.paths_use:
		var problem: String = _path_lines(layer, field, lines)
		if not problem.is_empty():
			return problem
	var footprints: PackedFloat32Array = _footprints(layer, field) if layer.exclusion_use else PackedFloat32Array()
	var numbers: Dictionary = {
		"mode": layer.mode,
		"species": species,
		"density": layer.density,
		"height_on": layer.height_use,
		"height_low": layer.height_min,
		"height_high": layer.height_max,
		"height_falloff": layer.height_falloff,
		"height_invert": layer.height_invert,
		"slope_on": layer.slope_use,
		"slope_low": layer.slope_min,
		"slope_high": layer.slope_max,
		"slope_falloff": layer.slope_falloff,
		"slope_invert": layer.slope_invert,
		"noise_on": layer.noise_use,
		"noise_scale": layer.noise_scale,
		"noise_octaves": layer.noise_octaves,
		"noise_threshold": layer.noise_threshold,
		"noise_falloff": layer.noise_falloff,
		"noise_seed": layer.noise_seed,
		"noise_invert": layer.noise_invert,
		"mask_on": layer.mask_use,
		"mask_width": mask_size.x,
		"mask_height": mask_size.y,
		"mask_x": rect.position.x,
		"mask_z": rect.position.y,
		"mask_size_x": rect.size.x,
		"mask_size_z": rect.size.y,
		"mask_outside": layer.mask_outside,
		"mask_invert": layer.mask_invert,
		"mask_channel": layer.mask_channel,
		"paths_on": layer.paths_use,
		"paths_half_width": layer.paths_half_width,
		"paths_falloff": layer.paths_falloff,
		"paths_invert": layer.paths_invert,
		"exclusion_on": layer.exclusion_use,
		"exclusion_falloff": layer.exclusion_falloff,
		"spacing_on": layer.spacing_use,
		"spacing_layer": layer.spacing_layer - 1,
		"spacing_distance": layer.spacing_distance,
	}
	var row: PackedFloat32Array = PackedFloat32Array()
	for name: String in names:
		if not numbers.has(name):
			return (
				"the native library asks for '%s', which this script does not know (the addon's scripts and library differ)"
				% name
			)
		row.append(float(numbers[name]))
	return placement.add_layer(row, lines, footprints, mask)


## The layer's paths' curves as seen from above in the field's space, each as (count, x, z, …),
## appended to [param lines]; returns what is wrong, or "".
func _path_lines(layer: SunflowerPlacementLayer, field: SunflowerField, lines: PackedFloat32Array) -> String:
	if not field.is_inside_tree():
		return "the field must be in the scene tree to find its paths"
	var to_field: Transform3D = field.global_transform.affine_inverse()
	for path: NodePath in layer.paths_nodes:
		var node: Path3D = field.get_node_or_null(path) as Path3D
		if node == null or node.curve == null:
			return "its path %s is not a Path3D with a curve (paths are named from the field)" % path
		var points: PackedVector3Array = node.curve.get_baked_points()
		if points.size() < 2:
			return "its path %s has fewer than two points" % path
		var transform: Transform3D = to_field * node.global_transform
		lines.append(points.size())
		for point: Vector3 in points:
			var local: Vector3 = transform * point
			lines.append(local.x)
			lines.append(local.z)
	return ""


## The footprints, as seen from above in the field's space, of the collision shapes of every
## CollisionObject3D of the field's scene on the layer's exclusion layers (not the field's own), each
## the convex outline of its shape's box, as (count, x, z, …).
func _footprints(layer: SunflowerPlacementLayer, field: SunflowerField) -> PackedFloat32Array:
	var footprints: PackedFloat32Array = PackedFloat32Array()
	if not field.is_inside_tree():
		return footprints
	var tree: SceneTree = field.get_tree()
	var scene: Node = tree.edited_scene_root if Engine.is_editor_hint() else tree.current_scene
	if scene == null:
		scene = tree.root
	var to_field: Transform3D = field.global_transform.affine_inverse()
	for node: Node in scene.find_children("*", "CollisionObject3D", true, false):
		var body: CollisionObject3D = node as CollisionObject3D
		if body.collision_layer & layer.exclusion_layers == 0 or field.is_ancestor_of(body):
			continue
		for child: Node in body.get_children():
			var shape: CollisionShape3D = child as CollisionShape3D
			if shape == null or shape.disabled or shape.shape == null:
				continue
			var transform: Transform3D = to_field * shape.global_transform
			var points: PackedVector2Array = PackedVector2Array()
			for vertex: Vector3 in _outline_points(shape.shape):
				var local: Vector3 = transform * vertex
				points.append(Vector2(local.x, local.z))
			var outline: PackedVector2Array = Geometry2D.convex_hull(points)
			outline.remove_at(outline.size() - 1)  # the hull repeats its first point last
			if outline.size() < 3:
				continue
			footprints.append(outline.size())
			for point: Vector2 in outline:
				footprints.append(point.x)
				footprints.append(point.y)
	return footprints


## Points whose hull from above is [param shape]'s footprint: the edges the editor draws of it (a
## box's corners, a sphere's, cylinder's or capsule's circles, a convex polygon's corners). A concave
## shape's footprint is the hull of its outline.
static func _outline_points(shape: Shape3D) -> PackedVector3Array:
	var mesh: ArrayMesh = shape.get_debug_mesh()
	var points: PackedVector3Array = PackedVector3Array()
	for surface: int in mesh.get_surface_count() if mesh else 0:
		points.append_array(mesh.surface_get_arrays(surface)[Mesh.ARRAY_VERTEX])
	return points
