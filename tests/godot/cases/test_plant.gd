extends TestCase
## Plant types (SunflowerPlant): the built-in sunflower by default, shared unchanged; a field's own plant
## through set_part_mesh and the old properties; a plant's form (part lengths, height) and variety
## (size and yaw ranges) in the plants drawn; a shared plant's change rebuilds every field using it;
## the impostor quads cut to what the plant's views show; an atlas read with the rows it was baked
## with; plain StandardMaterial3D parts taken over by the plant material.

const FarTileTable: GDScript = preload("res://addons/sunflower_field/runtime/far_tile_table.gd")
const NativeField: GDScript = preload("res://addons/sunflower_field/native/native_field.gd")
const DEMO_MAP: SunflowerFieldMap = preload("res://fields/demo.field")
const ImpostorSetScript: GDScript = preload("res://addons/sunflower_field/runtime/impostor_set.gd")
const PlantMaterialScript: GDScript = preload("res://addons/sunflower_field/plant/plant_material.gd")
const Dressing: GDScript = preload("res://runner/dressing.gd")
const Scenes: GDScript = preload("res://runner/scenes.gd")
const ImpostorBaker: GDScript = preload("res://addons/sunflower_field/plant/impostor_baker.gd")
const BakeLight: GDScript = preload("res://addons/sunflower_field/plant/bake_light.gd")

var fields: Array[SunflowerField] = []


func after_each() -> void:
	for field: SunflowerField in fields:
		if is_instance_valid(field):
			field.free()
	fields.clear()


func _field(plant: SunflowerPlant = null) -> SunflowerField:
	var field: SunflowerField = SunflowerField.new()
	field.plant = plant
	field.map = DEMO_MAP
	tree.root.add_child(field)
	field.finish_build()
	fields.append(field)
	return field


## The mesh a field's near bucket node draws for a part (a plant drawn part by part), once a
## rebuild that is due is done.
func _drawn_mesh(field: SunflowerField, level: int, part: int) -> Mesh:
	field.finish_build()
	var node: MultiMeshInstance3D = _child_named(field, "Mesh%d%s" % [level + 1, ["Bottom", "Middle", "Head"][part]])
	return node.multimesh.mesh if node else null


## The mesh a field's near bucket node draws for a level of a plant drawn whole (null when the
## plant is drawn part by part), once a rebuild that is due is done.
func _whole_mesh(field: SunflowerField, level: int) -> Mesh:
	field.finish_build()
	var node: MultiMeshInstance3D = _child_named(field, "Mesh%d" % (level + 1))
	return node.multimesh.mesh if node else null


## The node that draws a field's mesh-1 heads: its plants' level-1 node drawn whole, else its head
## part's.
func _heads_node(field: SunflowerField) -> MultiMeshInstance3D:
	var whole: MultiMeshInstance3D = _child_named(field, "Mesh1")
	return whole if whole else _child_named(field, "Mesh1Head")


## A field's internal MultiMesh node of that name, or null.
func _child_named(field: SunflowerField, node_name: String) -> MultiMeshInstance3D:
	for node: Node in field.get_children(true):
		if node.name == node_name:
			return node as MultiMeshInstance3D
	return null


func test_the_built_in_sunflower_is_the_default_and_stays_shared_unchanged() -> void:
	var default_plant: SunflowerPlant = SunflowerPlant.default_plant()
	check(default_plant != null, "the addon ships the sunflower plant")
	check_eq(default_plant.name, "Sunflower")
	var first: SunflowerField = _field()
	var second: SunflowerField = _field()
	check(first.plant == null, "no plant set: the built-in one is grown")
	check(default_plant.drawn_whole(), "the sunflower is drawn whole")
	check(_whole_mesh(first, 0) == default_plant.whole_mesh(0), "the sunflower's parts are drawn, merged")
	check(first.impostor_views == default_plant.impostor_views, "and its impostor textures")
	var box: BoxMesh = BoxMesh.new()
	first.set_part_mesh(0, 2, box)
	check(first.plant != null and first.plant != default_plant, "set_part_mesh gives the field its own plant")
	check(_drawn_mesh(first, 0, 2) == box, "the new head is drawn (part by part: a box cannot be merged)")
	check(_drawn_mesh(first, 0, 1) == default_plant.get_part_mesh(0, 1), "with the sunflower's other parts")
	check(default_plant.get_part_mesh(0, 2) != box, "the built-in plant is unchanged")
	check(_whole_mesh(second, 0) == default_plant.whole_mesh(0), "another field is unchanged")
	check(first.get_part_mesh(0, 1) == default_plant.get_part_mesh(0, 1), "the other parts stay the sunflower's")
	first.set_part_mesh(0, 2, null)
	check(first.get_part_mesh(0, 2) == null, "null empties the slot: no default part takes it")
	check(_whole_mesh(first, 0) != null, "the bottom and middle are drawn whole again")
	# Scenes saved before plant types named part meshes "part_meshes/mesh_N/part".
	second.set("part_meshes/mesh_2/middle", box)
	check(_drawn_mesh(second, 1, 1) == box, "the old property name still sets a part")
	check(second.get("part_meshes/mesh_2/middle") == box)


## A new plant holding the built-in sunflower's meshes (and none of its impostor textures).
func _plant_of_sunflower_parts() -> SunflowerPlant:
	var plant: SunflowerPlant = SunflowerPlant.new()
	for level: int in 3:
		for part: int in 3:
			plant.set_part_mesh(level, part, SunflowerPlant.default_plant().get_part_mesh(level, part))
	return plant


