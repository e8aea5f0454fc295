@tool
extends RefCounted
## The far representations' look: one multi-view impostor material and its quad mesh, framed as
## the plant type says; made once per field and shared by the field drawn and one being built.
## Sprites and billboards draw the same quad (shaders/impostor.gdshader): the plant seen from the
## observer's direction, blended from the plant's baked views, shaded through its baked normals.

const SHADER: Shader = preload("shaders/impostor.gdshader")

var material: ShaderMaterial = ShaderMaterial.new()
var _quad: ArrayMesh
var _stiffness: float = 1.0  # the plant type's
var _field_transform: Transform3D = Transform3D.IDENTITY


func _init() -> void:
	material.shader = SHADER
	material.set_shader_parameter("atlas_views", FieldPlant.ATLAS_VIEWS)


## Frames the quad and shows the views as [param plant] (a FieldPlant) says.
func configure(plant: Resource) -> void:
	for kind: String in FieldPlant.IMPOSTOR_TEXTURES:
		set_texture(kind, plant.texture_drawn(kind))
	_stiffness = plant.stiffness
	# Model units of the bottom part, and of the middle and head above it (how the wind bends them).
	material.set_shader_parameter(
		"part_reach", Vector2(plant.part_lengths.x, plant.part_lengths.y + plant.part_lengths.z)
	)
	var frame: Vector2 = plant.impostor_frame()
	material.set_shader_parameter("frame_size", frame.x)
	material.set_shader_parameter("frame_centre", frame.y)


## Shows [param texture] as the impostor's [param kind] ("views" or "normals"); null draws it
## untextured, with a warning.
func set_texture(kind: String, texture: Texture2D) -> void:
	var parameter: String = "view_atlas" if kind == "views" else "normal_atlas"
	if texture == material.get_shader_parameter(parameter):
		return
	if texture == null:
		push_warning(
			(
				"SunflowerField: no impostor %s texture; the far plants are drawn untextured (bake the plant's impostors)"
				% kind
			)
		)
	material.set_shader_parameter(parameter, texture)


## Sets a shader parameter of the impostor material ([code]alpha_scissor[/code],
## [code]thinning_start[/code], [code]thinning_min_density[/code]).
func set_shared(parameter: StringName, value: Variant) -> void:
	material.set_shader_parameter(parameter, value)


## Sways the far plants this frame: the field-wide wind [param state] (the simulation's
## [code]get_wind_state()[/code]), the [param wind]'s stiffnesses and the field's
## [param field_transform] (the wind is computed in the field's own frame, as the core does).
func sway(state: PackedFloat32Array, wind: SunflowerWind, field_transform: Transform3D) -> void:
	material.set_shader_parameter("wind_state_a", Vector4(state[0], state[1], state[2], state[3]))
	material.set_shader_parameter("wind_state_b", Vector4(state[4], state[5], state[6], state[7]))
	material.set_shader_parameter("bend_stiffness", Vector2(wind.stiffness_bottom, wind.stiffness_middle) * _stiffness)
	if field_transform != _field_transform:
		_field_transform = field_transform
		material.set_shader_parameter("world_from_field", Projection(field_transform))
		material.set_shader_parameter("field_from_world", Projection(field_transform.affine_inverse()))


## A unit square the shader turns to the observer and scales to the frame. (What it shows lies in
## the plant's cylinder, inside the cull radius the chunks' bounds are made from.)
func mesh() -> ArrayMesh:
	if _quad == null:
		_quad = ArrayMesh.new()
		var arrays: Array = []
		arrays.resize(Mesh.ARRAY_MAX)
		arrays[Mesh.ARRAY_VERTEX] = PackedVector3Array(
			[Vector3(-0.5, -0.5, 0), Vector3(0.5, -0.5, 0), Vector3(0.5, 0.5, 0), Vector3(-0.5, 0.5, 0)]
		)
		arrays[Mesh.ARRAY_NORMAL] = PackedVector3Array([Vector3.BACK, Vector3.BACK, Vector3.BACK, Vector3.BACK])
		arrays[Mesh.ARRAY_TEX_UV] = PackedVector2Array([Vector2(0, 1), Vector2(1, 1), Vector2(1, 0), Vector2(0, 0)])
		arrays[Mesh.ARRAY_INDEX] = PackedInt32Array([0, 2, 1, 0, 3, 2])
		_quad.add_surface_from_arrays(Mesh.PRIMITIVE_TRIANGLES, arrays)
		_quad.surface_set_material(0, material)
	return _quad
