extends TestCase
## A plant of one part from a scene (a 10 m pole, SunflowerPlant.from_scene) bends in the wind from
## its base, as a box with vertices all the way up, with a shader of its own and as one card from
## foot to top; its upper part flutters.

const Stage: GDScript = preload("res://runner/stage.gd")
const Maps: GDScript = preload("res://runner/maps.gd")

var stage: Node3D


func after_each() -> void:
	if stage:
		stage.free()
		stage = null


func test_a_plant_of_one_part_bends_in_the_wind_and_its_base_stands() -> void:
	var bases: PackedFloat32Array = []
	for kind: String in ["a StandardMaterial3D", "a shader of its own", "one card"]:
		var pole: Dictionary = _pole_field(_red_shader() if kind == "a shader of its own" else null, kind == "one card")
		var field: SunflowerField = pole.field
		var centres: Array[PackedFloat32Array] = []
		for power: float in [0.0, 6.0]:
			field.wind_power = power
			for step: int in 90:
				field.advance(1.0 / 30.0)
			await frames(4)
			var image: Image = tree.root.get_viewport().get_texture().get_image()
			image.save_png(artifact_path("scene_plant_pole_wind_%d_%s.png" % [int(power), kind.replace(" ", "_")]))
			centres.append(PackedFloat32Array([_pole_centre(pole, image, 1.0), _pole_centre(pole, image, 9.5)]))
		var low: float = centres[1][0] - centres[0][0]
		var top: float = centres[1][1] - centres[0][1]
		print("     a 10 m pole (%s) in wind 6: its top moves %.2f m, a point 1 m up %.3f m" % [kind, top, low])
		check(top > 0.3, "%s: the top sways with the wind (%.2f m)" % [kind, top])
		check(absf(low) < 0.05 * absf(top), "%s: the base stands (1 m up moves %.3f m)" % [kind, low])
		bases.append(centres[0][0])
		stage.free()
		stage = null
	check(absf(bases[1] - bases[0]) < 0.05, "the shader's own shift is left out (%.2f m)" % (bases[1] - bases[0]))


## Leaves flutter ([member SunflowerPlant.flutter]): the pole bent by wind 6, the field held still (no
## updates, so its bend stays), drawn over eight frames. With flutter its upper part (8 m up: the
## top itself dips up to ~1 m as it moves, so a row nearer it may miss it) moves from frame to frame
## and a point a tenth of its height up under a tenth as far; without, it stays. The pole is in both
## rows in every frame (a frame without it would count as a large move).
func test_a_plant_of_one_part_flutters_at_its_top() -> void:
	var pole: Dictionary = _pole_field()
	var field: SunflowerField = pole.field
	field.wind_power = 6.0
	for step: int in 90:
		field.advance(1.0 / 30.0)
	var spreads: Array[Vector2] = []
	for flutter: float in [0.0, 1.0]:
		(pole.plant as SunflowerPlant).flutter = flutter
		await frames(2)
		var tops: PackedFloat32Array = []
		var lows: PackedFloat32Array = []
		for frame: int in 8:
			await frames(1)
			var image: Image = tree.root.get_viewport().get_texture().get_image()
			if frame == 0:
				image.save_png(artifact_path("scene_plant_pole_flutter_%d.png" % int(flutter)))
			tops.append(_pole_centre(pole, image, 8.0))
			lows.append(_pole_centre(pole, image, 1.0))
		var missing: PackedStringArray = []
		for frame: int in tops.size():
			if tops[frame] < 0.0 or lows[frame] < 0.0:
				missing.append("frame %d (top %.2f, low %.2f)" % [frame, tops[frame], lows[frame]])
		check(
			missing.is_empty(), "flutter %.1f: the pole in every frame, missing in %s" % [flutter, ", ".join(missing)]
		)
		spreads.append(Vector2(_spread(lows), _spread(tops)))
	print(
		(
			"     the pole in wind 6 over 8 frames, 8 m / 1 m up moving: still %.3f / %.3f m, fluttering %.3f / %.3f m"
			% [spreads[0].y, spreads[0].x, spreads[1].y, spreads[1].x]
		)
	)
	check(spreads[0].y < 0.02, "without flutter the held field's upper part stays (%.3f m)" % spreads[0].y)
	check(spreads[1].y > 0.2, "with flutter the upper part moves (%.3f m)" % spreads[1].y)
	check(spreads[1].x < 0.1 * spreads[1].y, "the base hardly flutters (%.3f m)" % spreads[1].x)


