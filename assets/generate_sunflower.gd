extends SceneTree
## Generates the default sunflower models: three levels of detail × three parts (bottom, middle,
## head), each with its root at the origin and height 1 along +y, so parts chain end to start.
## The head faces +z and nods forward. Colours are vertex colours (no textures needed).
##
## Run: godot --headless --path <any project> --script assets/generate_sunflower.gd -- <out dir> [red]
## Writes sunflower_lod{1,2,3}_{bottom,middle,head}.res into <out dir> and prints triangle counts.
## With "red": the same plant as a red-petalled cultivar ("red_sunflower_lod…"), the addon's second
## plant type (plants/red_sunflower.tres), drawn lower by its SunflowerPlant.

const STEM_GREEN: Color = Color(0.23, 0.42, 0.11)
const LEAF_GREEN: Color = Color(0.20, 0.45, 0.10)
const LEAF_VEIN: Color = Color(0.42, 0.60, 0.22)
const DISC_BROWN: Color = Color(0.26, 0.13, 0.04)
const DISC_CENTRE: Color = Color(0.20, 0.17, 0.05)
const BACK_GREEN: Color = Color(0.28, 0.45, 0.13)
## Petal colours (base, tip) by variant.
const PETALS: Dictionary = {
	"": [Color(1.0, 0.76, 0.03), Color(1.0, 0.86, 0.25)],
	"red": [Color(0.62, 0.07, 0.05), Color(0.93, 0.45, 0.08)],
}

## Detail per level: stem sides and rings, leaf grid (along × across), head rings and sectors,
## petals per row, rows of petals, petal segments.
const LEVELS: Array[Dictionary] = [
	{
		"sides": 12,
		"rings": 8,
		"leaf_u": 16,
		"leaf_v": 8,
		"disc_rings": 6,
		"sectors": 32,
		"petals": 30,
		"petal_rows": 2,
		"petal_segments": 4
	},
	{
		"sides": 8,
		"rings": 5,
		"leaf_u": 10,
		"leaf_v": 6,
		"disc_rings": 4,
		"sectors": 20,
		"petals": 22,
		"petal_rows": 2,
		"petal_segments": 3
	},
	{
		"sides": 6,
		"rings": 3,
		"leaf_u": 8,
		"leaf_v": 4,
		"disc_rings": 3,
		"sectors": 14,
		"petals": 18,
		"petal_rows": 2,
		"petal_segments": 2
	},
]

var _petal_base: Color
var _petal_tip: Color


class MeshBuilder:
	var vertices: PackedVector3Array = PackedVector3Array()
	var colors: PackedColorArray = PackedColorArray()
	var indices: PackedInt32Array = PackedInt32Array()

	func add_vertex(position: Vector3, color: Color) -> int:
		vertices.append(position)
		colors.append(color)
		return vertices.size() - 1

	func add_triangle(a: int, b: int, c: int) -> void:
		indices.append_array([a, b, c])

	## A grid of (u_count + 1) × (v_count + 1) vertices from a function of (u, v) in [0, 1]².
	func add_grid(u_count: int, v_count: int, point: Callable, color: Callable) -> void:
		var base: int = vertices.size()
		for i: int in u_count + 1:
			for j: int in v_count + 1:
				var u: float = float(i) / u_count
				var v: float = float(j) / v_count
				add_vertex(point.call(u, v), color.call(u, v))
		for i: int in u_count:
			for j: int in v_count:
				var a: int = base + i * (v_count + 1) + j
				var b: int = a + v_count + 1
				add_triangle(a, b, a + 1)
				add_triangle(a + 1, b, b + 1)

	func triangle_count() -> int:
		return indices.size() / 3

	func build(material: Material) -> ArrayMesh:
		var normals: PackedVector3Array = PackedVector3Array()
		normals.resize(vertices.size())
		for t: int in range(0, indices.size(), 3):
			var a: Vector3 = vertices[indices[t]]
			var face: Vector3 = (vertices[indices[t + 2]] - a).cross(vertices[indices[t + 1]] - a)
			for k: int in 3:
				normals[indices[t + k]] += face
		for n: int in normals.size():
			normals[n] = normals[n].normalized() if normals[n].length() > 1e-9 else Vector3.UP
		var arrays: Array = []
		arrays.resize(Mesh.ARRAY_MAX)
		arrays[Mesh.ARRAY_VERTEX] = vertices
		arrays[Mesh.ARRAY_NORMAL] = normals
		arrays[Mesh.ARRAY_COLOR] = colors
		arrays[Mesh.ARRAY_INDEX] = indices
		var mesh: ArrayMesh = ArrayMesh.new()
		mesh.add_surface_from_arrays(Mesh.PRIMITIVE_TRIANGLES, arrays)
		mesh.surface_set_material(0, material)
		return mesh


