extends TestCase
## A catalogue of odd plant scenes, built here, each through SunflowerPlant.from_scene: drawn as the
## editor shows it (top_level nodes where they stand, MultiMesh instances as parts, blend shapes at
## their weights, Godot's visibility-range levels of detail as mesh levels), or refused or warned
## about with a message naming the node and the reason (nothing with area, non-finite positions,
## a gap in the LOD suffixes, nodes it does not read, a plant below its root); a skinned mesh in its
## skeleton's pose.
## Needs a renderer (the engine suite): a MultiMesh keeps its instances in the rendering server,
## which --headless does not keep.

const ScenePlant: GDScript = preload("res://addons/sunflower_field/plant/scene_plant.gd")
const Scenes: GDScript = preload("res://runner/scenes.gd")


func _box_node(node_name: String, size: Vector3, position: Vector3) -> MeshInstance3D:
	var box: BoxMesh = BoxMesh.new()
	box.size = size
	var instance: MeshInstance3D = MeshInstance3D.new()
	instance.name = node_name
	instance.mesh = box
	instance.position = position
	return instance


func _root() -> Node3D:
	var root: Node3D = Node3D.new()
	root.name = "Plant"
	return root


func test_a_top_level_node_stands_where_it_stands_not_where_its_parent_is() -> void:
	var root: Node3D = _root()
	var holder: Node3D = Node3D.new()
	holder.name = "Holder"
	holder.position = Vector3(0.0, 5.0, 0.0)
	root.add_child(holder)
	var free: MeshInstance3D = _box_node("Free", Vector3(0.4, 2.0, 0.4), Vector3(0.0, 1.0, 0.0))
	free.top_level = true
	holder.add_child(free)
	var plant: SunflowerPlant = SunflowerPlant.from_scene(Scenes.packed(root))
	if check(plant != null, "a plant"):
		check_near(plant.height, 2.0, 1e-3, "2 m tall from the root, as the top_level box stands (not 7 m)")


## (Run by both suites: with a renderer the instances are read; headless, where the renderer keeps no
## instance transforms, they are named and left out, not taken as three leaves at the root.) An
## instance's own colour, which a field's plant cannot carry, is named where its material shows it.
func test_multimesh_instances_are_parts_of_the_plant() -> void:
	var root: Node3D = _root()
	root.add_child(_box_node("Trunk", Vector3(0.2, 2.0, 0.2), Vector3(0.0, 1.0, 0.0)))
	var leaves: MultiMeshInstance3D = MultiMeshInstance3D.new()
	leaves.name = "Leaves"
	var multimesh: MultiMesh = MultiMesh.new()
	multimesh.transform_format = MultiMesh.TRANSFORM_3D
	multimesh.use_colors = true
	var leaf: QuadMesh = QuadMesh.new()
	leaf.size = Vector2(0.3, 0.3)
	leaf.material = StandardMaterial3D.new()
	(leaf.material as StandardMaterial3D).vertex_color_use_as_albedo = true  # shows instance colours
	multimesh.mesh = leaf
	multimesh.instance_count = 3
	for k: int in 3:
		multimesh.set_instance_transform(k, Transform3D(Basis(), Vector3(0.5 * (k - 1), 2.5 + 0.3 * k, 0.0)))
		multimesh.set_instance_color(k, Color.WHITE if k != 1 else Color.RED)
	leaves.multimesh = multimesh
	root.add_child(leaves)
	var plant: SunflowerPlant = SunflowerPlant.from_scene(Scenes.packed(root))
	if not check(plant != null, "a plant"):
		return
	if multimesh.buffer.is_empty():  # --headless: the renderer kept no transforms, read as identity once
		var warnings: String = "\n".join(take_warnings())
		check(warnings.contains("Leaves: this run's renderer keeps no MultiMesh instance transforms"), warnings)
		check_near(plant.height, 2.0, 1e-3, "the trunk alone, as the warning says")
		return
	var trunk: int = ScenePlant.triangle_count(BoxMesh.new())
	check_eq(ScenePlant.triangle_count(plant.mesh_level_1[0]), trunk + 3 * 2, "the trunk and three leaf quads")
	check_near(plant.height, 2.5 + 0.6 + 0.15, 1e-3, "as tall as the highest leaf instance")
	check(warned("Leaves: its instances' own colours are not carried"), "the red instance's colour is named as lost")
	# Colours a material does not show (no vertex colours as albedo) are not lost: nothing is said.
	(leaf.material as StandardMaterial3D).vertex_color_use_as_albedo = false
	var unshown: Node3D = _root()
	var copy: MultiMeshInstance3D = MultiMeshInstance3D.new()
	copy.name = "Leaves"
	copy.multimesh = multimesh
	unshown.add_child(copy)
	check(
		SunflowerPlant.from_scene(Scenes.packed(unshown)) != null, "a plant of the same leaves, their colours unshown"
	)
	check(not warned("own colours are not carried"), "colours its material does not show are not named")