## A scene and a plant saved before the plant's class was renamed (FieldPlant, at 22a3d56: the plant's
## header names the old class; the field's wind_power was the node's own) load to the same field as
## one made now: the plant a SunflowerPlant with its saved settings, the wind as saved, and every
## plant where a field of that plant made in code puts it.
func test_a_scene_and_a_plant_saved_under_the_old_class_name_load_to_the_same_field() -> void:
	var old: Node = (load("res://scenes/saved_22a3d56/own_plant_field.tscn") as PackedScene).instantiate()
	tree.root.add_child(old)
	var loaded: SunflowerField = old.get_node("SunflowerField") as SunflowerField
	loaded.finish_build()
	check(loaded.plant is SunflowerPlant, "the saved plant loads as a SunflowerPlant")
	check_eq(loaded.plant.name, "My plant", "its name")
	check_near(loaded.plant.height, 1.5, 1e-6, "its height")
	check(loaded.plant.get_part_mesh(0, 2) is SphereMesh, "its head part")
	check_near(loaded.wind_power, 2.0, 1e-6, "the field's wind as saved")
	var plant: SunflowerPlant = SunflowerPlant.new()
	plant.name = "My plant"
	plant.height = 1.5
	plant.height_units = 3.0
	plant.mesh_level_1 = loaded.plant.mesh_level_1
	var made: SunflowerField = _field(plant)
	check(loaded.get_plant_count() > 0, "the saved field has plants")
	check_eq(loaded.get_plant_count(), made.get_plant_count(), "as many plants as a field made now")
	for field: SunflowerField in [loaded, made]:
		field.advance(0.0)
	var same: bool = true
	for index: int in range(0, made.get_plant_count(), 97):
		var a: Dictionary = loaded.get_plant_info(index)
		var b: Dictionary = made.get_plant_info(index)
		same = same and (a["position"] as Vector3).is_equal_approx(b["position"])
		same = same and a["lod"] == b["lod"]
	check(same, "each plant where the field made now puts it, at the same level of detail")
	old.free()


func test_a_plants_form_and_height_shape_the_plants_drawn() -> void:
	var plant: SunflowerPlant = _plant_of_sunflower_parts()
	plant.part_lengths = Vector3(2.0, 0.5, 1.0)
	plant.middle_variation = 0.0
	plant.height = 7.0  # 3.5 model units: 2 m each
	plant.yaw_range = 0.0
	var field: SunflowerField = _field(plant)
	field.force_lod = SunflowerField.Lod.MESH_1
	field.advance(0.0)
	check_eq(field.plant_height, 7.0, "the node reports its plant's height")
	field.wind_power = 0.0
	field.advance(1.0)  # the natural wind eases out over half a second
	var parts: Array = field.get_plant_info(10)["parts"]
	var root: Vector3 = field.get_plant_info(10)["position"]
	check_near((parts[1] as Transform3D).origin.y - root.y, 4.0, 0.01, "the middle starts 2 units (4 m) up")
	check_near((parts[2] as Transform3D).origin.y - root.y, 5.0, 0.01, "the head 0.5 units (1 m) above it")
	check((parts[0] as Transform3D).basis.z.is_equal_approx(Vector3(0, 0, 2)), "no yaw with a zero yaw range")
	# Its parts drawn whole; without textures of its own (not baked yet) its impostors are
	# untextured (never the sunflower's), and it says so.
	check(_whole_mesh(field, 0) == plant.whole_mesh(0), "drawn whole")
	check(plant.whole_mesh(0).get_faces().size() > 0, "of the sunflower's parts, merged")
	check(field.impostor_views == null, "no sunflower texture on a plant of its own")
	check(warned("drawn untextured"), "a plant of its own parts without textures warns")


func test_a_plants_variety_spreads_sizes_and_yaws_within_its_ranges() -> void:
	var plant: SunflowerPlant = _plant_of_sunflower_parts()
	plant.scale_min = 0.6
	plant.scale_max = 1.4
	plant.yaw_range = PI / 2.0
	plant.middle_variation = 0.0
	var field: SunflowerField = _field(plant)
	field.wind_power = 0.0
	field.force_lod = SunflowerField.Lod.MESH_1
	field.advance(0.1)
	var smallest: float = INF
	var largest: float = 0.0
	var widest: float = 0.0
	for i: int in field.get_plant_count():
		var bottom: Transform3D = field.get_plant_info(i)["parts"][0]
		var size: float = bottom.basis.y.length() * 3.0 / plant.height  # the plant's size factor
		smallest = minf(smallest, size)
		largest = maxf(largest, size)
		widest = maxf(widest, absf(atan2(bottom.basis.z.x, bottom.basis.z.z)))
	check(smallest >= 0.6 - 1e-4 and largest <= 1.4 + 1e-4, "sizes within 0.6–1.4 (%.3f–%.3f)" % [smallest, largest])
	check(largest - smallest > 0.7, "and spread over the range")
	check(widest <= PI / 2.0 + 1e-4 and widest > 1.3, "yaws within ±90° (widest %.2f rad)" % widest)
	# Colour variety: the near buckets' instance colours (after the transform) vary by the range.
	var heads: MultiMesh = _heads_node(field).multimesh
	var stride: int = SunflowerDrawing.WHOLE_FLOATS_PER_INSTANCE
	var white: bool = true
	for k: int in mini(RenderingServer.multimesh_get_buffer(heads.get_rid()).size() / stride, 50):
		white = white and RenderingServer.multimesh_get_buffer(heads.get_rid())[k * stride + 12] == 1.0
	check(white, "no colour variety: white instances")
	plant.brightness_variation = 0.3
	await frames(1)
	field.finish_build()
	field.advance(0.1)
	var buffer: PackedFloat32Array = RenderingServer.multimesh_get_buffer(_heads_node(field).multimesh.get_rid())
	var greens: Array[float] = []
	for k: int in mini(buffer.size() / stride, 200):
		greens.append(buffer[k * stride + 13])
	check(not greens.is_empty() and greens.min() >= 0.7 - 1e-4 and greens.max() <= 1.3 + 1e-4, "brightness within ±0.3")
	check(not greens.is_empty() and greens.max() - greens.min() > 0.3, "and spread (%s)" % [greens.slice(0, 5)])
	take_warnings()


## A plant says it changed only when a value did: setting a value it already has (the inspector does,
## on every edit of a field) re-configures nothing; an array or texture always says so (it may hold
## new contents).
func test_a_plant_signals_a_change_only_when_a_value_changes() -> void:
	var plant: SunflowerPlant = SunflowerPlant.new()
	var changes: Array[int] = [0]
	plant.changed.connect(func() -> void: changes[0] += 1)
	plant.height = plant.height
	plant.stiffness = plant.stiffness
	plant.part_lengths = plant.part_lengths
	plant.name = plant.name
	plant.draw_whole = plant.draw_whole
	check_eq(changes[0], 0, "values set to what they are: no change")
	plant.height = 3.0
	plant.part_lengths = Vector3(1.0, 2.0, 1.0)
	check_eq(changes[0], 2, "two values changed: two changes")
	plant.height = -1.0  # refused: keeps 3.0
	check_eq(changes[0], 2, "a refused value changes nothing")
	plant.mesh_level_1 = plant.mesh_level_1
	check_eq(changes[0], 3, "an array set again says so (its contents may be new)")


