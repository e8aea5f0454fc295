extends TestCase
## Impostors baked in the engine: a plant of glTF parts gets view and normal atlases whose views show
## the parts' colours where they stand and whose normals point the way the faces seen do; a field
## growing it draws them; the built-in sunflower baked again matches the atlases the addon ships.

const ImpostorBaker: GDScript = preload("res://addons/sunflower_field/plant/impostor_baker.gd")
const ViewsMeasure: GDScript = preload("res://addons/sunflower_field/plant/views_measure.gd")
const FOLDER: String = "user://bake_test"
const RED: Color = Color(0.85, 0.1, 0.1)
const GREEN: Color = Color(0.1, 0.6, 0.15)
const GLOW: Color = Color(1.0, 0.55, 0.0)
const BACKLIGHT: Color = Color(0.8, 0.9, 0.3)
const Stage: GDScript = preload("res://runner/stage.gd")
const Picture: GDScript = preload("res://runner/picture.gd")
const Maps: GDScript = preload("res://runner/maps.gd")
const Scenes: GDScript = preload("res://runner/scenes.gd")


## A part as a glTF file would bring it: a coloured box written to glTF, read back.
func _gltf_part(colour: Color, size: Vector3, file: String) -> Mesh:
	var material: StandardMaterial3D = StandardMaterial3D.new()
	material.albedo_color = colour
	var box: BoxMesh = BoxMesh.new()
	box.size = size
	box.material = material
	var instance: MeshInstance3D = MeshInstance3D.new()
	instance.mesh = box
	instance.position.y = size.y * 0.5  # the part's root at the origin
	var scene: Node3D = Node3D.new()
	scene.add_child(instance)
	instance.owner = scene
	var writer: GLTFDocument = GLTFDocument.new()
	var state: GLTFState = GLTFState.new()
	writer.append_from_scene(scene, state)
	var path: String = FOLDER.path_join(file)
	writer.write_to_filesystem(state, path)
	scene.free()
	var reader: GLTFDocument = GLTFDocument.new()
	var read: GLTFState = GLTFState.new()
	if reader.append_from_file(path, read) != OK:
		return null
	var imported: Node = reader.generate_scene(read)
	var found: Array[Node] = imported.find_children("*", "MeshInstance3D", true, false)
	var mesh: Mesh = (found[0] as MeshInstance3D).mesh if not found.is_empty() else null
	imported.free()
	if mesh:  # the mesh's own root: move the box's vertices so the part starts at y = 0
		var shifted: ArrayMesh = ArrayMesh.new()
		for surface: int in mesh.get_surface_count():
			var arrays: Array = mesh.surface_get_arrays(surface)
			var vertices: PackedVector3Array = arrays[Mesh.ARRAY_VERTEX]
			for i: int in vertices.size():
				vertices[i].y += size.y * 0.5
			arrays[Mesh.ARRAY_VERTEX] = vertices
			shifted.add_surface_from_arrays(Mesh.PRIMITIVE_TRIANGLES, arrays)
			shifted.surface_set_material(surface, mesh.surface_get_material(surface))
		mesh = shifted
	return mesh


## The share of opaque pixels and their mean colour.
func _coverage(image: Image) -> Array:
	var opaque: int = 0
	var sum: Color = Color(0, 0, 0, 0)
	for y: int in image.get_height():
		for x: int in image.get_width():
			var c: Color = image.get_pixel(x, y)
			if c.a > 0.5:
				opaque += 1
				sum += c
	var share: float = float(opaque) / (image.get_width() * image.get_height())
	return [share, sum / maxf(opaque, 1.0)]


## One view's square of an atlas (column around the plant, row of elevation).
func _view(atlas: Image, column: int, row: int) -> Image:
	var cell: int = atlas.get_height() / SunflowerPlant.ATLAS_VIEWS.y
	return atlas.get_region(Rect2i(column * cell, row * cell, cell, cell))


## The plant-frame normal coded in a pixel of the normal atlas.
func _normal(normals: Image, point: Vector2i) -> Vector3:
	var c: Color = normals.get_pixelv(point)
	return Vector3(c.r, c.g, c.b) * 2.0 - Vector3.ONE