func test_visibility_range_variants_are_mesh_levels() -> void:
	var root: Node3D = _root()
	var detailed: MeshInstance3D = MeshInstance3D.new()
	detailed.name = "Detailed"
	var sphere: SphereMesh = SphereMesh.new()
	detailed.mesh = sphere
	detailed.visibility_range_end = 20.0
	root.add_child(detailed)
	var simple: MeshInstance3D = _box_node("Simple", Vector3.ONE, Vector3.ZERO)
	simple.visibility_range_begin = 20.0
	root.add_child(simple)
	var made: Dictionary = ScenePlant.levels_of(Scenes.packed(root))
	check(not made.generated, "levels from the scene, not simplified")
	check_eq(made.triangles[0], ScenePlant.triangle_count(SphereMesh.new()), "mesh 1: the detailed variant alone")
	check_eq(made.triangles[1], ScenePlant.triangle_count(BoxMesh.new()), "mesh 2: the simple one alone")


func test_blend_shapes_are_taken_at_the_nodes_weights() -> void:
	var arrays: Array = []
	arrays.resize(Mesh.ARRAY_MAX)
	arrays[Mesh.ARRAY_VERTEX] = PackedVector3Array([Vector3(-0.5, 0, 0), Vector3(0.5, 0, 0), Vector3(0, 1, 0)])
	var stretched: Array = []
	stretched.resize(Mesh.ARRAY_MAX)
	stretched[Mesh.ARRAY_VERTEX] = PackedVector3Array([Vector3(-0.5, 0, 0), Vector3(0.5, 0, 0), Vector3(0, 3, 0)])
	var mesh: ArrayMesh = ArrayMesh.new()
	mesh.add_blend_shape("Tall")
	mesh.add_surface_from_arrays(Mesh.PRIMITIVE_TRIANGLES, arrays, [stretched])
	var root: Node3D = _root()
	var instance: MeshInstance3D = MeshInstance3D.new()
	instance.name = "Blade"
	instance.mesh = mesh
	instance.set_blend_shape_value(0, 1.0)
	root.add_child(instance)
	var plant: SunflowerPlant = SunflowerPlant.from_scene(Scenes.packed(root))
	if check(plant != null, "a plant"):
		check_near(plant.height, 3.0, 1e-3, "3 m tall, as its blend shape at weight 1 shows it (the base is 1 m)")


func test_a_scene_that_draws_nothing_with_area_is_refused_naming_why() -> void:
	var root: Node3D = _root()
	var flat: MeshInstance3D = _box_node("Squashed", Vector3.ONE, Vector3(0.0, 0.5, 0.0))
	flat.scale = Vector3.ZERO
	root.add_child(flat)
	allow_error("draws no triangle with area")
	check(SunflowerPlant.from_scene(Scenes.packed(root)) == null, "no plant of a mesh scaled to nothing")


func test_non_finite_positions_are_named_by_node_and_surface() -> void:
	var arrays: Array = []
	arrays.resize(Mesh.ARRAY_MAX)
	arrays[Mesh.ARRAY_VERTEX] = PackedVector3Array([Vector3(0, 0, 0), Vector3(1, 0, 0), Vector3(0, NAN, 0)])
	var broken: ArrayMesh = ArrayMesh.new()
	broken.add_surface_from_arrays(Mesh.PRIMITIVE_TRIANGLES, arrays)
	var root: Node3D = _root()
	root.add_child(_box_node("Trunk", Vector3(0.2, 2.0, 0.2), Vector3(0.0, 1.0, 0.0)))
	var instance: MeshInstance3D = MeshInstance3D.new()
	instance.name = "Broken"
	instance.mesh = broken
	root.add_child(instance)
	var plant: SunflowerPlant = SunflowerPlant.from_scene(Scenes.packed(root))
	check(plant != null, "a plant of the rest")
	check(warned("Broken: surface 0 has 1 vertex positions that are not finite"), "the node and surface named")
	if plant:
		check_near(plant.height, 2.0, 1e-3, "the broken surface left out, not stretching the plant")