## A field of one 10 m red pole from a scene (a plant of one part drawn whole), wind from −x, seen
## from the side through an orthographic camera 12 m high: field, plant, camera and the pole's root.
## [param material]: the pole's ([method _red] when null); [param card]: the pole is one quad facing
## the camera, two triangles from its foot to its top (else a box with vertices all the way up).
func _pole_field(material: Material = null, card: bool = false) -> Dictionary:
	stage = Stage.new(tree.root).root
	var pole: Node3D = Node3D.new()
	var body: MeshInstance3D = MeshInstance3D.new()
	if card:
		var quad: QuadMesh = QuadMesh.new()
		quad.size = Vector2(0.3, 10.0)
		quad.material = material if material else _red()
		body.mesh = quad
	else:
		var box: BoxMesh = BoxMesh.new()
		box.size = Vector3(0.3, 10.0, 0.3)
		box.subdivide_height = 40  # vertices all the way up, as a trunk has
		box.material = material if material else _red()
		body.mesh = box
	body.position.y = 5.0
	pole.add_child(body)
	body.owner = pole
	var packed: PackedScene = PackedScene.new()
	packed.pack(pole)
	pole.free()
	var plant: SunflowerPlant = SunflowerPlant.from_scene(packed)
	plant.yaw_range = 0.0
	check(plant.drawn_whole(), "the pole is drawn whole (its shader bends it)")
	var field: SunflowerField = SunflowerField.new()
	field.plant = plant
	field.map = Maps.filled(1, 1, "user://one_pole.field")
	field.wind_direction = Vector2(1.0, 0.0)
	field.lod_fade = 0.0
	field.force_lod = SunflowerField.Lod.MESH_1
	stage.add_child(field)
	field.finish_build()
	field.set_process(false)
	var root: Vector3 = field.get_plant_info(0)["position"]
	var camera: Camera3D = Camera3D.new()
	stage.add_child(camera)
	camera.projection = Camera3D.PROJECTION_ORTHOGONAL
	camera.size = 12.0
	camera.look_at_from_position(root + Vector3(0.0, 5.5, 30.0), root + Vector3(0.0, 5.5, 0.0))
	camera.make_current()
	return {"field": field, "plant": plant, "camera": camera, "root": root}


static func _red() -> StandardMaterial3D:
	var red: StandardMaterial3D = StandardMaterial3D.new()
	red.albedo_color = Color(1.0, 0.02, 0.02)
	return red


## A red ShaderMaterial of its own that, outside a field, shifts its mesh 3 m along +x (a wind of its
## own, which it leaves to the field's bend there).
static func _red_shader() -> ShaderMaterial:
	var shader: Shader = Shader.new()
	shader.code = "shader_type spatial;\nuniform vec4 tint : source_color = vec4(1.0, 0.02, 0.02, 1.0);\n"
	shader.code += "void vertex() {\n#ifndef PLANT_BENT_BY_FIELD\n\tVERTEX.x += 3.0;\n#endif\n}\n"
	shader.code += "void fragment() {\n\tALBEDO = tint.rgb;\n}\n"
	var red: ShaderMaterial = ShaderMaterial.new()
	red.shader = shader
	return red


## Where the pole of [method _pole_field] is across [param image] at [param height] metres above its
## root, in metres from the picture's left edge (negative when it is not in that row).
func _pole_centre(pole: Dictionary, image: Image, height: float) -> float:
	var camera: Camera3D = pole.camera
	var pixels_per_metre: float = image.get_height() / camera.size
	var row: int = int(image.get_height() * 0.5 - (height - 5.5) * pixels_per_metre)
	return _red_centre(image, row) / pixels_per_metre


static func _spread(values: PackedFloat32Array) -> float:
	var low: float = INF
	var high: float = -INF
	for value: float in values:
		low = minf(low, value)
		high = maxf(high, value)
	return high - low


## The mean column of the pole's red pixels in [param row] (-1 when none).
func _red_centre(image: Image, row: int) -> float:
	var sum: float = 0.0
	var count: int = 0
	for x: int in image.get_width():
		var c: Color = image.get_pixel(x, clampi(row, 0, image.get_height() - 1))
		if c.r > 0.3 and c.r > 3.0 * c.g and c.r > 3.0 * c.b:
			sum += x
			count += 1
	return sum / count if count > 0 else -1.0