func _init() -> void:
	var args: PackedStringArray = OS.get_cmdline_user_args()
	if args.is_empty():
		printerr("usage: godot --headless --script generate_sunflower.gd -- <output folder>")
		quit(2)
		return
	var out_dir: String = args[0]
	var variant: String = args[1] if args.size() > 1 else ""
	if not PETALS.has(variant):
		printerr("unknown variant '%s' (none, or red)" % variant)
		quit(2)
		return
	_petal_base = PETALS[variant][0]
	_petal_tip = PETALS[variant][1]
	var prefix: String = "sunflower" if variant.is_empty() else variant + "_sunflower"
	DirAccess.make_dir_recursive_absolute(out_dir)
	# Vertex colours (picked in sRGB) as albedo, both faces, and the cross-fade into the impostor.
	var material: ShaderMaterial = ShaderMaterial.new()
	material.shader = load("res://addons/sunflower_field/shaders/plant_parts.gdshader")
	material.resource_name = "sunflower_parts"
	var failed: bool = false
	for level: int in LEVELS.size():
		var detail: Dictionary = LEVELS[level]
		var parts: Array[MeshBuilder] = [_bottom(detail), _middle(detail), _head(detail)]
		var names: Array[String] = ["bottom", "middle", "head"]
		var total: int = 0
		for p: int in 3:
			total += parts[p].triangle_count()
			var path: String = out_dir.path_join("%s_lod%d_%s.res" % [prefix, level + 1, names[p]])
			var error: Error = ResourceSaver.save(parts[p].build(material), path, ResourceSaver.FLAG_COMPRESS)
			if error != OK:
				printerr("cannot save %s: %s" % [path, error_string(error)])
				failed = true
		print(
			(
				"level %d: %d triangles (bottom %d, middle %d, head %d)"
				% [level + 1, total, parts[0].triangle_count(), parts[1].triangle_count(), parts[2].triangle_count()]
			)
		)
	quit(1 if failed else 0)


## A tapered stem from y0 to y1 following a curve x/z = bend(y).
func _stem(
	builder: MeshBuilder, detail: Dictionary, radius0: float, radius1: float, y1: float, curve: Callable
) -> void:
	var sides: int = detail["sides"]
	var rings: int = detail["rings"]
	builder.add_grid(
		rings,
		sides,
		func(u: float, v: float) -> Vector3:
			var angle: float = v * TAU
			var radius: float = lerpf(radius0, radius1, u)
			var centre: Vector3 = curve.call(u * y1)
			return centre + Vector3(cos(angle) * radius, 0.0, sin(angle) * radius),
		func(u: float, _v: float) -> Color: return STEM_GREEN.lightened(0.08 * u)
	)


func _straight(y: float) -> Vector3:
	return Vector3(0.0, y, 0.0)


## A broad, pointed, drooping sunflower leaf on a short petiole.
func _leaf(
	builder: MeshBuilder, detail: Dictionary, height: float, angle: float, length: float, width: float, droop: float
) -> void:
	var dir: Vector3 = Vector3(cos(angle), 0.0, sin(angle))
	var side: Vector3 = Vector3(-dir.z, 0.0, dir.x)
	var base: Vector3 = Vector3(0.0, height, 0.0) + dir * 0.025
	var petiole_end: Vector3 = base + dir * length * 0.28 + Vector3(0.0, length * 0.12, 0.0)
	# Petiole: a thin flat strip.
	builder.add_grid(
		2,
		1,
		func(u: float, v: float) -> Vector3: return base.lerp(petiole_end, u) + side * (v - 0.5) * 0.02,
		func(_u: float, _v: float) -> Color: return STEM_GREEN
	)
	builder.add_grid(
		detail["leaf_u"],
		detail["leaf_v"],
		func(u: float, v: float) -> Vector3:
			# Heart-to-point outline: widest near a third of the way, pointed at the tip.
			var half_width: float = width * 0.5 * sin(PI * pow(u, 0.75)) * (1.0 - 0.25 * u)
			var across: float = (v - 0.5) * 2.0
			var along: Vector3 = dir * length * u
			var sag: float = -droop * length * u * u  # the blade droops towards its tip
			var fold: float = absf(across) * half_width * 0.35  # a shallow V along the midrib
			return petiole_end + along + side * across * half_width + Vector3(0.0, sag + fold, 0.0),
		func(u: float, v: float) -> Color:
			var vein: float = clampf(1.0 - absf(v - 0.5) * 10.0, 0.0, 1.0)
			return LEAF_GREEN.lerp(LEAF_VEIN, vein * 0.7).darkened(0.12 * u)
	)