func test_a_gap_in_the_lod_suffixes_is_named() -> void:
	var root: Node3D = _root()
	root.add_child(_box_node("Bush_LOD1", Vector3(1.0, 1.0, 1.0), Vector3(0.0, 0.5, 0.0)))
	root.add_child(_box_node("Bush_LOD2", Vector3(1.0, 0.5, 1.0), Vector3(0.0, 0.25, 0.0)))
	var plant: SunflowerPlant = SunflowerPlant.from_scene(Scenes.packed(root))
	check(warned("no _LOD0: _LOD1 is taken as mesh level 1"), "the missing _LOD0 named")
	if check(plant != null, "a plant of the variants there are"):
		check_near(plant.height, 1.0, 1e-3, "mesh 1 is Bush_LOD1")
		check_near(plant.mesh_level_2[0].get_aabb().size.y, 0.5, 1e-3, "mesh 2 is Bush_LOD2")


func test_nodes_it_does_not_read_are_named() -> void:
	var root: Node3D = _root()
	root.add_child(_box_node("Trunk", Vector3(0.2, 2.0, 0.2), Vector3(0.0, 1.0, 0.0)))
	var sprite: Sprite3D = Sprite3D.new()
	sprite.name = "Flower"
	root.add_child(sprite)
	var crown: CSGSphere3D = CSGSphere3D.new()
	crown.name = "Crown"
	root.add_child(crown)
	var plant: SunflowerPlant = SunflowerPlant.from_scene(Scenes.packed(root))
	check(plant != null, "a plant of what it reads")
	var warnings: String = "\n".join(take_warnings())
	check(warnings.contains("Flower: a Sprite3D is not read"), "the sprite named, with the reason")
	# The engine makes a CSG shape's mesh only in the scene tree: named, not dropped in silence.
	check(warnings.contains("Crown: the CSG shape gives no mesh outside the scene tree"), "the CSG shape named")


## What a node shows beyond its meshes and materials is named, not dropped or drawn in silence: a
## shadow proxy (a 3 m box that only casts a shadow) is left out, the plant as tall as its 2 m trunk;
## a material overlay, a node's transparency and a shadow it does not cast are named as not carried; a
## light is named as left out.
func test_what_a_plant_cannot_carry_from_a_node_is_named() -> void:
	var root: Node3D = _root()
	root.add_child(_box_node("Trunk", Vector3(0.2, 2.0, 0.2), Vector3(0.0, 1.0, 0.0)))
	var proxy: MeshInstance3D = _box_node("ShadowProxy", Vector3(1.0, 3.0, 1.0), Vector3(0.0, 1.5, 0.0))
	proxy.cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_SHADOWS_ONLY
	root.add_child(proxy)
	var crown: MeshInstance3D = _box_node("Crown", Vector3(1.0, 0.5, 1.0), Vector3(0.0, 1.5, 0.0))
	crown.material_overlay = StandardMaterial3D.new()
	crown.transparency = 0.5
	crown.cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF
	root.add_child(crown)
	var lamp: OmniLight3D = OmniLight3D.new()
	lamp.name = "Lamp"
	root.add_child(lamp)
	var plant: SunflowerPlant = SunflowerPlant.from_scene(Scenes.packed(root))
	if not check(plant != null, "a plant of the trunk and the crown"):
		return
	check_near(plant.height, 2.0, 1e-3, "as tall as the trunk: the 3 m shadow proxy is not drawn")
	var box: int = ScenePlant.triangle_count(BoxMesh.new())
	check_eq(ScenePlant.triangle_count(plant.mesh_level_1[0]), 2 * box, "the trunk and the crown, not the proxy")
	var warnings: String = "\n".join(take_warnings())
	for expected: String in [
		"ShadowProxy: it only casts a shadow (a shadow proxy); left out",
		"Crown: its material_overlay is not carried",
		"Crown: its transparency (0.50) is not carried",
		"Crown: it casts no shadow in the scene",
		"Lamp: a OmniLight3D is not carried into a field's plants; left out",
	]:
		check(warnings.contains(expected), "named: %s (%s)" % [expected, warnings])


