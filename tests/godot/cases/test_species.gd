extends TestCase
## Several plant types in one map: the legend maps a character to a SunflowerPlant; each type has its
## own near buckets, impostors and chunks, its own height, and LOD counts per type that add up to
## the field's. A render of a hilly field mixing the sunflower and the red sunflower shows both,
## standing on the hills (saved to tests/artifacts/render_hilly_mixed.png).

const FarTileTable: GDScript = preload("res://addons/sunflower_field/runtime/far_tile_table.gd")
const NativeField: GDScript = preload("res://addons/sunflower_field/native/native_field.gd")
const RED: SunflowerPlant = preload("res://addons/sunflower_field/plants/red_sunflower.tres")
const SHOT: String = "render_hilly_mixed.png"

var scene: Node3D


func before_each() -> void:
	scene = Node3D.new()
	tree.root.add_child(scene)


func after_each() -> void:
	scene.free()


## A side × side map: 'm' in a band of columns, '*' elsewhere, 'S' (an object) in one cell.
func _mixed_map(side: int, stone: bool = true) -> SunflowerFieldMap:
	var lines: PackedStringArray = ["%d %d" % [side, side]]
	for row: int in side:
		var line: String = ""
		for column: int in side:
			line += "m" if column >= side / 3 and column < side * 2 / 3 else "*"
		lines.append(line)
	if stone:
		lines[1] = "S" + lines[1].substr(1)
	var field_map: SunflowerFieldMap = SunflowerFieldMap.new()
	field_map.source_path = "user://mixed_%d.field" % side
	field_map.text = "\n".join(lines).to_utf8_buffer()
	return field_map


func _node_named(field: SunflowerField, name: String) -> MultiMeshInstance3D:
	for node: Node in field.get_children(true):
		if node.name == name:
			return node as MultiMeshInstance3D
	return null


func test_a_legend_plant_is_a_species_with_its_own_buckets_impostors_and_counts() -> void:
	var marker: Node3D = Node3D.new()
	marker.name = "Stone"
	var stone: PackedScene = PackedScene.new()
	stone.pack(marker)
	marker.free()
	var maize: SunflowerPlant = SunflowerPlant.new()
	maize.name = "Box maize"
	maize.height = 3.0
	maize.height_units = 3.5
	var box: BoxMesh = BoxMesh.new()
	maize.mesh_level_1 = [box, box, box]
	maize.impostor_shadow_shift = 0.0  # at the plant's own depths, where the sunflower's stand 0.03 out
	var field: SunflowerField = SunflowerField.new()
	field.legend = {"m": maize, "S": stone}
	field.map = _mixed_map(60)
	scene.add_child(field)
	field.finish_build()
	check_eq(field.get_plant_count(), 60 * 60 - 1, "plants of both types (and one stone)")
	var types: Array[SunflowerPlant] = field.get_plant_types()
	check(types.size() == 2 and types[1] == maize, "the field grows the sunflower and the legend's plant")
	check(_node_named(field, "Plant1Mesh1Head") != null, "the second type has its own near bucket nodes")
	check(_node_named(field, "Plant1Mesh1Head").multimesh.mesh == box, "drawn with its own parts")
	check(_node_named(field, "Plant1Mesh1") == null, "part by part: a box cannot be merged")
	check(_node_named(field, "Mesh1").multimesh.mesh == types[0].whole_mesh(0), "the sunflower keeps its own, whole")
	# The far impostors of the second type are framed for it: 3.5 model units tall.
	var maize_quad: Mesh = _node_named(field, "Plant1Impostors").multimesh.mesh
	var sunflower_quad: Mesh = _node_named(field, "Impostors").multimesh.mesh
	var frames: Array[float] = [
		sqrt(3.2 * 3.2 + types[0].impostor_width * types[0].impostor_width),
		sqrt(3.5 * 3.5 + types[1].impostor_width * types[1].impostor_width),
	]
	var framed: Array[float] = []
	for quad: Mesh in [sunflower_quad, maize_quad]:
		framed.append((quad.surface_get_material(0) as ShaderMaterial).get_shader_parameter("frame_size"))
	check_near(framed[1], frames[1], 1e-3, "the second type's impostor frame")
	check_near(framed[0], frames[0], 1e-3, "the sunflower's impostor frame")
	# Each type's shadow casters (the impostor nodes' caster children) stand out as far as it says,
	# and a change is drawn without a rebuild.
	var casters: Array[ShaderMaterial] = []
	for node_name: String in ["Impostors", "Plant1Impostors"]:
		casters.append(_node_named(field, node_name).get_child(0, true).material_override as ShaderMaterial)
	var shifts: Array[float] = []
	for caster: ShaderMaterial in casters:
		shifts.append(caster.get_shader_parameter("shadow_caster_shift"))
	check_eq(shifts, [0.03, 0.0] as Array[float], "each type's shadow shift")
	maize.impostor_shadow_shift = 0.3
	var shift: float = casters[1].get_shader_parameter("shadow_caster_shift")
	check_near(shift, 0.3, 1e-6, "the new shift is drawn")
	check(not field.is_building(), "without a rebuild")
	# Tiles hold one type each, with that type's impostor quads.
	var simulation: NativeField = NativeField.new(field.get_simulation())
	var types_seen: Dictionary = {}
	for tile: int in simulation.get_tile_count():
		var species: int = FarTileTable.new(simulation).species(tile)
		types_seen[species] = true
		var impostors: MultiMeshInstance3D = _node_named(field, "FarTile%d" % FarTileTable.new(simulation).key(tile))
		var material: ShaderMaterial = impostors.multimesh.mesh.surface_get_material(0) as ShaderMaterial
		check(
			(
				material.get_shader_parameter("records_hold_shares") != true
				and is_equal_approx(material.get_shader_parameter("frame_size"), framed[species])
			),
			"tile %d draws its type's impostor from compact records" % tile
		)
	check_eq(types_seen.size(), 2, "tiles of both types")
	# Per-type counts add up to the field's; each type's plants are as tall as it says.
	var by_species: Array[PackedInt32Array] = field.get_lod_counts_by_species()
	var total: PackedInt32Array = field.get_lod_counts()
	var sums: Array[int] = [0, 0]
	for lod: int in total.size():
		check_eq(by_species[0][lod] + by_species[1][lod], total[lod], "LOD %d adds up" % lod)
		sums[0] += by_species[0][lod]
		sums[1] += by_species[1][lod]
	check_eq(sums[1], 60 * 20, "the band of 'm' cells")
	field.force_lod = SunflowerField.Lod.MESH_1
	field.wind_power = 0.0
	field.advance(1.0)
	var maize_plant: int = -1
	var sunflower_plant: int = -1
	for i: int in field.get_plant_count():
		var x: float = field.get_plant_info(i)["position"].x
		if maize_plant < 0 and x > 11.0 and x < 19.0:
			maize_plant = i
		if sunflower_plant < 0 and x < 9.0 and field.get_plant_info(i)["position"].z > 1.0:
			sunflower_plant = i
	var maize_parts: Array = field.get_plant_info(maize_plant)["parts"]
	var sunflower_parts: Array = field.get_plant_info(sunflower_plant)["parts"]
	check_near((maize_parts[0] as Transform3D).basis.y.length(), 1.0, 1e-3, "3 m over 3 units")
	check_near((sunflower_parts[0] as Transform3D).basis.y.length(), 2.0 / 3.0, 1e-3, "2 m over 3 units")
	# The stone is still an object; a symbol that is neither is still an error.
	check(field.get_children(true).any(func(n: Node) -> bool: return n.name.begins_with("Stone")), "the stone")
	check_eq(SunflowerField.FieldLegend.plant_symbols(field.legend), "m")
	check_eq(SunflowerField.FieldLegend.object_symbols(field.legend), "S")


