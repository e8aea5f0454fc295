class_name DemoHills
extends Node3D
## Rolling hills for the demo: one generated height image makes both the terrain's collision (a
## HeightMapShape3D) and its mesh. The field stands on the collision (ground source Colliders), as
## it would on any game's terrain.

## Height samples per side, one metre apart.
const SIDE: int = 161
## The heights of the image's red 0 and 1.
const LOW: float = -3.0
const HIGH: float = 9.0
const SEED: int = 20081

var _body: StaticBody3D
var _mesh: MeshInstance3D


## The hills' heights as red 0–1 (FORMAT_RF, as HeightMapShape3D reads images).
static func height_image() -> Image:
	var noise: FastNoiseLite = FastNoiseLite.new()
	noise.seed = SEED
	noise.frequency = 0.012
	noise.fractal_octaves = 3
	var image: Image = Image.create(SIDE, SIDE, false, Image.FORMAT_RF)
	for z: int in SIDE:
		for x: int in SIDE:
			image.set_pixel(x, z, Color(clampf(0.5 + 0.6 * noise.get_noise_2d(x, z), 0.0, 1.0), 0.0, 0.0))
	return image


func _ready() -> void:
	var image: Image = height_image()
	var shape: HeightMapShape3D = HeightMapShape3D.new()
	shape.update_map_data_from_image(image, LOW, HIGH)
	var collision: CollisionShape3D = CollisionShape3D.new()
	collision.shape = shape
	_body = StaticBody3D.new()
	_body.add_child(collision)
	add_child(_body)
	_mesh = MeshInstance3D.new()
	_mesh.mesh = _terrain_mesh(shape.map_data)
	add_child(_mesh)
	set_enabled(false)


## Shows the hills and makes them ground (collision layer 1), or hides them and takes them out.
func set_enabled(enabled: bool) -> void:
	visible = enabled
	_body.collision_layer = 1 if enabled else 0


## The terrain's mesh: the collision's heights as a grid of triangles with smooth normals, centred
## like the HeightMapShape3D.
func _terrain_mesh(heights: PackedFloat32Array) -> ArrayMesh:
	var half: float = (SIDE - 1) * 0.5
	var vertices: PackedVector3Array = []
	var normals: PackedVector3Array = []
	for z: int in SIDE:
		for x: int in SIDE:
			vertices.append(Vector3(x - half, heights[z * SIDE + x], z - half))
			var left: float = heights[z * SIDE + maxi(x - 1, 0)]
			var right: float = heights[z * SIDE + mini(x + 1, SIDE - 1)]
			var back: float = heights[maxi(z - 1, 0) * SIDE + x]
			var front: float = heights[mini(z + 1, SIDE - 1) * SIDE + x]
			normals.append(Vector3(left - right, 2.0, back - front).normalized())
	var indices: PackedInt32Array = []
	for z: int in SIDE - 1:
		for x: int in SIDE - 1:
			var i: int = z * SIDE + x
			indices.append_array([i, i + 1, i + SIDE, i + 1, i + SIDE + 1, i + SIDE])
	var arrays: Array = []
	arrays.resize(Mesh.ARRAY_MAX)
	arrays[Mesh.ARRAY_VERTEX] = vertices
	arrays[Mesh.ARRAY_NORMAL] = normals
	arrays[Mesh.ARRAY_INDEX] = indices
	var mesh: ArrayMesh = ArrayMesh.new()
	mesh.add_surface_from_arrays(Mesh.PRIMITIVE_TRIANGLES, arrays)
	var soil: StandardMaterial3D = StandardMaterial3D.new()
	soil.albedo_color = Color(0.36, 0.3, 0.17)
	mesh.surface_set_material(0, soil)
	return mesh