## A plant named [param plant_name] of glTF parts: a thin green stalk (bottom and middle) and a red
## head written to [param head_file], 3 units tall; null (after a failed check) when they do not load.
func _gltf_plant(plant_name: String, head_file: String) -> SunflowerPlant:
	DirAccess.make_dir_recursive_absolute(FOLDER)
	var stalk: Mesh = _gltf_part(GREEN, Vector3(0.15, 1.0, 0.15), "stalk.gltf")
	var head: Mesh = _gltf_part(RED, Vector3(0.9, 1.0, 0.9), head_file)
	if not check(stalk != null and head != null, "the glTF parts load"):
		return null
	var plant: SunflowerPlant = SunflowerPlant.new()
	plant.name = plant_name
	plant.mesh_level_1 = [stalk, stalk, head]
	plant.height_units = 3.0
	return plant


func test_a_gltf_plant_gets_impostors_in_its_own_colours() -> void:
	var plant: SunflowerPlant = _gltf_plant("Red plant", "head.gltf")
	if plant == null:
		return
	var result: Error = await plant.bake_impostors(tree.root, FOLDER, "red_plant")
	check_eq(result, OK, "baked")
	for kind: String in SunflowerPlant.IMPOSTOR_TEXTURES:
		check(FileAccess.file_exists(FOLDER.path_join("red_plant_%s.png" % kind)), "%s atlas written" % kind)
	check(plant.impostor_emission == null, "a plant that gives off no light gets no emission atlas")
	check(not FileAccess.file_exists(FOLDER.path_join("red_plant_emission.png")), "and no emission file")
	check(plant.impostor_backlight == null, "a plant that lets no light through gets no back-light atlas")
	check(not FileAccess.file_exists(FOLDER.path_join("red_plant_backlight.png")), "and no back-light file")
	if not check(
		plant.impostor_views != null and plant.impostor_normals != null and plant.impostor_depths != null,
		"the plant has its atlases"
	):
		return
	var views: Image = plant.impostor_views.get_image()
	var normals: Image = plant.impostor_normals.get_image()
	views.clear_mipmaps()
	normals.clear_mipmaps()
	check_eq(views.get_size(), SunflowerPlant.ATLAS_VIEWS * ImpostorBaker.CELL_PIXELS, "one square per view")
	var cell: int = ImpostorBaker.CELL_PIXELS
	var frame: Vector2 = plant.impostor_frame()
	var pixels_per_unit: float = cell / frame.x
	for column: int in [0, 3, 7]:  # from the side, three directions around
		var side: Image = _view(views, column, 0)
		var measured: Array = _coverage(side)
		# The head is 0.9 wide and one of 3 units tall in a √(3² + 1.6²)-unit square; the stalks thin.
		check(
			measured[0] > 0.04 and measured[0] < 0.25,
			"view %d covers part of its square (%.2f)" % [column, measured[0]]
		)
		check((measured[1] as Color).r > (measured[1] as Color).g * 1.5, "mostly the head's red: %s" % measured[1])
		# The head's rows are red, the stalk's green: the parts stacked as the plant stands.
		var top: Color = side.get_pixel(cell / 2, roundi(cell / 2 - 1.0 * pixels_per_unit))
		var low: Color = side.get_pixel(cell / 2, roundi(cell / 2 + 1.0 * pixels_per_unit))
		check(top.r > 0.6 and top.g < 0.3, "view %d: the head at the top is red: %s" % [column, top])
		check(low.g > low.r and low.a > 0.5, "view %d: the stalk below is green: %s" % [column, low])
	# From straight above only the head's top shows: red in the middle, facing up; from the front,
	# the head's front face faces +z, from the right side (a quarter turn) +x.
	var above: Image = _view(views, 0, SunflowerPlant.ATLAS_VIEWS.y - 1)
	check(above.get_pixel(cell / 2, cell / 2).r > 0.6, "from above, the head: %s" % above.get_pixel(cell / 2, cell / 2))
	var head_point: Vector2i = Vector2i(cell / 2, roundi(cell / 2 - 1.0 * pixels_per_unit))
	var quarter: int = SunflowerPlant.ATLAS_VIEWS.x / 4
	var expected: Array = [
		[Vector2i(0, SunflowerPlant.ATLAS_VIEWS.y - 1), Vector2i(cell / 2, cell / 2), Vector3.UP],
		[Vector2i(0, 0), head_point, Vector3.BACK],
		[Vector2i(quarter, 0), head_point, Vector3.RIGHT],
	]
	for case: Array in expected:
		var at: Vector2i = (case[0] as Vector2i) * cell + (case[1] as Vector2i)
		var normal: Vector3 = _normal(normals, at)
		check(normal.dot(case[2]) > 0.95, "view %s: the head's normal %s points %s" % [case[0], normal, case[2]])
	# Depths along the view, in shares of the square from the plant's middle (1.5 units up): from
	# above, the head's top (3 units up) is the nearest; from the side, the thin stalk stands on the
	# plant's axis, as deep as the middle.
	var depths: Image = plant.impostor_depths.get_image()
	depths.clear_mipmaps()
	var above_depth: float = (
		depths.get_pixelv(Vector2i(0, SunflowerPlant.ATLAS_VIEWS.y - 1) * cell + Vector2i(cell / 2, cell / 2)).r
	)
	check(
		above_depth > 0.5 + 1.3 / frame.x,
		"from above, the head's top is 1.5 units nearer than the middle: %.3f" % above_depth
	)
	for column: int in [0, 3, 7]:
		var stalk_depth: Color = depths.get_pixelv(
			Vector2i(column, 0) * cell + Vector2i(cell / 2, roundi(cell / 2 + 1.0 * pixels_per_unit))
		)
		check(
			stalk_depth.a > 0.5 and absf(stalk_depth.r - 0.5) < 0.2 / frame.x,
			"view %d: the stalk lies at the middle's depth: %.3f" % [column, stalk_depth.r]
		)
	# A field growing the plant draws the baked atlases.
	var field: SunflowerField = SunflowerField.new()
	field.plant = plant
	tree.root.add_child(field)
	check(field.impostor_views == plant.impostor_views, "the field draws them")
	check(field.impostor_depths == plant.impostor_depths, "and their depths")
	field.free()