## A skinned mesh (as glTF plants with an armature for wind come) in the pose its skeleton holds:
## a 1 m box bound to one bone posed 1 m up makes a plant 2 m tall (unposed: 1 m).
func test_a_skinned_mesh_is_taken_in_its_pose() -> void:
	var root: Node3D = _root()
	var skeleton: Skeleton3D = Skeleton3D.new()
	skeleton.name = "Armature"
	skeleton.add_bone("Root")
	skeleton.set_bone_pose_position(0, Vector3(0.0, 1.0, 0.0))
	root.add_child(skeleton)
	var arrays: Array = BoxMesh.new().get_mesh_arrays()
	var count: int = (arrays[Mesh.ARRAY_VERTEX] as PackedVector3Array).size()
	var positions: PackedVector3Array = arrays[Mesh.ARRAY_VERTEX]
	for k: int in count:
		positions[k] += Vector3(0.0, 0.5, 0.0)  # standing on the root
	arrays[Mesh.ARRAY_VERTEX] = positions
	var bones: PackedInt32Array = []
	var weights: PackedFloat32Array = []
	for k: int in count:
		bones.append_array(PackedInt32Array([0, 0, 0, 0]))
		weights.append_array(PackedFloat32Array([1.0, 0.0, 0.0, 0.0]))
	arrays[Mesh.ARRAY_BONES] = bones
	arrays[Mesh.ARRAY_WEIGHTS] = weights
	var body: ArrayMesh = ArrayMesh.new()
	body.add_surface_from_arrays(Mesh.PRIMITIVE_TRIANGLES, arrays)
	var skinned: MeshInstance3D = MeshInstance3D.new()
	skinned.name = "Body"
	skinned.mesh = body
	skinned.skeleton = NodePath("..")
	skeleton.add_child(skinned)
	var plant: SunflowerPlant = SunflowerPlant.from_scene(Scenes.packed(root))
	if check(plant != null, "a plant"):
		check_near(plant.height, 2.0, 1e-3, "2 m tall, as its bone's pose shows it")


func test_a_plant_wholly_below_its_root_is_warned_about() -> void:
	var root: Node3D = _root()
	root.add_child(_box_node("Sunk", Vector3(1.0, 2.0, 1.0), Vector3(0.0, -4.0, 0.0)))
	var plant: SunflowerPlant = SunflowerPlant.from_scene(Scenes.packed(root))
	check(plant != null, "a plant, as the scene has it")
	check(warned("stands wholly below its root"), "with what to fix")


## A part whose material the plant material cannot draw is named, with what keeps it and what
## follows (drawn as it is, without the levels' cross-fades, the plant part by part): a
## StandardMaterial3D with a setting the plant material does not carry (rim), one that blends its
## alpha, and a shader of your own the field cannot bend as one plant (world_vertex_coords); a plant of
## carried materials (alpha scissor, alpha hash, none) is not warned about. (Such a
## plant leaned in the wind as one piece without a word.)
func test_a_material_the_plant_material_cannot_draw_is_named() -> void:
	var rim: StandardMaterial3D = StandardMaterial3D.new()
	rim.resource_name = "Shiny bark"
	rim.rim_enabled = true
	var blended: StandardMaterial3D = Scenes.holed_leaves()
	blended.resource_name = "Glassy leaves"
	blended.transparency = BaseMaterial3D.TRANSPARENCY_ALPHA
	var hashed: StandardMaterial3D = Scenes.holed_leaves()
	hashed.transparency = BaseMaterial3D.TRANSPARENCY_ALPHA_HASH
	var worldly: ShaderMaterial = Scenes.shader_material(
		"shader_type spatial;\nrender_mode world_vertex_coords;\nvoid fragment() { ALBEDO = vec3(0.2, 0.5, 0.1); }\n",
		"World leaves"
	)
	for case: Array in [[rim, blended, worldly], [Scenes.holed_leaves(), hashed, null]]:
		var root: Node3D = _root()
		for k: int in case.size():
			var node: MeshInstance3D = _box_node("Part%d" % k, Vector3(0.4, 1.0, 0.4), Vector3(0.0, 0.5 + k, 0.0))
			node.material_override = case[k]
			root.add_child(node)
		check(SunflowerPlant.from_scene(Scenes.packed(root)) != null, "a plant, as the scene has it")
		var named: PackedStringArray = take_warnings()
		var kept: PackedStringArray = Array(named).filter(
			func(warning: String) -> bool: return warning.contains("as it is, without the levels' cross-fades")
		)
		if case[0] == rim:
			check(
				Array(kept).any(
					func(w: String) -> bool: return w.contains("'Shiny bark'") and w.contains("rim_enabled")
				),
				"the rim material named, and its setting (%s)" % "; ".join(kept)
			)
			check(
				Array(kept).any(func(w: String) -> bool: return w.contains("'Glassy leaves'") and w.contains("blends")),
				"the blended material named (%s)" % "; ".join(kept)
			)
			check(
				Array(named).any(
					func(w: String) -> bool: return w.contains("'World leaves'") and w.contains("world_vertex_coords")
				),
				"the shader the field cannot bend named (%s)" % "; ".join(named)
			)
		else:
			check(kept.is_empty(), "carried materials are not named (%s)" % "; ".join(kept))