func test_changing_a_shared_plant_rebuilds_every_field_that_grows_it() -> void:
	var plant: SunflowerPlant = _plant_of_sunflower_parts()
	var first: SunflowerField = _field(plant)
	var second: SunflowerField = _field(plant)
	var before: float = NativeField.new(second.get_simulation()).get_chunk_aabb(0).end.y
	plant.height = 4.0
	await frames(1)
	first.finish_build()
	second.finish_build()
	for field: SunflowerField in [first, second]:
		check_near(
			NativeField.new(field.get_simulation()).get_chunk_aabb(0).end.y,
			before * 2.0,
			0.05,
			"chunk bounds follow the height"
		)
	# Drawn whole: a part that merges as well is swapped into both fields' merged meshes in place.
	var other_bottom: Mesh = SunflowerPlant.default_plant().get_part_mesh(1, 0)
	plant.set_part_mesh(2, 0, other_bottom)
	check(not first.is_building() and not second.is_building(), "a mesh change drawn the same way needs no rebuild")
	var merged: Mesh = plant.whole_mesh(2)
	check(_whole_mesh(first, 2) == merged and _whole_mesh(second, 2) == merged, "a mesh change shows in both")
	check(
		merged.get_faces().size() > SunflowerPlant.default_plant().whole_mesh(2).get_faces().size(), "with the new part"
	)
	# Part by part (a box cannot be merged: both rebuild once), then a mesh change swaps in place.
	var box: BoxMesh = BoxMesh.new()
	plant.set_part_mesh(2, 0, box)
	check(first.is_building(), "changing how the plant is drawn rebuilds the field")
	check(_drawn_mesh(first, 2, 0) == box and _drawn_mesh(second, 2, 0) == box, "a mesh change shows in both")
	var sphere: SphereMesh = SphereMesh.new()
	plant.set_part_mesh(2, 1, sphere)
	check(not first.is_building(), "a mesh change drawn the same way needs no rebuild")
	check(_drawn_mesh(first, 2, 1) == sphere and _drawn_mesh(second, 2, 1) == sphere, "and shows in both")
	take_warnings()


## An empty slot draws nothing: a new plant draws no plant near and says so; a plant of one mesh
## draws it at all three levels with nothing above it, and its height spans that one part; a slot
## left empty below a filled one is a configuration warning naming it. No sunflower part anywhere.
func test_empty_slots_draw_nothing_and_a_plant_of_one_part_stands_its_height() -> void:
	var plant: SunflowerPlant = SunflowerPlant.new()
	var field: SunflowerField = _field(plant)
	var sunflower_meshes: Array[Mesh] = []
	for level: int in 3:
		sunflower_meshes.append_array(SunflowerPlant.default_plant().get("mesh_level_%d" % (level + 1)))
	for level: int in 3:
		for part: int in 3:
			check(field.get_part_mesh(level, part) == null, "a new plant's slots are empty (%d / %d)" % [level, part])
	check(_whole_mesh(field, 0) == null and _drawn_mesh(field, 0, 0) == null, "and nothing is drawn near")
	check(field.impostor_views == null, "nor the sunflower's impostors far")
	check(
		"\n".join(field._get_configuration_warnings()).contains("has no mesh in mesh_level_1"),
		"a plant without meshes is a configuration warning"
	)
	take_warnings()
	# One mesh: a 4-unit trunk in the bottom slot of level 1, nothing else.
	var trunk: BoxMesh = BoxMesh.new()
	trunk.size = Vector3(0.5, 4.0, 0.5)
	plant.use_plant_material = false
	plant.mesh_level_1 = [trunk, null, null]
	plant.part_lengths = Vector3(4.0, 1.0, 1.0)  # the empty slots' lengths count 0
	plant.height = 8.0
	plant.middle_variation = 0.0
	check_eq(plant.stacked_lengths(), Vector3(4.0, 0.0, 0.0), "the empty slots above the trunk have no length")
	field.force_lod = SunflowerField.Lod.MESH_1
	field.finish_build()
	field.advance(0.0)
	for level: int in 3:
		check(_drawn_mesh(field, level, 0) == trunk, "the trunk is drawn at mesh level %d" % (level + 1))
		for part: int in [1, 2]:
			var drawn: Mesh = _drawn_mesh(field, level, part)
			check(drawn == null, "slot %d of level %d draws nothing (%s)" % [part, level + 1, drawn])
			check(not sunflower_meshes.has(drawn), "no sunflower part")
	var bottom: Transform3D = field.get_plant_info(10)["parts"][0]
	check_near(bottom.basis.y.length(), 2.0, 0.01, "8 m over the trunk's 4 units: 2 m a unit")
	check(plant.stacking_problems().is_empty(), "a plant of one part stacks")
	# A head with no middle below it floats over the gap: a warning names the slot.
	plant.set_part_mesh(0, 2, trunk)
	check(
		"\n".join(field._get_configuration_warnings()).contains("mesh_level_1's middle slot is empty below its head"),
		"a slot left empty below a filled one is a configuration warning naming it"
	)
	# Drawn whole: the merged mesh of a plant of the sunflower's bottom alone holds just that part.
	var stem: SunflowerPlant = SunflowerPlant.new()
	stem.mesh_level_1 = [SunflowerPlant.default_plant().get_part_mesh(0, 0), null, null]
	check(stem.drawn_whole(), "a plant of one plant-material part is drawn whole")
	check_eq(
		stem.whole_mesh(0).get_faces().size(),
		SunflowerPlant.default_plant().get_part_mesh(0, 0).get_faces().size(),
		"its merged mesh is that part alone"
	)
	check(stem.whole_mesh(2) != null, "a level without meshes draws the level above's")
	take_warnings()


