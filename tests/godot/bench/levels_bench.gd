extends SceneTree
## Generated levels benchmark (numbers, not pass/fail; tools/bench.sh runs it headless): how long
## [method SunflowerPlant.from_scene] takes to make a plant of many foliage cards, its levels 2 and 3
## thinned and their kept cards grown to the cover measured (plant_cover.gd: in five views up to
## [constant PlantLevels.COVER_CARD_TRIANGLES] card triangles, in one above). Two kinds of card on a 1 m square:
## blades (1 cm wide, 0.3–0.6 m tall, leaning) and broad cards (30 cm wide, cut out by a disc in their
## texture, the slow case of the cover's rows); then the Sapling test plants, and curtains of twigs
## (the branches' cover measured, [constant PlantLevels.COVER_BRANCH_TRIANGLES], their kept twigs
## thickened). Prints the median of [constant RUNS] runs.

const ScenePlant: GDScript = preload("res://addons/sunflower_field/plant/scene_plant.gd")
const PlantLevels: GDScript = preload("res://addons/sunflower_field/plant/plant_levels.gd")
const Scenes: GDScript = preload("res://runner/scenes.gd")
const MeshPieces: GDScript = preload("res://addons/sunflower_field/plant/mesh_pieces.gd")
const RUNS: int = 3
## Cards per plant (two triangles each).
const CARDS: Array[int] = [5_000, 10_000, 20_000]
## Twigs per curtain (48 triangles each, seven leaf cards beside each).
const TWIGS: Array[int] = [48, 400, 800]
## The test plants (test_scene_plant.gd).
const ScenePlantTests: GDScript = preload("res://cases/test_scene_plant.gd")


func _initialize() -> void:
	print("| cards | card triangles | blades (s) | broad cut-out cards (s) |")
	print("|---|---|---|---|")
	for cards: int in CARDS:
		var times: Array[String] = []
		for half_width: float in [0.005, 0.15]:
			var scene: PackedScene = _card_plant(cards, half_width)
			var seconds: Array[float] = []
			for run: int in RUNS:
				var started: int = Time.get_ticks_usec()
				var plant: SunflowerPlant = SunflowerPlant.from_scene(scene)
				seconds.append((Time.get_ticks_usec() - started) / 1e6)
				if plant == null:
					push_error("levels_bench: no plant made of %d cards" % cards)
			seconds.sort()
			times.append("%.1f" % seconds[RUNS / 2])
		var how: String = ""  # how the cover is measured: in five views, one, or not at all
		if 2 * cards > PlantLevels.COVER_ONE_VIEW_TRIANGLES:
			how = " (unmeasured)"
		elif 2 * cards > PlantLevels.COVER_CARD_TRIANGLES:
			how = " (one view)"
		print("| %d | %d | %s%s | %s%s |" % [cards, 2 * cards, times[0], how, times[1], how])
	print("")
	print("| plant | triangles (leaves / other) | made (s) |")
	print("|---|---|---|")
	var plants: Dictionary = {}
	for file: String in ScenePlantTests.TEST_PLANTS:
		plants[file.get_basename()] = load(ScenePlantTests.TEST_PLANT_FOLDER.path_join(file))
	for twigs: int in TWIGS:
		plants["curtain of %d twigs" % twigs] = Scenes.twig_curtain(twigs)
	for plant_name: String in plants:
		var seconds: Array[float] = []
		var plant: SunflowerPlant = null
		for run: int in RUNS:
			var started: int = Time.get_ticks_usec()
			plant = SunflowerPlant.from_scene(plants[plant_name])
			seconds.append((Time.get_ticks_usec() - started) / 1e6)
		seconds.sort()
		var mesh: ArrayMesh = plant.mesh_level_1[0] if plant else null
		var leaves: int = 0
		for surface: int in mesh.get_surface_count() if mesh else 0:
			var pieces: MeshPieces = MeshPieces.new(mesh.surface_get_arrays(surface))
			leaves += pieces.piece_of.size() if pieces.are_cards() else 0
		var triangles: int = ScenePlant.triangle_count(mesh) if mesh else 0
		print("| %s | %d / %d | %.2f |" % [plant_name, leaves, triangles - leaves, seconds[RUNS / 2]])
	quit()


## A scene of one node drawing [param cards] cards of [param half_width] standing on a 1 m square,
## cut out by a disc in their texture.
func _card_plant(cards: int, half_width: float) -> PackedScene:
	var random: RandomNumberGenerator = RandomNumberGenerator.new()
	random.seed = 17
	var tool: SurfaceTool = SurfaceTool.new()
	tool.begin(Mesh.PRIMITIVE_TRIANGLES)
	var corners_uv: Array[Vector2] = [Vector2(0, 1), Vector2(1, 1), Vector2(1, 0), Vector2(0, 0)]
	for card: int in cards:
		var foot: Vector3 = Vector3(random.randf_range(-0.5, 0.5), 0.0, random.randf_range(-0.5, 0.5))
		var turn: float = random.randf() * TAU
		var across: Vector3 = Vector3(cos(turn), 0.0, sin(turn)) * half_width
		var top: Vector3 = Vector3(
			random.randf_range(-0.1, 0.1), random.randf_range(0.3, 0.6), random.randf_range(-0.1, 0.1)
		)
		var corners: Array[Vector3] = [foot - across, foot + across, foot + across + top, foot - across + top]
		for corner: int in [0, 1, 2, 0, 2, 3]:
			tool.set_normal(across.cross(top).normalized())
			tool.set_uv(corners_uv[corner])
			tool.add_vertex(corners[corner])
	tool.index()
	var disc: Image = Image.create(32, 32, false, Image.FORMAT_RGBA8)
	for y: int in 32:
		for x: int in 32:
			disc.set_pixel(x, y, Color(0.2, 0.6, 0.2, 1.0 if Vector2(x - 15.5, y - 15.5).length() < 14.0 else 0.0))
	var material: StandardMaterial3D = StandardMaterial3D.new()
	material.transparency = BaseMaterial3D.TRANSPARENCY_ALPHA_SCISSOR
	material.albedo_texture = ImageTexture.create_from_image(disc)
	var root: Node3D = Node3D.new()
	var leaves: MeshInstance3D = MeshInstance3D.new()
	leaves.name = "Cards"
	leaves.mesh = tool.commit()
	leaves.material_override = material
	root.add_child(leaves)
	return Scenes.packed(root)