## A plant made by [method _gltf_plant] whose head gives off [constant GLOW] light (a
## StandardMaterial3D's emission) of [param energy], baked; null when it could not be.
func _glowing_plant(plant_name: String, head_file: String, energy: float) -> SunflowerPlant:
	var plant: SunflowerPlant = _gltf_plant(plant_name, head_file)
	if plant == null:
		return null
	var head: Mesh = plant.mesh_level_1[2]
	var glowing: StandardMaterial3D = (
		(head.surface_get_material(0) as StandardMaterial3D).duplicate() as StandardMaterial3D
	)
	glowing.emission_enabled = true
	glowing.emission = GLOW
	glowing.emission_energy_multiplier = energy
	head.surface_set_material(0, glowing)
	var base_name: String = plant_name.to_snake_case()
	check_eq(await plant.bake_impostors(tree.root, FOLDER, base_name), OK, "baked")
	check(FileAccess.file_exists(FOLDER.path_join(base_name + "_emission.png")), "emission atlas written")
	if not check(plant.impostor_emission != null, "the plant has an emission atlas"):
		return null
	return plant


## Checks that [param plant]'s emission atlas holds the head's light of [param energy] over the
## plant's range where the head stands, and none where the stalk does, from two sides.
func _check_glow(plant: SunflowerPlant, energy: float) -> void:
	var emission: Image = plant.impostor_emission.get_image()
	emission.clear_mipmaps()
	var cell: int = ImpostorBaker.CELL_PIXELS
	var pixels_per_unit: float = cell / plant.impostor_frame().x
	var expected: Color = GLOW.srgb_to_linear() * (energy / plant.impostor_emission_range)
	for column: int in [0, 5]:
		var side: Image = _view(emission, column, 0)
		var lit: Color = side.get_pixel(cell / 2, roundi(cell / 2 - 1.0 * pixels_per_unit)).srgb_to_linear()
		var dark: Color = side.get_pixel(cell / 2, roundi(cell / 2 + 1.0 * pixels_per_unit))
		check(
			absf(lit.r - expected.r) < 0.03 and absf(lit.g - expected.g) < 0.03 and lit.b < 0.03,
			"view %d: the head's light, %s, is the material's over the range, %s" % [column, lit, expected]
		)
		check(dark.a > 0.5 and maxf(dark.r, dark.g) < 0.02, "view %d: the stalk gives off none: %s" % [column, dark])


