extends TestCase
## Impostors baked in the engine: a plant of glTF parts gets front and side textures that are not
## empty and have the parts' colours; a field growing it draws them; the built-in sunflower baked
## again matches the textures the addon ships.

const FOLDER: String = "user://bake_test"
const RED: Color = Color(0.85, 0.1, 0.1)
const GREEN: Color = Color(0.1, 0.6, 0.15)


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


func test_a_gltf_plant_gets_impostors_in_its_own_colours() -> void:
	DirAccess.make_dir_recursive_absolute(FOLDER)
	var stalk: Mesh = _gltf_part(GREEN, Vector3(0.15, 1.0, 0.15), "stalk.gltf")
	var head: Mesh = _gltf_part(RED, Vector3(0.9, 1.0, 0.9), "head.gltf")
	if not check(stalk != null and head != null, "the glTF parts load"):
		return
	var plant: FieldPlant = FieldPlant.new()
	plant.name = "Red plant"
	plant.mesh_level_1 = [stalk, stalk, head]
	plant.height_units = 3.0
	var result: Error = await plant.bake_impostors(tree.root, FOLDER, "red_plant")
	check_eq(result, OK, "baked")
	for view: String in ["front", "side"]:
		check(FileAccess.file_exists(FOLDER.path_join("red_plant_%s.png" % view)), "%s texture written" % view)
	if not check(plant.front_texture != null and plant.side_texture != null, "the plant has its textures"):
		return
	check(plant.billboard_texture == plant.front_texture, "the billboard shows the front")
	for texture: Texture2D in [plant.front_texture, plant.side_texture]:
		var image: Image = texture.get_image()
		var measured: Array = _coverage(image)
		var share: float = measured[0]
		var colour: Color = measured[1]
		# The head is 0.9 of the 1.6 wide frame and one of 3 units tall; the stalks thin.
		check(share > 0.12 and share < 0.5, "the plant covers part of the frame (%.2f)" % share)
		check(colour.r > colour.g * 1.5 and colour.r > colour.b * 1.5, "mostly the head's red: %s" % colour)
		# The head's rows are red, the stalk's rows green: the parts stacked as the plant stands.
		var top: Color = image.get_pixel(image.get_width() / 2, image.get_height() / 6)
		var low: Color = image.get_pixel(image.get_width() / 2, image.get_height() * 5 / 6)
		check(top.r > 0.6 and top.g < 0.3, "the head at the top is red: %s" % top)
		check(low.g > low.r and low.a > 0.5, "the stalk below is green: %s" % low)
	# A field growing the plant draws the baked textures.
	var field: SunflowerField = SunflowerField.new()
	field.plant = plant
	tree.root.add_child(field)
	check(field.sprite_front_texture == plant.front_texture, "the field draws them")
	field.free()


func test_the_built_in_sunflower_baked_again_matches_the_shipped_textures() -> void:
	var plant: FieldPlant = FieldPlant.default_plant().duplicate() as FieldPlant
	var result: Error = await plant.bake_impostors(tree.root, FOLDER, "sunflower_again")
	check_eq(result, OK)
	for view: String in ["front", "side"]:
		var shipped: Image = (FieldPlant.default_plant().get(view + "_texture") as Texture2D).get_image()
		var baked: Image = (plant.get(view + "_texture") as Texture2D).get_image()
		shipped.decompress()
		shipped.convert(Image.FORMAT_RGBA8)
		check_eq(baked.get_size(), shipped.get_size(), "%s: the same frame" % view)
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
		print("     bake: %s differs from the shipped texture in %.1f %% of pixels" % [view, share * 100.0])
		check(share < 0.03, "%s: the baker reproduces the shipped texture (%.1f %% differ)" % [view, share * 100.0])