func _bottom(detail: Dictionary) -> MeshBuilder:
	var builder: MeshBuilder = MeshBuilder.new()
	_stem(builder, detail, 0.042, 0.036, 1.0, _straight)
	var golden: float = deg_to_rad(137.5)
	var heights: Array[float] = [0.28, 0.5, 0.7, 0.9]
	for i: int in heights.size():
		_leaf(builder, detail, heights[i], 0.4 + golden * i, 0.6, 0.5, 0.5)
	return builder


func _middle(detail: Dictionary) -> MeshBuilder:
	var builder: MeshBuilder = MeshBuilder.new()
	_stem(builder, detail, 0.036, 0.030, 1.0, _straight)
	var golden: float = deg_to_rad(137.5)
	var heights: Array[float] = [0.2, 0.45, 0.68, 0.9]
	for i: int in heights.size():
		_leaf(builder, detail, heights[i], 2.1 + golden * i, 0.52 - 0.05 * i, 0.44 - 0.04 * i, 0.45)
	return builder


## The neck curves forward; the head faces +z, nodding down.
func _neck(y: float) -> Vector3:
	var t: float = y / 0.62
	return Vector3(0.0, y, 0.12 * t * t * t)


func _head(detail: Dictionary) -> MeshBuilder:
	var builder: MeshBuilder = MeshBuilder.new()
	_stem(builder, detail, 0.030, 0.026, 0.62, _neck)
	_leaf(builder, detail, 0.3, 4.0, 0.28, 0.24, 0.4)
	# The head: a disc facing forward and a little down, centred in front of the neck's top.
	var facing: Vector3 = Vector3(0.0, -0.35, 1.0).normalized()
	var up: Vector3 = Vector3.UP.cross(facing).cross(facing).normalized() * -1.0
	var right: Vector3 = up.cross(facing).normalized()
	var centre: Vector3 = Vector3(0.0, 0.66, 0.19)
	var disc_radius: float = 0.17
	var sectors: int = detail["sectors"]
	var disc_rings: int = detail["disc_rings"]
	var at: Callable = func(radius: float, angle: float, depth: float) -> Vector3:
		return centre + (right * cos(angle) + up * sin(angle)) * radius + facing * depth
	# Seed disc, slightly domed.
	builder.add_grid(
		disc_rings,
		sectors,
		func(u: float, v: float) -> Vector3: return at.call(disc_radius * u, v * TAU, 0.025 * (1.0 - u * u)),
		func(u: float, _v: float) -> Color:
			return DISC_CENTRE.lerp(DISC_BROWN, u).darkened(0.15 * (1.0 - absf(sin(u * 9.0))))
	)
	# Back of the head: a green shallow bowl behind the disc.
	builder.add_grid(
		maxi(disc_rings - 1, 1),
		sectors,
		func(u: float, v: float) -> Vector3: return at.call(disc_radius * (1.04 - 0.7 * u * u), -v * TAU, -0.07 * u),
		func(_u: float, _v: float) -> Color: return BACK_GREEN
	)
	# Ray petals around the rim, in rows, curving slightly backwards.
	var petals: int = detail["petals"]
	var segments: int = detail["petal_segments"]
	for row: int in detail["petal_rows"]:
		for p: int in petals:
			var angle: float = (p + 0.5 * row) * TAU / petals
			var radial: Vector3 = right * cos(angle) + up * sin(angle)
			var tangent: Vector3 = facing.cross(radial).normalized()
			var length: float = 0.2 - 0.03 * row
			var root: Vector3 = centre + radial * disc_radius * 0.95 - facing * (0.01 + 0.012 * row)
			builder.add_grid(
				segments,
				1,
				func(u: float, v: float) -> Vector3:
					var half_width: float = 0.05 * sin(PI * (0.15 + 0.85 * u))
					return (
						root
						+ radial * length * u
						+ tangent * (v - 0.5) * 2.0 * half_width
						- facing * (0.04 * u * u + 0.01 * row)
					),
				func(u: float, _v: float) -> Color: return _petal_base.lerp(_petal_tip, u * 0.6).darkened(0.08 * row)
			)
	return builder