func test_the_impostor_quad_covers_only_what_its_views_show() -> void:
	# Two 16-pixel squares: the first draws pixels (2..5, 4..15), the second nothing.
	var image: Image = Image.create_empty(32, 16, false, Image.FORMAT_RGBA8)
	image.fill_rect(Rect2i(2, 4, 4, 12), Color(0.2, 0.8, 0.1, 0.5))
	var bounds: PackedVector4Array = ImpostorSetScript.view_bounds(
		ImageTexture.create_from_image(image), Vector2i(2, 1)
	)
	check_eq(bounds.size(), 2, "a rectangle per view")
	check(
		bounds[0].is_equal_approx(Vector4(2.0, 4.0, 6.0, 16.0) / 16.0), "the drawn pixels' rectangle (%s)" % bounds[0]
	)
	check(bounds[1].z <= bounds[1].x, "an empty view has an empty rectangle (%s)" % bounds[1])
	check(ImpostorSetScript.view_bounds(null, Vector2i(2, 1)).is_empty(), "no texture: no rectangles")
	# Joined for the shader: 3 columns × 2 rows of views, one of them empty.
	var views: PackedVector4Array = [
		Vector4(0.4, 0.5, 0.6, 0.9),
		Vector4(0.3, 0.4, 0.5, 0.8),
		Vector4(0, 0, 0, 0),
		Vector4(0.2, 0.1, 0.5, 0.6),
		Vector4(0.45, 0.2, 0.7, 0.7),
		Vector4(0.1, 0.6, 0.2, 0.95),
	]
	var up: PackedVector4Array = ImpostorSetScript.joined_view_bounds(views, Vector2i(3, 2), Vector2i(1, 2))
	var block: PackedVector4Array = ImpostorSetScript.joined_view_bounds(views, Vector2i(3, 2), Vector2i(2, 2))
	var expected: Dictionary = {
		"up, first view": [up[0], Vector4(0.2, 0.1, 0.6, 0.9)],
		"up, an empty view and the one above it": [up[2], views[5]],
		"up, the top row alone": [up[4], views[4]],
		"block of the first two columns": [block[0], Vector4(0.2, 0.1, 0.7, 0.9)],
		"block wrapping from the last column to the first": [block[2], Vector4(0.1, 0.1, 0.6, 0.95)],
		"block at the top row": [block[5], Vector4(0.1, 0.1, 0.5, 0.95)],
	}
	for what: String in expected:
		check(expected[what][0].is_equal_approx(expected[what][1]), "%s: %s" % [what, expected[what][0]])
	var nothing: PackedVector4Array = [Vector4.ZERO, Vector4.ZERO]
	check_eq(
		ImpostorSetScript.joined_view_bounds(nothing, Vector2i(2, 1), Vector2i(2, 2))[0],
		Vector4(1, 1, 0, 0),
		"views drawing nothing join to an empty rectangle"
	)
	check(ImpostorSetScript.joined_view_bounds([], Vector2i(2, 1), Vector2i(2, 2)).is_empty(), "no views: none joined")
	# The built-in sunflower's views fill about a quarter of their squares: its impostors' quads are
	# cut to that, for the near buckets' material and the far tiles' alike.
	var field: SunflowerField = _field()
	for name: String in ["Impostors", "FarTile%d" % FarTileTable.new(NativeField.new(field.get_simulation())).key(0)]:
		var node: MultiMeshInstance3D = _child_named(field, name)
		var material: ShaderMaterial = node.multimesh.mesh.surface_get_material(0) as ShaderMaterial
		var drawn: PackedVector4Array = material.get_shader_parameter("view_bounds_block")
		var area: float = 0.0
		for view: Vector4 in drawn:
			area += (view.z - view.x) * (view.w - view.y) / drawn.size()
		check_eq(
			drawn.size(), SunflowerPlant.ATLAS_VIEWS.x * SunflowerPlant.ATLAS_VIEWS.y, "%s: a rectangle per view" % name
		)
		check(area > 0.1 and area < 0.45, "%s: four views together fill %.2f of their squares" % [name, area])
		check_eq(material.get_shader_parameter("view_bounds_up").size(), drawn.size(), "%s: pairs of views" % name)


## The baker makes 10 rows of elevation (10° apart); an atlas baked with 4 (30° apart) or 7 (15°
## apart, as older bakes made) is read with its own rows, from its shape, so its views are still found
## where they are.
func test_an_atlas_is_read_with_the_rows_it_was_baked_with() -> void:
	var columns: int = SunflowerPlant.ATLAS_VIEWS.x
	var oldest: ImageTexture = ImageTexture.create_from_image(
		Image.create(columns * 8, 4 * 8, false, Image.FORMAT_RGBA8)
	)
	var old: ImageTexture = ImageTexture.create_from_image(Image.create(columns * 8, 7 * 8, false, Image.FORMAT_RGBA8))
	var now: ImageTexture = ImageTexture.create_from_image(
		Image.create(columns * 8, SunflowerPlant.ATLAS_VIEWS.y * 8, false, Image.FORMAT_RGBA8)
	)
	check_eq(SunflowerPlant.ATLAS_VIEWS, Vector2i(12, 10), "the baker's views: 12 around, 10 elevations")
	check_eq(ImpostorSetScript.atlas_layout(oldest), Vector2i(columns, 4), "a 4-row atlas")
	check_eq(ImpostorSetScript.atlas_layout(old), Vector2i(columns, 7), "a 7-row atlas")
	check_eq(ImpostorSetScript.atlas_layout(now), SunflowerPlant.ATLAS_VIEWS, "a 10-row atlas")
	check_eq(ImpostorSetScript.atlas_layout(null), SunflowerPlant.ATLAS_VIEWS, "no atlas: the baker's layout")
	var impostors: RefCounted = ImpostorSetScript.new()
	for texture: ImageTexture in [oldest, old, now]:
		impostors.set_texture("views", texture)
		var rows: int = texture.get_height() / 8
		for material: ShaderMaterial in [impostors.material, impostors.tile_material]:
			check_eq(material.get_shader_parameter("atlas_views"), Vector2i(columns, rows), "%d rows drawn" % rows)
			check_eq(material.get_shader_parameter("view_bounds_block").size(), columns * rows, "a rectangle per view")
	# An atlas of another shape is named as such (and warned of when drawn).
	check_eq(ImpostorSetScript.atlas_problem(oldest), "", "a 4-row atlas is one the baker made")
	check_eq(ImpostorSetScript.atlas_problem(old), "", "a 7-row atlas is one the baker made")
	check_eq(ImpostorSetScript.atlas_problem(now), "", "a 10-row atlas is one the baker made")
	for size: Vector2i in [
		Vector2i(columns * 8 + 3, 32), Vector2i(columns * 8, 30), Vector2i(columns * 8, 8), Vector2i(512, 512)
	]:
		var odd: ImageTexture = ImageTexture.create_from_image(Image.create(size.x, size.y, false, Image.FORMAT_RGBA8))
		var problem: String = ImpostorSetScript.atlas_problem(odd)
		check(not problem.is_empty(), "a %d × %d atlas is not one the baker makes" % [size.x, size.y])
		print("     %d × %d: %s" % [size.x, size.y, problem])
	# The shipped sunflower is baked with the baker's layout.
	check_eq(
		ImpostorSetScript.atlas_problem(SunflowerPlant.default_plant().impostor_views), "", "the built-in atlas' shape"
	)
	check_eq(
		ImpostorSetScript.atlas_layout(SunflowerPlant.default_plant().impostor_views),
		SunflowerPlant.ATLAS_VIEWS,
		"the built-in sunflower's atlas"
	)