func test_a_hilly_field_of_two_plant_types_renders_both_on_the_hills() -> void:
	var environment: Environment = Environment.new()
	environment.background_mode = Environment.BG_COLOR
	environment.background_color = Color(0.55, 0.7, 0.9)
	environment.ambient_light_source = Environment.AMBIENT_SOURCE_COLOR
	environment.ambient_light_color = Color(0.8, 0.8, 0.85)
	var world: WorldEnvironment = WorldEnvironment.new()
	world.environment = environment
	scene.add_child(world)
	var sun: DirectionalLight3D = DirectionalLight3D.new()
	sun.rotation_degrees = Vector3(-45.0, 30.0, 0.0)
	scene.add_child(sun)
	# Hills as an image: a ridge across the middle, 6 m high.
	var hills: Image = Image.create(33, 33, false, Image.FORMAT_RF)
	for z: int in 33:
		for x: int in 33:
			hills.set_pixel(x, z, Color(0.5 + 0.5 * sin(z * 0.2) * cos(x * 0.15), 0.0, 0.0))
	var field: SunflowerField = SunflowerField.new()
	field.legend = {"m": RED}
	field.map = _mixed_map(60, false)
	field.ground_source = SunflowerField.GroundSource.HEIGHT_MAP
	field.height_map = ImageTexture.create_from_image(hills)
	field.height_range = Vector2(0.0, 6.0)
	field.wind_power = 0.0
	scene.add_child(field)
	field.finish_build()
	var camera: Camera3D = Camera3D.new()
	scene.add_child(camera)
	camera.look_at_from_position(Vector3(15.0, 14.0, 42.0), Vector3(15.0, 2.0, 12.0))
	camera.current = true
	field.observer = camera.get_path()
	await frames(8)
	var image: Image = tree.root.get_viewport().get_texture().get_image()
	image.save_png(artifact_path(SHOT))
	var yellow: int = 0
	var red: int = 0
	for y: int in range(0, image.get_height(), 2):
		for x: int in range(0, image.get_width(), 2):
			var c: Color = image.get_pixel(x, y)
			if c.r > 0.55 and c.g > 0.45 and c.b < 0.3:
				yellow += 1
			elif c.r > 0.35 and c.r > 2.0 * c.g and c.b < 0.25:
				red += 1
	var samples: float = (image.get_width() / 2) * (image.get_height() / 2)
	print("     hilly mixed render: %.1f %% yellow, %.1f %% red" % [yellow * 100.0 / samples, red * 100.0 / samples])
	check(yellow > samples * 0.01, "sunflower heads are seen")
	check(red > samples * 0.003, "red sunflower heads are seen")
	var roots: Array[float] = []
	for i: int in range(0, field.get_plant_count(), 97):
		roots.append(field.get_plant_info(i)["position"].y)
	check(roots.max() - roots.min() > 3.0, "the plants stand on hills")