## A scene whose meshes stand off to the side of its root (modelled away from the origin, as a mesh
## taken out of a larger layout can be) is made a plant, as the scene has it, with a warning saying
## what to fix: its plants would stand off their cells, and its width, from the root, sets their
## spacing (a 1 m box 20 m off became a plant 41 m wide without a word). A plant leaning over its
## root, its base at the root, is not warned about.
func test_a_plant_off_to_the_side_of_its_root_is_warned_about() -> void:
	var aside: Node3D = _root()
	aside.add_child(_box_node("Aside", Vector3(1.0, 2.0, 1.0), Vector3(20.0, 1.0, 0.0)))
	check(SunflowerPlant.from_scene(Scenes.packed(aside)) != null, "a plant, as the scene has it")
	check(warned("from its root across the ground"), "with what to fix")
	var leaning: Node3D = _root()
	var trunk: MeshInstance3D = _box_node("Trunk", Vector3(0.3, 4.0, 0.3), Vector3(1.0, 1.9, 0.0))
	trunk.rotation = Vector3(0.0, 0.0, -0.5)  # its foot at the root, its top 2 m over
	leaning.add_child(trunk)
	check(SunflowerPlant.from_scene(Scenes.packed(leaning)) != null, "a leaning plant")
	check(not warned("from its root across the ground"), "a plant leaning over its root is not warned about")


## Instance shader parameters a scene's nodes set (instance_shader_parameters/…) are the plant's:
## the field gives them to every node that draws its meshes, so a part tinted by its node is drawn
## in that tint (a shader whose default tint is red, the nodes' green); a node that sets another
## value is named, and the first node's value kept.
func test_instance_shader_parameters_are_carried_to_the_field() -> void:
	var shader: Shader = Shader.new()
	shader.code = "shader_type spatial;\nrender_mode unshaded;\n"
	shader.code += "instance uniform vec4 tint : source_color = vec4(1.0, 0.0, 0.0, 1.0);\n"
	shader.code += "void fragment() {\n\tALBEDO = tint.rgb;\n}\n"
	var material: ShaderMaterial = ShaderMaterial.new()
	material.shader = shader
	var root: Node3D = _root()
	var green: Color = Color(0.0, 1.0, 0.0, 1.0)
	for part: int in 2:
		var node: MeshInstance3D = _box_node("Part%d" % part, Vector3(0.6, 1.0, 0.6), Vector3(0.0, 0.5 + part, 0.0))
		node.material_override = material
		node.set_instance_shader_parameter(&"tint", green)
		root.add_child(node)
	var plant: SunflowerPlant = SunflowerPlant.from_scene(Scenes.packed(root.duplicate()))
	if not check(plant != null, "a plant"):
		root.free()
		return
	check_eq(plant.instance_shader_parameters, {"tint": green}, "the nodes' tint is the plant's")
	var odd: MeshInstance3D = _box_node("Odd", Vector3(0.3, 0.3, 0.3), Vector3(0.0, 2.2, 0.0))
	odd.material_override = material
	odd.set_instance_shader_parameter(&"tint", Color(0.0, 0.0, 1.0, 1.0))
	root.add_child(odd)
	take_warnings()
	var mixed: SunflowerPlant = SunflowerPlant.from_scene(Scenes.packed(root))
	var warnings: String = "\n".join(take_warnings())
	check(warnings.contains("Odd: its instance shader parameter 'tint'"), "the odd node is named: %s" % warnings)
	check_eq(mixed.instance_shader_parameters, {"tint": green}, "the first node's value kept")
	var field: SunflowerField = SunflowerField.new()
	field.plant = plant
	field.map = SunflowerFieldMap.new()
	field.map.source_path = "user://tinted.field"
	field.map.text = "1 1\n*\n".to_utf8_buffer()
	field.wind_power = 0.0
	field.force_lod = SunflowerField.Lod.MESH_1
	tree.root.add_child(field)
	field.finish_build()
	var nodes: Array[Node] = field.find_children("Mesh*", "MultiMeshInstance3D", true, false)
	check(not nodes.is_empty(), "near mesh nodes")
	check(
		nodes.all(
			func(n: Node) -> bool: return (n as GeometryInstance3D).get_instance_shader_parameter(&"tint") == green
		),
		"every near mesh node draws with the tint"
	)
	if DisplayServer.get_name() == "headless":
		print("     (headless: nothing drawn to look at; the engine suite checks the picture)")
		field.free()
		return
	var camera: Camera3D = Camera3D.new()
	tree.root.add_child(camera)
	camera.look_at_from_position(
		field.get_plant_info(0)["position"] + Vector3(0.0, 1.0, 4.0),
		field.get_plant_info(0)["position"] + Vector3(0.0, 1.0, 0.0)
	)
	camera.make_current()
	field.advance(0.0)
	await frames(3)
	var image: Image = tree.root.get_viewport().get_texture().get_image()
	image.save_png(artifact_path("scene_import_tinted.png"))
	var counts: Vector2i = Vector2i.ZERO  # (green, red) pixels
	for y: int in range(0, image.get_height(), 2):
		for x: int in range(0, image.get_width(), 2):
			var pixel: Color = image.get_pixel(x, y)
			counts.x += 1 if pixel.g > 0.8 and pixel.r < 0.2 and pixel.b < 0.2 else 0
			counts.y += 1 if pixel.r > 0.8 and pixel.g < 0.2 and pixel.b < 0.2 else 0
	print("     the tinted plant: %d green pixels, %d red (every fourth pixel)" % [counts.x, counts.y])
	check(
		counts.x > 100 and counts.y == 0,
		"the plant is drawn green, not its shader's red (%d, %d)" % [counts.x, counts.y]
	)
	camera.free()
	field.free()