## A spatial ShaderMaterial of your own is drawn by a copy whose shader fades: the plant material's
## include after its shader_type and render_mode lines and its one line first in fragment() (or a
## fragment() of that line when it has none). A shader that fades already, one that is not spatial
## and one that includes a file by a relative path are left as they are; the include is not added
## twice; your material and shader are not changed; one copy of the shader serves every material.
func test_a_shader_of_your_own_is_made_to_fade() -> void:
	var code: String = "shader_type spatial;\nrender_mode unshaded;\nuniform vec4 tint;\n"
	code += "void fragment() {\n\tALBEDO = tint.rgb;\n}\n"
	var faded: String = PlantMaterialScript.fading_code(code)
	_check_placed(
		faded, PlantMaterialScript.FADE_INCLUDE, PlantMaterialScript.FADE_CALL, "fragment", "ALBEDO = tint.rgb;"
	)
	var bare: String = PlantMaterialScript.fading_code("shader_type spatial;\nvoid vertex() {\n}\n")
	check(bare.contains("void fragment() {\n\t" + PlantMaterialScript.FADE_CALL), "a fragment() of the call is added")
	var included: String = PlantMaterialScript.fading_code(
		code.replace("uniform", PlantMaterialScript.FADE_INCLUDE + "\nuniform")
	)
	check_eq(included.count(PlantMaterialScript.FADE_INCLUDE_PATH), 1, "an include already there is not added twice")
	check_eq(PlantMaterialScript.fading_code(faded), "", "a shader that fades already is left as it is")
	check_eq(PlantMaterialScript.fading_code("shader_type canvas_item;\nvoid fragment() {\n}\n"), "", "not spatial")
	check_eq(
		PlantMaterialScript.fading_code(code.replace("uniform", '#include "mine.gdshaderinc"\nuniform')),
		"",
		"relative include"
	)
	var shader: Shader = Shader.new()
	shader.code = code
	var first: ShaderMaterial = ShaderMaterial.new()
	first.shader = shader
	var second: ShaderMaterial = first.duplicate() as ShaderMaterial
	var copy: ShaderMaterial = PlantMaterialScript.fading(first)
	if check(copy != null, "your ShaderMaterial gets a fading copy"):
		check_eq(copy.shader.code, faded, "drawn with the fading code")
		check(PlantMaterialScript.fading(second).shader == copy.shader, "one fading shader for every material of yours")
	check(first.shader == shader and shader.code == code, "your material and shader stay as they were")
	check(PlantMaterialScript.fading(StandardMaterial3D.new()) == null, "only ShaderMaterials")
	# Through a plant: the field's mesh draws the copy, the plant's own mesh keeps yours.
	var plant: SunflowerPlant = SunflowerPlant.default_plant().duplicate()
	Dressing.dress_parts(plant, func(_level: int, _part: int) -> Material: return first)
	var drawn: Material = plant.mesh_for_field(0, 0).surface_get_material(0)
	check(
		drawn is ShaderMaterial and (drawn as ShaderMaterial).shader == copy.shader, "the field draws the fading copy"
	)
	check_eq(plant.mesh_drawn(0, 0).surface_get_material(0), first, "the plant's own mesh keeps your material")
	check(plant.drawn_whole(), "and the plant is drawn whole (by a copy that bends too)")
	plant.use_plant_material = false
	check_eq(plant.mesh_for_field(0, 0).surface_get_material(0), first, "use_plant_material off: yours as it is")
	check(not plant.drawn_whole(), "and the plant part by part")