## A plant whose head gives off light (a StandardMaterial3D's emission, energy 2) gets an emission
## atlas holding that light over the range (8: no pixel saturates in it) where the head stands, none
## where the stalk does; a field of it in the dark seen from 45 m, all impostors, glows as brightly
## as the same field drawn with every plant as mesh 1 (and stays dark without the atlas: what the
## far levels did before).
func test_a_glowing_plant_glows_as_far_impostors() -> void:
	var plant: SunflowerPlant = await _glowing_plant("Glowing plant", "glowing_head.gltf", 2.0)
	if plant == null:
		return
	check_eq(plant.impostor_emission_range, 8.0, "the light fits the first range")
	_check_glow(plant, 2.0)
	# The field in the dark: no sun, no sky light, a black background.
	var seen: Vector3 = await _field_in_the_dark(
		plant, Vector3(5.0, 3.0, 55.0), SunflowerPlant.EMISSION_TEXTURE, false, "glowing"
	)
	var ratio: float = seen.y
	var without: float = seen.z
	print(
		(
			"     glowing far plants in the dark: %.3f of the meshes' brightness (%.3f without the emission atlas)"
			% [ratio, without]
		)
	)
	check(seen.x > 0.005, "the meshes glow: mean brightness %.4f" % seen.x)
	check(ratio > 0.8 and ratio < 1.25, "the impostors glow as the meshes do: %.3f of their brightness" % ratio)
	check(without < 0.2, "without the atlas they would stay dark: %.3f" % without)


## A plant of one thin leaf that lets light through (a StandardMaterial3D's back-light) gets a
## back-light atlas holding that colour where the leaf stands and nothing beside it; a field of it
## seen against the sun (no shadows, no ambient light, a black background), all impostors, is as
## bright as the same field drawn with every plant as mesh 1, and would be dark without the atlas
## (what the far levels did before).
func test_a_backlit_plant_lets_the_sun_through_as_far_impostors() -> void:
	DirAccess.make_dir_recursive_absolute(FOLDER)
	var leaf: Mesh = _gltf_part(Color(0.1, 0.3, 0.05), Vector3(0.9, 1.0, 0.02), "leaf.gltf")
	if not check(leaf != null, "the glTF leaf loads"):
		return
	var backlit: StandardMaterial3D = (
		(leaf.surface_get_material(0) as StandardMaterial3D).duplicate() as StandardMaterial3D
	)
	backlit.backlight_enabled = true
	backlit.backlight = BACKLIGHT
	leaf.surface_set_material(0, backlit)
	var plant: SunflowerPlant = SunflowerPlant.new()
	plant.name = "Backlit plant"
	plant.mesh_level_1 = [leaf, null, null]
	plant.height_units = 1.0
	check_eq(await plant.bake_impostors(tree.root, FOLDER, "backlit_plant"), OK, "baked")
	check(FileAccess.file_exists(FOLDER.path_join("backlit_plant_backlight.png")), "back-light atlas written")
	if not check(plant.impostor_backlight != null, "the plant has a back-light atlas"):
		return
	# Straight at either face of the leaf (view 0 and the one half a turn round): its middle, and a
	# point beside it.
	var through: Image = plant.impostor_backlight.get_image()
	through.clear_mipmaps()
	var cell: int = ImpostorBaker.CELL_PIXELS
	var pixels_per_unit: float = cell / plant.impostor_frame().x
	var expected: Color = BACKLIGHT.srgb_to_linear()
	for column: int in [0, SunflowerPlant.ATLAS_VIEWS.x / 2]:
		var side: Image = _view(through, column, 0)
		var lit: Color = side.get_pixel(cell / 2, cell / 2).srgb_to_linear()
		var beside: Color = side.get_pixel(mini(cell - 1, roundi(cell / 2 + 0.6 * pixels_per_unit)), cell / 2)
		check(
			absf(lit.r - expected.r) < 0.03 and absf(lit.g - expected.g) < 0.03 and absf(lit.b - expected.b) < 0.03,
			"view %d: the leaf's back-light, %s, is the material's, %s" % [column, lit, expected]
		)
		check(beside.a < 0.5, "view %d: nothing beside the leaf: %s" % [column, beside])
	# The field against the sun: the camera north of it, looking south, the sun ahead and above.
	var seen: Vector3 = await _field_in_the_dark(
		plant, Vector3(5.0, 3.0, -45.0), SunflowerPlant.BACKLIGHT_TEXTURE, true, "backlit"
	)
	var ratio: float = seen.y
	var without: float = seen.z
	print(
		(
			"     backlit far plants against the sun: %.3f of the meshes' brightness (%.3f without the back-light atlas)"
			% [ratio, without]
		)
	)
	check(seen.x > 0.005, "the meshes let the sun through: mean brightness %.4f" % seen.x)
	check(
		ratio > 0.85 and ratio < 1.15, "the impostors let it through as the meshes do: %.3f of their brightness" % ratio
	)
	check(without < 0.7, "without the atlas they would be darker: %.3f" % without)