## A shader of your own that reads model-space positions, on a node moved, turned and scaled in the
## scene, looks as in the scene (#60 item 3): the merge puts the node's transform into the plant's
## vertices, and the part is drawn by a copy of the shader that takes them back into the node's space
## and whose node matrices are the plant's times the node's. The test shader colours by the height
## its vertex() gives MODEL_MATRIX × VERTEX against 1.5 m, and red where NODE_POSITION_WORLD is not
## the node's place 1.5 m up: the lone plant drawn at mesh 1, its root at the origin, shows the same
## share of the two colours as the scene drawn plainly and no red (VERTEX alone carried: all of the
## lower colour). A shader reading the model matrix on a second moved node is carried too.
func test_a_shader_reading_positions_on_a_moved_node_sees_the_nodes_space() -> void:
	var by_height: ShaderMaterial = Scenes.shader_material(
		(
			"shader_type spatial;\nrender_mode unshaded;\nvarying float h;\n"
			+ "void vertex() {\n\th = (MODEL_MATRIX * vec4(VERTEX, 1.0)).y - 1.5;\n}\n"
			+ "void fragment() {\n\tALBEDO = h > 0.0 ? vec3(1.0, 0.9, 0.0) : vec3(0.0, 0.2, 1.0);\n"
			+ "\tALBEDO = abs(NODE_POSITION_WORLD.y - 1.5) > 0.2 ? vec3(1.0, 0.0, 0.0) : ALBEDO;\n}\n"
		)
	)
	var root: Node3D = _root()
	var leaves: MeshInstance3D = _box_node("Leaves", Vector3(1.0, 1.0, 1.0), Vector3(0.0, 1.5, 0.0))
	leaves.scale = Vector3.ONE * 0.8
	leaves.rotation.y = 0.3
	leaves.material_override = by_height
	root.add_child(leaves)
	var plant: SunflowerPlant = SunflowerPlant.from_scene(Scenes.packed(root.duplicate()))
	if not check(plant != null, "a plant"):
		root.free()
		return
	check(not "\n".join(take_warnings()).contains("Leaves:"), "a shader reading positions is carried, not warned about")
	var drawn: Material = plant.get_part_mesh(0, 0).surface_get_material(0)
	check(
		drawn is ShaderMaterial and (drawn as ShaderMaterial).shader.code.contains("plant_node_inverse"),
		"the leaves are drawn by a copy that sees the node's space"
	)
	var by_matrix: ShaderMaterial = Scenes.shader_material(
		(
			"shader_type spatial;\nvarying float h;\nvoid vertex() {\n\th = MODEL_MATRIX[3].y;\n}\n"
			+ "void fragment() {\n\tALBEDO = vec3(h);\n}\n"
		)
	)
	var stone: MeshInstance3D = _box_node("Stone", Vector3(0.3, 0.3, 0.3), Vector3(0.5, 0.15, 0.0))
	stone.material_override = by_matrix
	var named_root: Node3D = root.duplicate()
	named_root.add_child(stone)
	SunflowerPlant.from_scene(Scenes.packed(named_root))
	var warnings: String = "\n".join(take_warnings())
	check(not warnings.contains("Stone:") and not warnings.contains("Leaves:"), "both shaders carried: %s" % warnings)
	if DisplayServer.get_name() == "headless":
		print("     (headless: nothing drawn to look at; the engine suite checks the picture)")
		root.free()
		return
	var camera: Camera3D = Camera3D.new()
	tree.root.add_child(camera)
	camera.look_at_from_position(Vector3(0.0, 1.5, 4.0), Vector3(0.0, 1.5, 0.0))
	camera.make_current()
	tree.root.add_child(root)
	await frames(3)
	var scene_share: float = _lower_colour_share(tree.root.get_viewport().get_texture().get_image())
	root.free()
	var field: SunflowerField = SunflowerField.new()
	plant.scale_min = 1.0
	plant.scale_max = 1.0
	plant.yaw_range = 0.0
	plant.middle_variation = 0.0
	field.plant = plant
	field.map = SunflowerFieldMap.new()
	field.map.source_path = "user://node_space.field"
	field.map.text = "1 1\n*\n".to_utf8_buffer()
	field.cell_size = 1.0
	field.wind_power = 0.0
	field.force_lod = SunflowerField.Lod.MESH_1
	tree.root.add_child(field)
	field.finish_build()
	field.position = -field.get_plant_info(0)["position"]
	field.advance(0.0)
	await frames(3)
	var image: Image = tree.root.get_viewport().get_texture().get_image()
	image.save_png(artifact_path("scene_import_node_space.png"))
	var plant_share: float = _lower_colour_share(image)
	print("     the lower colour's share: %.2f of the scene's leaves, %.2f of the plant's" % [scene_share, plant_share])
	check(scene_share > 0.3, "the scene shows both colours (%.2f)" % scene_share)
	check_near(plant_share, scene_share, 0.1, "the plant's leaves are coloured as the scene's")
	camera.free()
	field.free()