## A plant drawn whole with a ShaderMaterial of your own is drawn by a copy whose shader also bends:
## the bend's include after the shader_type and render_mode lines, its call first in vertex() (or a
## vertex() of that call when it has none). A shader that reads UV2 (where the merged mesh keeps each
## vertex's part), has world-space vertices or bends already, and one that is not spatial, cannot; a
## part whose own shader cannot bend keeps its plant drawn part by part, and its warning names what it
## uses (UV2, also where the shader names plant_place before it). The merged mesh's material is the
## copy with the plant's part lengths and flutter; your material and the fading copy stay.
func test_a_shader_of_your_own_is_made_to_bend_when_drawn_whole() -> void:
	var code: String = "shader_type spatial;\nrender_mode unshaded;\nuniform vec4 tint;\n"
	code += "void vertex() {\n\tVERTEX.y += 0.0;\n}\nvoid fragment() {\n\tALBEDO = tint.rgb;\n}\n"
	var bent: String = PlantMaterialScript.bending_code(code)
	_check_placed(bent, PlantMaterialScript.BEND_INCLUDE, PlantMaterialScript.BEND_CALL, "vertex", "VERTEX.y += 0.0;")
	var bare: String = PlantMaterialScript.bending_code("shader_type spatial;\nvoid fragment() {\n}\n")
	check(bare.contains("void vertex() {\n\t" + PlantMaterialScript.BEND_CALL), "a vertex() of the call is added")
	check_eq(PlantMaterialScript.bending_code(bent), "", "a shader that bends already is left as it is")
	check_eq(PlantMaterialScript.bending_code(code.replace("ALBEDO = tint.rgb", "ALBEDO = vec3(UV2, 0.0)")), "", "UV2")
	check_eq(
		PlantMaterialScript.bending_code(code.replace("unshaded", "unshaded, world_vertex_coords")), "", "world space"
	)
	check_eq(PlantMaterialScript.bending_code("shader_type canvas_item;\nvoid vertex() {\n}\n"), "", "not spatial")

	var shader: Shader = Shader.new()
	shader.code = code
	var own: ShaderMaterial = ShaderMaterial.new()
	own.shader = shader
	var plant: SunflowerPlant = SunflowerPlant.new()
	var box: BoxMesh = BoxMesh.new()
	box.material = own
	var mesh: ArrayMesh = ArrayMesh.new()
	mesh.add_surface_from_arrays(Mesh.PRIMITIVE_TRIANGLES, box.get_mesh_arrays())
	mesh.surface_set_material(0, own)
	plant.mesh_level_1 = [mesh, null, null]
	plant.mesh_level_2 = [mesh, null, null]
	plant.mesh_level_3 = [mesh, null, null]
	plant.part_lengths = Vector3(2.0, 0.0, 0.0)
	plant.flutter = 0.25
	check(plant.drawn_whole(), "a plant of one part with your shader is drawn whole")
	var drawn: ShaderMaterial = plant.whole_mesh(0).surface_get_material(0) as ShaderMaterial
	if check(drawn != null, "its merged mesh has a ShaderMaterial"):
		check(drawn.shader.code.contains(PlantMaterialScript.BEND_CALL), "whose shader bends")
		check(drawn.shader.code.contains(PlantMaterialScript.FADE_CALL), "and fades")
		check(drawn.shader.code.contains("ALBEDO = tint.rgb;"), "and is yours")
		check_eq(drawn.get_shader_parameter(&"plant_part_lengths"), Vector3(2.0, 0.0, 0.0), "the part lengths")
		check_eq(drawn.get_shader_parameter(&"plant_flutter"), 0.25, "the flutter")
		var again: ShaderMaterial = PlantMaterialScript.bending(plant.mesh_for_field(1, 0).surface_get_material(0))
		check(again.shader == drawn.shader, "one bending shader for every material of yours")
	check(own.shader == shader and shader.code == code, "your material and shader stay as they were")
	var uv2_shader: Shader = Shader.new()
	uv2_shader.code = code.replace("ALBEDO = tint.rgb", "ALBEDO = vec3(UV2, 0.0)")
	var uv2_mesh: ArrayMesh = mesh.duplicate()
	var uv2_material: ShaderMaterial = ShaderMaterial.new()
	uv2_material.shader = uv2_shader
	uv2_mesh.surface_set_material(0, uv2_material)
	plant.mesh_level_1 = [uv2_mesh, null, null]
	check(not plant.drawn_whole(), "a shader that reads UV2 keeps its plant drawn part by part")
	var uv2_named: PackedStringArray = PlantMaterialScript.kept_materials([uv2_mesh])
	check(uv2_named.size() == 1 and uv2_named[0].contains("its shader uses UV2"), "and is named: %s" % [uv2_named])
	# (A shader of its own: changing a drawn shader's code frees its pipelines off the render thread.)
	var named_first: Shader = Shader.new()
	named_first.code = uv2_shader.code.replace("uniform vec4 tint;", "uniform vec4 tint; // plant_place")
	var named_first_mesh: ArrayMesh = mesh.duplicate()
	var named_first_material: ShaderMaterial = ShaderMaterial.new()
	named_first_material.shader = named_first
	named_first_mesh.surface_set_material(0, named_first_material)
	uv2_named = PlantMaterialScript.kept_materials([named_first_mesh])
	check(
		uv2_named.size() == 1 and uv2_named[0].contains("its shader uses UV2"),
		"named for its UV2 when plant_place comes first: %s" % [uv2_named]
	)


## Checks that [param made] (a test shader's code, "render_mode unshaded;" then "uniform vec4 tint;")
## has [param include] after its render_mode line and before its declarations, and [param call] in
## its [param function]() before [param first], the statement that came first there.
## The copies keep your line numbers (an error in a copy names your line): the include takes the
## blank line after the shader_type and render_mode lines, the calls go on the function's head line.
## A shader of yours that does not compile is not copied (the engine reports its error once; a copy
## would report it again), and the part keeps it as it is.
func test_copies_of_your_shader_keep_its_lines_and_a_broken_one_is_not_copied() -> void:
	var code: String = "shader_type spatial;\nrender_mode unshaded;\n\nuniform vec4 tint;\n"
	code += "void vertex() {\n\tVERTEX.y += 0.0;\n}\nvoid fragment() {\n\tALBEDO = tint.rgb;\n}\n"
	var faded: String = PlantMaterialScript.fading_code(code)
	var lines: PackedStringArray = faded.split("\n")
	var yours: PackedStringArray = code.split("\n")
	if check_eq(lines.size(), yours.size(), "as many lines as yours:\n" + faded):
		for i: int in yours.size():
			check(lines[i].begins_with(yours[i]), "line %d is yours: '%s' / '%s'" % [i + 1, lines[i], yours[i]])
	# The bending copy of a fading one has no blank line left for its include: one line more.
	check_eq(PlantMaterialScript.bending_code(faded).count("\n"), faded.count("\n") + 1, "bent: one line more")
	var without_blank: String = PlantMaterialScript.fading_code(code.replace("unshaded;\n\n", "unshaded;\n"))
	check(without_blank.contains("unshaded;\n" + PlantMaterialScript.FADE_INCLUDE + "\nuniform"), "no blank line")
	var broken: Shader = Shader.new()
	allow_error("Unknown identifier in expression: 'nowhere'")
	allow_error("Shader compilation failed")
	broken.code = code.replace("tint.rgb;", "tint.rgb + nowhere;")
	var material: ShaderMaterial = ShaderMaterial.new()
	material.shader = broken
	check(PlantMaterialScript.fading(material) == null, "a shader that does not compile gets no copy")
	var mesh: ArrayMesh = ArrayMesh.new()
	mesh.add_surface_from_arrays(Mesh.PRIMITIVE_TRIANGLES, BoxMesh.new().get_mesh_arrays())
	mesh.surface_set_material(0, material)
	check_eq(PlantMaterialScript.adopt_mesh(mesh).surface_get_material(0), material, "its part keeps it")