## A plant whose leaf is drawn by a shader of the user's that sets BACKLIGHT itself (#60 item 2)
## gets the same: a back-light atlas holding that light where the leaf stands (the bake draws a copy
## of the shader that shows BACKLIGHT as its colour), no warning, and a field of it against the sun
## as bright as impostors as with every plant as mesh 1 (darker without the atlas).
func test_a_shader_of_the_users_that_sets_backlight_lets_the_sun_through_as_far_impostors() -> void:
	DirAccess.make_dir_recursive_absolute(FOLDER)
	var leaf: Mesh = _gltf_part(Color(0.1, 0.3, 0.05), Vector3(0.9, 1.0, 0.02), "own_leaf.gltf")
	if not check(leaf != null, "the glTF leaf loads"):
		return
	var own: ShaderMaterial = Scenes.shader_material(
		(
			"shader_type spatial;\nuniform vec3 through = vec3(0.8, 0.9, 0.3);\n"
			+ "void fragment() {\n\tALBEDO = vec3(0.1, 0.3, 0.05);\n\tBACKLIGHT = through;\n}\n"
		),
		"own_backlit"
	)
	leaf.surface_set_material(0, own)
	var plant: SunflowerPlant = SunflowerPlant.new()
	plant.name = "Own backlit plant"
	plant.mesh_level_1 = [leaf, null, null]
	plant.height_units = 1.0
	take_warnings()
	check_eq(await plant.bake_impostors(tree.root, FOLDER, "own_backlit_plant"), OK, "baked")
	var warnings: String = "\n".join(take_warnings())
	check(not warnings.contains("BACKLIGHT"), "its back-light is not named as lost: %s" % warnings)
	if not check(plant.impostor_backlight != null, "the plant has a back-light atlas"):
		return
	var through: Image = plant.impostor_backlight.get_image()
	through.clear_mipmaps()
	var cell: int = ImpostorBaker.CELL_PIXELS
	var lit: Color = _view(through, 0, 0).get_pixel(cell / 2, cell / 2).srgb_to_linear()
	check(
		absf(lit.r - 0.8) < 0.03 and absf(lit.g - 0.9) < 0.03 and absf(lit.b - 0.3) < 0.03,
		"the leaf's back-light, %s, is the shader's (0.8, 0.9, 0.3)" % lit
	)
	var seen: Vector3 = await _field_in_the_dark(
		plant, Vector3(5.0, 3.0, -45.0), SunflowerPlant.BACKLIGHT_TEXTURE, true, "own_backlit"
	)
	print(
		(
			"     a shader's own back-light, far plants against the sun: %.3f of the meshes' brightness (%.3f without)"
			% [seen.y, seen.z]
		)
	)
	check(seen.x > 0.005, "the meshes let the sun through: mean brightness %.4f" % seen.x)
	check(seen.y > 0.85 and seen.y < 1.15, "the impostors let it through as the meshes do: %.3f" % seen.y)
	check(seen.z < 0.7, "without the atlas they would be darker: %.3f" % seen.z)


