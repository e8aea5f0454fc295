@tool
extends RefCounted
## The far representations' look: the impostor materials (one per texture) and the sprite and
## billboard quad meshes, framed as the plant type says (its impostor width, height and sprite
## lean, in model units); made once per field and shared by the field drawn and one being built.

const SHADER: Shader = preload("shaders/impostor.gdshader")
## The materials, by the texture they show.
const KINDS: PackedStringArray = ["front", "side", "billboard"]

var _materials: Dictionary = {}
var _sprite: ArrayMesh
var _billboard: ArrayMesh
var _frame: Vector3 = Vector3(1.6, 3.2, 0.12)  # width, height, sprite lean (model units)


func _init() -> void:
	for kind: String in KINDS:
		var material: ShaderMaterial = ShaderMaterial.new()
		material.shader = SHADER
		material.set_shader_parameter("face_observer", kind == "billboard")
		_materials[kind] = material


## Frames the quads and textures as [param plant] (a FieldPlant) says; the quad meshes are made
## anew when the frame changed (nodes made before keep theirs).
func configure(plant: Resource) -> void:
	for kind: String in KINDS:
		set_texture(kind, plant.texture_drawn(kind))
	var frame: Vector3 = Vector3(plant.impostor_width, plant.height_units, plant.sprite_lean)
	if frame != _frame:
		_frame = frame
		_sprite = null
		_billboard = null


## Shows [param texture] on the [param kind] impostor ("front", "side" or "billboard"); null draws it
## untextured, with a warning.
func set_texture(kind: String, texture: Texture2D) -> void:
	var material: ShaderMaterial = _materials[kind]
	if texture == material.get_shader_parameter("albedo_texture"):
		return
	if texture == null:
		push_warning(
			"SunflowerField: no %s texture; that impostor is drawn untextured (bake the plant's impostors)" % kind
		)
	(_materials[kind] as ShaderMaterial).set_shader_parameter("albedo_texture", texture)


## Sets a shader parameter shared by every impostor material ([code]alpha_scissor[/code],
## [code]thinning_start[/code], [code]thinning_min_density[/code]).
func set_shared(parameter: StringName, value: Variant) -> void:
	for kind: String in KINDS:
		(_materials[kind] as ShaderMaterial).set_shader_parameter(parameter, value)


## Two crossed quads (front texture facing +z, side texture facing +x); the top edge leans
## forward like the nodding head (thesis 3.2.3).
func sprite_mesh() -> ArrayMesh:
	if _sprite == null:
		var w: float = _frame.x * 0.5
		var h: float = _frame.y
		var lean: float = _frame.z
		_sprite = ArrayMesh.new()
		var front: Array = [Vector3(-w, 0, 0), Vector3(w, 0, 0), Vector3(w, h, lean), Vector3(-w, h, lean)]
		var side: Array = [Vector3(0, 0, w), Vector3(0, 0, -w), Vector3(lean, h, -w), Vector3(lean, h, w)]
		_add_quad(_sprite, front, Vector3(0, 0, 1), _materials["front"])
		_add_quad(_sprite, side, Vector3(1, 0, 0), _materials["side"])
	return _sprite


## One quad; the shader turns it about y to face the observer.
func billboard_mesh() -> ArrayMesh:
	if _billboard == null:
		var w: float = _frame.x * 0.5
		var h: float = _frame.y
		_billboard = ArrayMesh.new()
		var corners: Array = [Vector3(-w, 0, 0), Vector3(w, 0, 0), Vector3(w, h, 0), Vector3(-w, h, 0)]
		_add_quad(_billboard, corners, Vector3(0, 0, 1), _materials["billboard"])
	return _billboard


static func _add_quad(mesh: ArrayMesh, corners: Array, normal: Vector3, material: Material) -> void:
	var arrays: Array = []
	arrays.resize(Mesh.ARRAY_MAX)
	arrays[Mesh.ARRAY_VERTEX] = PackedVector3Array(corners)
	arrays[Mesh.ARRAY_NORMAL] = PackedVector3Array([normal, normal, normal, normal])
	arrays[Mesh.ARRAY_TEX_UV] = PackedVector2Array([Vector2(0, 1), Vector2(1, 1), Vector2(1, 0), Vector2(0, 0)])
	arrays[Mesh.ARRAY_INDEX] = PackedInt32Array([0, 2, 1, 0, 3, 2])
	mesh.add_surface_from_arrays(Mesh.PRIMITIVE_TRIANGLES, arrays)
	mesh.surface_set_material(mesh.get_surface_count() - 1, material)