func _check_placed(made: String, include: String, call: String, function: String, first: String) -> void:
	var include_at: int = made.find(include)
	var call_at: int = made.find(call)
	check(include_at > made.find("render_mode unshaded;"), "the include follows the render_mode line:\n" + made)
	check(include_at < made.find("uniform vec4 tint;"), "and comes before your declarations")
	check(call_at > made.find("void %s() {" % function), "the call is in %s()" % function)
	check(call_at < made.find(first), "before anything else there")


func test_plain_standard_materials_are_taken_over_and_others_kept() -> void:
	var texture: ImageTexture = ImageTexture.create_from_image(Image.create(4, 4, false, Image.FORMAT_RGBA8))
	var leaf: StandardMaterial3D = StandardMaterial3D.new()
	leaf.albedo_color = Color(0.2, 0.6, 0.1)
	leaf.albedo_texture = texture
	leaf.uv1_scale = Vector3(2.0, 3.0, 1.0)
	leaf.roughness = 0.4
	leaf.transparency = BaseMaterial3D.TRANSPARENCY_ALPHA_SCISSOR
	leaf.alpha_scissor_threshold = 0.3
	leaf.metallic = 0.2
	leaf.metallic_specular = 0.7
	leaf.normal_enabled = true
	leaf.normal_texture = texture
	leaf.normal_scale = 0.5
	leaf.roughness_texture = texture
	leaf.roughness_texture_channel = BaseMaterial3D.TEXTURE_CHANNEL_GREEN
	leaf.metallic_texture = texture
	leaf.metallic_texture_channel = BaseMaterial3D.TEXTURE_CHANNEL_BLUE
	var taken: ShaderMaterial = PlantMaterialScript.adopt(leaf, false)
	if check(taken != null, "a plain textured, scissored StandardMaterial3D is taken over"):
		check(taken.shader == preload("res://addons/sunflower_field/shaders/plant_parts.gdshader"), "plant shader")
		check_eq(taken.get_shader_parameter("albedo_colour"), leaf.albedo_color, "albedo colour")
		check_eq(taken.get_shader_parameter("albedo_texture"), texture, "albedo texture")
		check_eq(taken.get_shader_parameter("use_albedo_texture"), true, "the texture is used")
		check_eq(taken.get_shader_parameter("uv_scale"), Vector2(2.0, 3.0), "UV scale")
		check(is_equal_approx(taken.get_shader_parameter("roughness"), 0.4), "roughness")
		check(is_equal_approx(taken.get_shader_parameter("alpha_scissor"), 0.3), "alpha scissor")
		check(is_equal_approx(taken.get_shader_parameter("metallic"), 0.2), "metallic")
		check(is_equal_approx(taken.get_shader_parameter("specular"), 0.7), "specular")
		check_eq(taken.get_shader_parameter("use_normal_texture"), true, "the normal map is used")
		check_eq(taken.get_shader_parameter("normal_texture"), texture, "normal map")
		check(is_equal_approx(taken.get_shader_parameter("normal_scale"), 0.5), "normal scale")
		check_eq(taken.get_shader_parameter("use_roughness_texture"), true, "the roughness texture is used")
		check_eq(taken.get_shader_parameter("roughness_channel"), Vector4(0, 1, 0, 0), "roughness from green")
		check_eq(taken.get_shader_parameter("use_metallic_texture"), true, "the metallic texture is used")
		check_eq(taken.get_shader_parameter("metallic_channel"), Vector4(0, 0, 1, 0), "metallic from blue")
	# Emission, ambient occlusion and back-light carry over.
	var glowing: StandardMaterial3D = leaf.duplicate()
	glowing.emission_enabled = true
	glowing.emission = Color(0.5, 0.25, 0.0)
	glowing.emission_energy_multiplier = 2.5
	glowing.emission_operator = BaseMaterial3D.EMISSION_OP_MULTIPLY
	glowing.emission_texture = texture
	glowing.ao_enabled = true
	glowing.ao_texture = texture
	glowing.ao_texture_channel = BaseMaterial3D.TEXTURE_CHANNEL_ALPHA
	glowing.ao_light_affect = 0.6
	glowing.backlight_enabled = true
	glowing.backlight = Color(0.4, 0.5, 0.1)
	glowing.backlight_texture = texture
	var lit_up: ShaderMaterial = PlantMaterialScript.adopt(glowing, false)
	if check(lit_up != null, "emission, ambient occlusion and back-light are taken over"):
		check_eq(lit_up.get_shader_parameter("emission_colour"), glowing.emission, "emission colour")
		check(is_equal_approx(lit_up.get_shader_parameter("emission_energy"), 2.5), "emission energy")
		check_eq(lit_up.get_shader_parameter("emission_multiply"), true, "emission times its texture")
		check_eq(lit_up.get_shader_parameter("emission_texture"), texture, "emission texture")
		check_eq(lit_up.get_shader_parameter("use_ao_texture"), true, "the occlusion texture is used")
		check_eq(lit_up.get_shader_parameter("ao_texture"), texture, "occlusion texture")
		check_eq(lit_up.get_shader_parameter("ao_channel"), Vector4(0, 0, 0, 1), "occlusion from alpha")
		check(is_equal_approx(lit_up.get_shader_parameter("ao_light_affect"), 0.6), "occlusion's light affect")
		check_eq(lit_up.get_shader_parameter("backlight_colour"), glowing.backlight, "back-light colour")
		check_eq(lit_up.get_shader_parameter("use_backlight_texture"), true, "the back-light texture is used")
		check_eq(lit_up.get_shader_parameter("backlight_texture"), texture, "back-light texture")
	if taken:
		check(not taken.get_shader_parameter("emission_energy"), "no emission unless enabled")
		check(not taken.get_shader_parameter("use_ao_texture"), "no occlusion unless enabled")
		check(not taken.get_shader_parameter("backlight_colour"), "no back-light unless enabled")
	# What the plant material cannot draw is kept: the part is drawn by its own material.
	var second_uv: StandardMaterial3D = glowing.duplicate()
	second_uv.ao_on_uv2 = true
	check(PlantMaterialScript.adopt(second_uv, false) == null, "occlusion read from UV2 is kept as it is")
	ProjectSettings.set_setting(PlantMaterialScript.PHYSICAL_LIGHT_UNITS, true)
	var physical: ShaderMaterial = PlantMaterialScript.adopt(glowing, false)
	ProjectSettings.set_setting(PlantMaterialScript.PHYSICAL_LIGHT_UNITS, false)
	check(physical == null, "emission under physical light units is kept as it is")
	var rimmed: StandardMaterial3D = leaf.duplicate()
	rimmed.rim_enabled = true
	check(PlantMaterialScript.adopt(rimmed, false) == null, "rim lighting is kept as it is")
	var blended: StandardMaterial3D = leaf.duplicate()
	blended.transparency = BaseMaterial3D.TRANSPARENCY_ALPHA
	check(PlantMaterialScript.adopt(blended, false) == null, "alpha blending is kept as it is")
	var front: StandardMaterial3D = leaf.duplicate()
	front.cull_mode = BaseMaterial3D.CULL_FRONT
	check(PlantMaterialScript.adopt(front, false) == null, "front faces culled are kept as they are")
	var passes: StandardMaterial3D = leaf.duplicate()
	passes.next_pass = StandardMaterial3D.new()
	check(PlantMaterialScript.adopt(passes, false) == null, "a next pass is kept as it is")
	check(PlantMaterialScript.adopt(ORMMaterial3D.new(), false) == null, "an ORMMaterial3D is kept as it is")
	check(PlantMaterialScript.adopt(leaf, true) == null, "vertex colours the material ignores: kept as it is")
	var coloured: ArrayMesh = SunflowerPlant.default_plant().mesh_drawn(0, 0).duplicate() as ArrayMesh  # has them
	for surface: int in coloured.get_surface_count():
		coloured.surface_set_material(surface, leaf)
	check(PlantMaterialScript.adopt_mesh(coloured) == coloured, "a mesh with vertex colours its material ignores")
	leaf.vertex_color_use_as_albedo = true
	check(PlantMaterialScript.adopt(leaf, true) != null, "vertex colours as albedo: taken over")
	# A plant of such parts is drawn whole, one surface per distinct material; switched off, or with
	# one part kept, part by part.
	var plant: SunflowerPlant = SunflowerPlant.default_plant().duplicate()
	var stalk: StandardMaterial3D = StandardMaterial3D.new()
	stalk.vertex_color_use_as_albedo = true
	var head: StandardMaterial3D = stalk.duplicate()
	head.albedo_color = Color(1.0, 0.8, 0.2)
	Dressing.dress_parts(plant, func(_level: int, part: int) -> Material: return head if part == 2 else stalk)
	check(plant.drawn_whole(), "plain StandardMaterial3D parts: drawn whole")
	check_eq(plant.whole_mesh(0).get_surface_count(), 2, "one merged surface per distinct material")
	check_eq(plant.mesh_drawn(0, 2).surface_get_material(0), head, "the plant's own mesh keeps its material")
	plant.use_plant_material = false
	check(not plant.drawn_whole(), "their own materials: drawn part by part")
	plant.use_plant_material = true
	var lit: ArrayMesh = plant.mesh_drawn(1, 0).duplicate() as ArrayMesh
	lit.surface_set_material(0, rimmed)
	plant.set_part_mesh(1, 0, lit)
	check(not plant.drawn_whole(), "a part with rim lighting: drawn part by part")
	check_eq(plant.mesh_for_field(1, 0).surface_get_material(0), rimmed, "that part keeps its material")