## A 20 × 20 field of [param plant] (10 m square) in a stage with no ambient light and a black
## background, seen from [param eye] with a 15° view (the field fills the picture): all impostors,
## every plant as mesh 1, and all impostors with the plant's [param atlas] taken away (saved as
## [param name]_impostors, _meshes and _no_<atlas>.png). The sun shines, without shadows (a leaf's
## far face is lit through, not shaded by the leaf), when [param sun]; else it is off. Returns the
## meshes' mean brightness, and the impostors' with and without the atlas relative to it.
func _field_in_the_dark(plant: SunflowerPlant, eye: Vector3, atlas: String, sun: bool, name: String) -> Vector3:
	var stage: RefCounted = Stage.new(tree.root, 200.0, Vector3(5.0, 0.0, 5.0))
	stage.show_scenery(false)
	stage.environment.ambient_light_source = Environment.AMBIENT_SOURCE_COLOR
	stage.environment.ambient_light_color = Color.BLACK
	stage.environment.reflected_light_source = Environment.REFLECTION_SOURCE_DISABLED
	for light: Node in stage.root.find_children("*", "DirectionalLight3D", false, false):
		(light as DirectionalLight3D).visible = sun
		(light as DirectionalLight3D).shadow_enabled = false
	var field: SunflowerField = SunflowerField.new()
	field.plant = plant
	stage.root.add_child(field)
	field.map = Maps.filled(20, 20, "user://%s.field" % name)
	field.wind_power = 0.0
	field.finish_build()
	var camera: Camera3D = Camera3D.new()
	stage.root.add_child(camera)
	camera.make_current()
	camera.fov = 15.0
	camera.look_at_from_position(eye, Vector3(5.0, 1.0, 5.0))
	var brightness: Array[float] = []
	for step: int in 3:
		field.force_lod = 0 if step == 1 else -1
		if step == 2:
			plant.set("impostor_" + atlas, null)
		for i: int in 5:
			field.advance(1.0 / 60.0)
		await RenderingServer.frame_post_draw
		await RenderingServer.frame_post_draw
		var image: Image = tree.root.get_viewport().get_texture().get_image()
		image.save_png(artifact_path("%s_%s.png" % [name, ["impostors", "meshes", "no_" + atlas][step]]))
		brightness.append(_mean_luminance(image))
	stage.root.free()
	var meshes: float = maxf(brightness[1], 1e-6)
	return Vector3(brightness[1], brightness[0] / meshes, brightness[2] / meshes)


## The mean luminance of [param image].
func _mean_luminance(image: Image) -> float:
	var pixels: PackedFloat32Array = Picture.new(image.get_width(), image.get_height()).luminance(image)
	var sum: float = 0.0
	for value: float in pixels:
		sum += value
	return sum / maxf(pixels.size(), 1.0)


## A light brighter than the first range (energy 24 against 8, which clipped it to a third) is
## baked in the next one, 64, where it keeps its value; the field's far levels multiply it back.
func test_a_bright_glow_gets_a_wider_range() -> void:
	var plant: SunflowerPlant = await _glowing_plant("Bright plant", "bright_head.gltf", 24.0)
	if plant == null:
		return
	check_eq(plant.impostor_emission_range, 64.0, "the range widened once")
	_check_glow(plant, 24.0)
	var field: SunflowerField = SunflowerField.new()
	field.plant = plant
	tree.root.add_child(field)
	field.map = Maps.filled(4, 4, "user://bright.field")
	field.finish_build()
	var tile: MultiMeshInstance3D = null
	for node: Node in field.get_children(true):
		if node.name.begins_with("FarTile"):
			tile = node
	if check(tile != null, "a far tile"):
		var material: ShaderMaterial = tile.multimesh.mesh.surface_get_material(0) as ShaderMaterial
		check_eq(material.get_shader_parameter("emission_range"), 64.0, "the far levels multiply it back")
	field.free()