## The share of the lower (blue) colour among the pixels of either of the test shader's colours.
func _lower_colour_share(image: Image) -> float:
	var counts: Vector2 = Vector2.ZERO  # (upper, lower)
	for y: int in range(0, image.get_height(), 2):
		for x: int in range(0, image.get_width(), 2):
			var pixel: Color = image.get_pixel(x, y)
			counts.x += 1.0 if pixel.r > 0.8 and pixel.g > 0.7 and pixel.b < 0.3 else 0.0
			counts.y += 1.0 if pixel.b > 0.8 and pixel.r < 0.2 else 0.0
	return counts.y / maxf(counts.x + counts.y, 1.0)


## A surface of positions alone (a mesh made in code) gets tangents in the plant's meshes, drawn in
## levels or whole (and a part of such a surface drawn whole): the plant's shaders bend TANGENT, and
## the engine warned at every draw of a plant mesh without them (23 times in one run of the levels
## test, whose card bush has no normals). The engine gives a surface with normals a tangent itself.
func test_a_surface_without_normals_gets_tangents_in_the_plant() -> void:
	var blade: Array = []
	blade.resize(Mesh.ARRAY_MAX)
	blade[Mesh.ARRAY_VERTEX] = PackedVector3Array([Vector3(-0.1, 0, 0), Vector3(0.1, 0, 0), Vector3(0, 1, 0)])
	var mesh: ArrayMesh = ArrayMesh.new()
	mesh.add_surface_from_arrays(Mesh.PRIMITIVE_TRIANGLES, blade)
	mesh.surface_set_material(0, StandardMaterial3D.new())
	var root: Node3D = _root()
	var instance: MeshInstance3D = MeshInstance3D.new()
	instance.name = "Blade"
	instance.mesh = mesh
	root.add_child(instance)
	var plant: SunflowerPlant = SunflowerPlant.from_scene(Scenes.packed(root))
	if not check(plant != null, "a plant"):
		return
	var meshes: Dictionary = {}  # each mesh level, and the mesh it is drawn whole with
	for level: int in 3:
		meshes["mesh %d" % (level + 1)] = plant.get("mesh_level_%d" % (level + 1))[0]
		meshes["mesh %d drawn whole" % (level + 1)] = plant.whole_mesh(level)
	var own: SunflowerPlant = SunflowerPlant.new()  # the blade given as a part, not by a scene
	own.mesh_level_1 = [mesh, null, null]
	meshes["a part of positions alone drawn whole"] = own.whole_mesh(0)
	for what: String in meshes:
		var drawn: Mesh = meshes[what]
		if not check(drawn != null, "%s is made" % what):
			continue
		for surface: int in drawn.get_surface_count():
			var arrays: Array = drawn.surface_get_arrays(surface)
			var count: int = (arrays[Mesh.ARRAY_VERTEX] as PackedVector3Array).size()
			var tangents: Variant = arrays[Mesh.ARRAY_TANGENT]
			if not check(
				tangents != null and (tangents as PackedFloat32Array).size() == 4 * count,
				"%s, surface %d: a tangent for each of its %d vertices" % [what, surface, count]
			):
				continue
			var least: float = INF
			for k: int in count:
				least = minf(least, Vector3(tangents[4 * k], tangents[4 * k + 1], tangents[4 * k + 2]).length())
			check_near(least, 1.0, 0.01, "%s, surface %d: unit tangents" % [what, surface])