## A shader of the user's that lights its surface itself (light()) or lets light through as SSS
## transmittance is named in a warning when the impostors are baked (#60); one that sets BACKLIGHT
## (its back-light is baked: test_bake), the plant material and a StandardMaterial3D are not named.
func test_a_shader_whose_own_light_the_bake_cannot_capture_is_named() -> void:
	var lit: ShaderMaterial = Scenes.shader_material(
		(
			"shader_type spatial;\nvoid fragment() { ALBEDO = vec3(0.2, 0.6, 0.1); }\n"
			+ "void light() { DIFFUSE_LIGHT += ATTENUATION * LIGHT_COLOR; }\n"
		),
		"leaves_lit"
	)
	var transmits: String = "SSS_TRANSMITTANCE_COLOR = vec4(0.5);"
	var through: ShaderMaterial = Scenes.shader_material(
		"shader_type spatial;\nvoid fragment() { ALBEDO = vec3(0.2); %s }\n" % transmits, "leaves_through"
	)
	var backlit: ShaderMaterial = Scenes.shader_material(
		"shader_type spatial;\nvoid fragment() { ALBEDO = vec3(0.2); BACKLIGHT = vec3(0.5); }\n", "leaves_backlit"
	)
	var plain: ShaderMaterial = Scenes.shader_material(
		"shader_type spatial;\n// no light() here\nvoid fragment() { ALBEDO = vec3(0.5); }\n"
	)
	var mesh: ArrayMesh = ArrayMesh.new()
	for material: Material in [
		lit,
		through,
		backlit,
		plain,
		StandardMaterial3D.new(),
		PlantMaterialScript.adopt(StandardMaterial3D.new(), false)
	]:
		var surface: SurfaceTool = SurfaceTool.new()
		surface.begin(Mesh.PRIMITIVE_TRIANGLES)
		for vertex: Vector3 in [Vector3.ZERO, Vector3.UP, Vector3.RIGHT]:
			surface.add_vertex(vertex)
		surface.set_material(material)
		surface.commit(mesh)
	var grown: SunflowerPlant = SunflowerPlant.new()
	grown.set_part_mesh(0, 0, mesh)
	var problems: PackedStringArray = BakeLight.lighting_not_baked(grown, ImpostorBaker.bake_level(grown))
	check_eq(problems.size(), 2, "two materials named: %s" % str(problems))
	check(
		problems.size() == 2 and problems[0].contains("leaves_lit") and problems[0].contains("light()"), "its light()"
	)
	check(
		problems.size() == 2 and problems[1].contains("leaves_through") and problems[1].contains("SSS transmittance"),
		"its transmittance"
	)