## Where a plain cut keeps less than half the views' cover: views of whole texels are not thin
## before their shapes blur at the coarse levels (−1: past ViewsMeasure.THIN_LATEST); views of one
## lit texel in each 2 × 2 are thin from half-way to level 1 (all cover at level 0, none kept at 1).
func test_the_bake_finds_where_a_plant_is_thin() -> void:
	var solid: Image = Image.create_empty(64, 64, false, Image.FORMAT_RGBA8)
	solid.fill_rect(Rect2i(16, 16, 32, 32), Color.WHITE)
	check_eq(
		ViewsMeasure.thin_from(ViewsMeasure.alpha_levels(solid)),
		-1.0,
		"a solid square: not thin before the far test is hashed"
	)
	var specks: Image = Image.create_empty(64, 64, false, Image.FORMAT_RGBA8)
	for y: int in range(0, 64, 2):
		for x: int in range(0, 64, 2):
			specks.set_pixel(x, y, Color.WHITE)
	check_near(
		ViewsMeasure.thin_from(ViewsMeasure.alpha_levels(specks)), 0.5, 0.01, "specks of a texel: thin from mip 0.5"
	)
	var sparse: Image = Image.create_empty(64, 64, false, Image.FORMAT_RGBA8)
	sparse.fill_rect(Rect2i(0, 0, 64, 64), Color(1.0, 1.0, 1.0, 0.3))
	check_eq(
		ViewsMeasure.thin_from(ViewsMeasure.alpha_levels(sparse)), 0.0, "texels a third covered: thin from the start"
	)
	# A thin plant's views are kept twice as fine (ImpostorBaker._read_views): the same specks a level
	# later, and measured so up to THIN_LATEST levels after the usual views' own.
	var fine: Image = specks.duplicate() as Image
	fine.resize(128, 128, Image.INTERPOLATE_NEAREST)
	check_near(ViewsMeasure.thin_from(ViewsMeasure.alpha_levels(fine), 1.0), 1.5, 0.01, "twice as fine: from 1.5")
	var cell: int = ImpostorBaker.CELL_PIXELS
	for side: int in [cell, 2 * cell]:
		var atlas: Image = Image.create_empty(
			SunflowerPlant.ATLAS_VIEWS.x * side, SunflowerPlant.ATLAS_VIEWS.y * side, false, Image.FORMAT_L8
		)
		check_eq(ViewsMeasure.finer_levels(atlas), 0.0 if side == cell else 1.0, "%d pixels a view" % side)
	var late: Image = Image.create_empty(64, 64, false, Image.FORMAT_RGBA8)  # squares of 8 texels, 16 apart
	for y: int in range(0, 64, 16):
		for x: int in range(0, 64, 16):
			late.fill_rect(Rect2i(x, y, 8, 8), Color.WHITE)
	var late_levels: Array[PackedInt32Array] = ViewsMeasure.alpha_levels(late)
	check_eq(ViewsMeasure.thin_from(late_levels), -1.0, "squares thin from 3.5: past the usual views' latest")
	check_near(ViewsMeasure.thin_from(late_levels, 1.0), 3.5, 0.01, "within twice-as-fine views' latest")


func test_views_are_drawn_in_tiles_as_large_as_the_triangle_budget_allows() -> void:
	var views: Vector2i = SunflowerPlant.ATLAS_VIEWS
	check_eq(ImpostorBaker.tile_of(216), views, "a grass clump: every view in one render")
	check_eq(ImpostorBaker.tile_of(8532), Vector2i(views.x, 5), "an 8 500-triangle bush: half the rows a render")
	check_eq(ImpostorBaker.tile_of(30000), Vector2i(views.x, 2), "two rows")
	check_eq(ImpostorBaker.tile_of(300000), Vector2i(3, 1), "a quarter of a row")
	check_eq(ImpostorBaker.tile_of(2000000), Vector2i(1, 1), "a huge plant: one view a render")
	# A plant of more than BAKE_TRIANGLES at level 1 is drawn from its finest level within them.
	var ball: SphereMesh = SphereMesh.new()
	ball.radial_segments = 320
	ball.rings = 200  # 128 000 triangles
	var heavy: ArrayMesh = ArrayMesh.new()
	heavy.add_surface_from_arrays(Mesh.PRIMITIVE_TRIANGLES, ball.get_mesh_arrays())
	var light: ArrayMesh = ArrayMesh.new()
	ball.radial_segments = 64
	ball.rings = 32
	light.add_surface_from_arrays(Mesh.PRIMITIVE_TRIANGLES, ball.get_mesh_arrays())
	var plant: SunflowerPlant = SunflowerPlant.new()
	plant.set_part_mesh(0, 0, heavy)
	plant.set_part_mesh(1, 0, heavy)
	plant.set_part_mesh(2, 0, light)
	check_eq(ImpostorBaker.bake_level(plant), 2, "128 000 triangles at levels 1 and 2: drawn from level 3")
	plant.set_part_mesh(1, 0, light)
	check_eq(ImpostorBaker.bake_level(plant), 1, "from level 2 when it is within the budget")
	check_eq(ImpostorBaker.bake_level(SunflowerPlant.default_plant()), 0, "the sunflower from level 1")
	# The sunflower drawn four views at a time (a third of a row: tiles that start and end within
	# rows) bakes the atlases it bakes in one render.
	var whole: SunflowerPlant = SunflowerPlant.default_plant().duplicate() as SunflowerPlant
	check_eq(await whole.bake_impostors(tree.root, FOLDER, "sunflower_whole"), OK)
	var tiled: SunflowerPlant = SunflowerPlant.default_plant().duplicate() as SunflowerPlant
	var four_views: int = 4 * tiled.triangle_count(ImpostorBaker.bake_level(tiled))
	ImpostorBaker.test_set_triangles_per_render(four_views)
	check_eq(ImpostorBaker.tile_of(four_views / 4), Vector2i(4, 1), "the sunflower's views four a render")
	check_eq(await tiled.bake_impostors(tree.root, FOLDER, "sunflower_tiled"), OK)
	ImpostorBaker.test_set_triangles_per_render(0)
	for kind: String in SunflowerPlant.IMPOSTOR_TEXTURES:
		var a: Image = (whole.get("impostor_" + kind) as Texture2D).get_image()
		var b: Image = (tiled.get("impostor_" + kind) as Texture2D).get_image()
		a.clear_mipmaps()
		b.clear_mipmaps()
		var differ: int = 0
		for y: int in a.get_height():
			for x: int in a.get_width():
				var p: Color = a.get_pixel(x, y)
				var q: Color = b.get_pixel(x, y)
				if absf(p.a - q.a) > 0.1 or absf(p.get_luminance() - q.get_luminance()) * minf(p.a, q.a) > 0.05:
					differ += 1
		var share: float = float(differ) / (a.get_width() * a.get_height())
		print("     tiled bake: %s differs from the one-render bake in %.2f %% of pixels" % [kind, share * 100.0])
		check(share < 0.005, "%s: four views at a time draw the same atlas (%.2f %% differ)" % [kind, share * 100.0])