## The scene root's own rotation and scale are the plant's, as the editor shows the scene (and as an
## instance of it starts): a model turned upright by its root (modelled Z-up) stands up, one scaled by
## its root (an import in centimetres, its root scaled 0.01) has its size; the root's origin is the
## plant's root, wherever the root stands (a top_level node's place is measured from it). (Taken
## without the root's transform, the first plant was 0.2 m tall, lying down, the second 200 m.)
func test_the_scene_roots_rotation_and_scale_are_the_plants() -> void:
	var upright: Node3D = _root()
	upright.rotation = Vector3(-PI / 2.0, 0.0, 0.0)  # +Z up in the model, +Y up in the scene
	upright.position = Vector3(5.0, 2.0, 0.0)
	upright.add_child(_box_node("Trunk", Vector3(0.4, 0.4, 3.0), Vector3(0.0, 0.0, 1.5)))
	var in_centimetres: Node3D = _root()
	in_centimetres.scale = Vector3(0.01, 0.01, 0.01)
	in_centimetres.add_child(_box_node("Trunk", Vector3(40.0, 200.0, 40.0), Vector3(0.0, 100.0, 0.0)))
	for case: Array in [["a root turned upright", upright, 3.0, 0.4], ["a root scaled 0.01", in_centimetres, 2.0, 0.4]]:
		var plant: SunflowerPlant = SunflowerPlant.from_scene(Scenes.packed(case[1]))
		if not check(plant != null, "%s: a plant" % case[0]):
			continue
		var box: AABB = plant.mesh_level_1[0].get_aabb()
		check_near(plant.height, case[2], 1e-3, "%s: the plant's height" % case[0])
		check_near(box.position.y, 0.0, 1e-3, "%s: its base at its root" % case[0])
		check_near(box.size.x, case[3], 1e-3, "%s: its width" % case[0])
	# A top_level node stands where it stands, measured from the root's origin.
	var moved: Node3D = _root()
	moved.position = Vector3(5.0, 1.0, 0.0)
	var free: MeshInstance3D = _box_node("Free", Vector3(0.4, 2.0, 0.4), Vector3(5.0, 2.0, 0.0))
	free.top_level = true
	moved.add_child(free)
	var standing: SunflowerPlant = SunflowerPlant.from_scene(Scenes.packed(moved))
	if check(standing != null, "a root moved, a top_level node: a plant"):
		var box: AABB = standing.mesh_level_1[0].get_aabb()
		check_near(box.get_center().x, 0.0, 1e-3, "a top_level node 5 m along, as its root: at the plant's root")
		check_near(box.position.y, 0.0, 1e-3, "a top_level node from 1 m up, as its root: its base at the root")
	# A root that is no Node3D has no place: a top_level node below it stands where it stands.
	var plain_root: Node = Node.new()
	plain_root.name = "Plant"
	var alone: MeshInstance3D = _box_node("Alone", Vector3(0.4, 2.0, 0.4), Vector3(0.0, 1.0, 0.0))
	alone.top_level = true
	plain_root.add_child(alone)
	var under_node: SunflowerPlant = SunflowerPlant.from_scene(Scenes.packed(plain_root))
	if check(under_node != null, "a root that is no Node3D, a top_level node: a plant"):
		check_near(under_node.height, 2.0, 1e-3, "the top_level node under a plain Node root where it stands")