func test_the_built_in_sunflower_baked_again_matches_the_shipped_textures() -> void:
	var plant: SunflowerPlant = SunflowerPlant.default_plant().duplicate() as SunflowerPlant
	var result: Error = await plant.bake_impostors(tree.root, FOLDER, "sunflower_again")
	check_eq(result, OK)
	for kind: String in SunflowerPlant.IMPOSTOR_TEXTURES:
		var shipped: Image = (SunflowerPlant.default_plant().get("impostor_" + kind) as Texture2D).get_image()
		var baked: Image = (plant.get("impostor_" + kind) as Texture2D).get_image()
		shipped.decompress()
		shipped.clear_mipmaps()
		baked.clear_mipmaps()
		shipped.convert(Image.FORMAT_RGBA8)
		check_eq(baked.get_size(), shipped.get_size(), "%s: the same frame" % kind)
		if baked.get_size() != shipped.get_size():
			continue
		var differ: int = 0
		var total: int = 0
		for y: int in range(0, baked.get_height(), 2):
			for x: int in range(0, baked.get_width(), 2):
				var a: Color = baked.get_pixel(x, y)
				var b: Color = shipped.get_pixel(x, y)
				total += 1
				if (a.a > 0.5) != (b.a > 0.5) or (a.a > 0.5 and absf(a.get_luminance() - b.get_luminance()) > 0.15):
					differ += 1
		var share: float = float(differ) / total
		print("     bake: %s differs from the shipped atlas in %.1f %% of pixels" % [kind, share * 100.0])
		check(share < 0.03, "%s: the baker reproduces the shipped atlas (%.1f %% differ)" % [kind, share * 100.0])
	# The alpha cuts it measures are the shipped plant's (tools/regenerate_assets.sh writes them there).
	var shipped_cuts: PackedFloat32Array = SunflowerPlant.default_plant().impostor_alpha_cuts
	check_eq(plant.impostor_alpha_cuts.size(), shipped_cuts.size(), "an alpha cut for each mip level, as shipped")
	for level: int in mini(plant.impostor_alpha_cuts.size(), shipped_cuts.size()):
		check_near(
			plant.impostor_alpha_cuts[level], shipped_cuts[level], 0.02, "the alpha cut at mip %d, as shipped" % level
		)
	# The sunflower is not thin before its far test is hashed anyway (its views cross at mip 3.8).
	check_eq(plant.impostor_thin_from, -1.0, "the sunflower is not thin from near")
	check_eq(SunflowerPlant.default_plant().impostor_thin_from, -1.0, "nor is the shipped one")
