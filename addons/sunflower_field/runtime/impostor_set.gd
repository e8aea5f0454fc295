@tool
extends RefCounted
## The far representations' look: one multi-view impostor material and its quad mesh, framed as
## the plant type says; made once per field and shared by the field drawn and one being built.
## Sprites and billboards draw the same quad (shaders/impostor.gdshader): the plant seen from the
## observer's direction, blended from the plant's baked views, shaded through its baked normals.
## Both draw it from compact 8-float instance records: the near bucket's carry each plant's share
## of the pixels ([code]records_hold_shares[/code]), the far tiles' their chunk's cell, which the
## tiles' twin of the material looks up in the mask of active chunks. Each has a shadow caster's
## twin (shaders/impostor_shadow.gdshader), drawn from the same records by nodes that cast shadows
## only; every other parameter is set on all four.

const SHADER: Shader = preload("../shaders/impostor.gdshader")
const SHADOW_SHADER: Shader = preload("../shaders/impostor_shadow.gdshader")
## The shader's sampler of each of [constant SunflowerPlant.IMPOSTOR_TEXTURES].
const ATLAS_PARAMETERS: Dictionary = {"views": "view_atlas", "normals": "normal_atlas", "depths": "depth_atlas"}

## The mip levels of the views whose alpha cut the shader takes (its alpha_cuts array): an atlas
## 32 768 texels wide has 16.
const ALPHA_CUT_LEVELS: int = 16

## The material of the near bucket's impostors (records with shares).
var material: ShaderMaterial = ShaderMaterial.new()
## The material of the far tiles' impostors (records with their chunk's cell).
var tile_material: ShaderMaterial = ShaderMaterial.new()
## Their shadow casters' materials.
var caster_material: ShaderMaterial = ShaderMaterial.new()
var tile_caster_material: ShaderMaterial = ShaderMaterial.new()
var _quads: Array[ArrayMesh] = [null, null]  # [near, tiles]
var _stiffness: float = 1.0  # the plant type's
var _field_transform: Transform3D = Transform3D.IDENTITY


func _init() -> void:
	material.shader = SHADER
	material.set_shader_parameter("records_hold_shares", true)
	tile_material.shader = SHADER
	caster_material.shader = SHADOW_SHADER
	caster_material.set_shader_parameter("records_hold_shares", true)
	tile_caster_material.shader = SHADOW_SHADER
	_set_all("atlas_views", SunflowerPlant.ATLAS_VIEWS)


## Frames the quad and shows the views as [param plant] (a SunflowerPlant) says.
func configure(plant: Resource) -> void:
	for kind: String in SunflowerPlant.IMPOSTOR_TEXTURES:
		set_texture(kind, plant.texture_drawn(kind))
	set_emission(plant.texture_drawn(SunflowerPlant.EMISSION_TEXTURE), plant.impostor_emission_range)
	set_backlight(plant.texture_drawn(SunflowerPlant.BACKLIGHT_TEXTURE))
	_stiffness = plant.stiffness
	# Model units of the bottom part, and of the middle and head above it (how the wind bends them).
	var lengths: Vector3 = plant.stacked_lengths()
	_set_all("part_reach", Vector2(lengths.x, lengths.y + lengths.z))
	var frame: Vector2 = plant.impostor_frame()
	_set_all("frame_size", frame.x)
	_set_all("frame_centre", frame.y)
	_set_all("shadow_caster_shift", plant.impostor_shadow_shift)
	set_alpha_cuts(plant.impostor_alpha_cuts)
	_set_all("thin_from", plant.impostor_thin_from)


## Cuts the views' alpha at each mip level as [param cuts] says ([member SunflowerPlant.impostor_alpha_cuts]:
## at most the shader's 16 levels); none: the field's alpha_scissor raised with distance.
func set_alpha_cuts(cuts: PackedFloat32Array) -> void:
	var kept: PackedFloat32Array = cuts.slice(0, ALPHA_CUT_LEVELS)
	var padded: PackedFloat32Array = kept.duplicate()
	padded.resize(ALPHA_CUT_LEVELS)
	_set_all("alpha_cuts", padded)
	_set_all("alpha_cut_count", kept.size())


## Shows [param texture] as the impostor's [param kind] (one of [constant SunflowerPlant.IMPOSTOR_TEXTURES]);
## null draws it untextured (flat, for depths), with a warning.
func set_texture(kind: String, texture: Texture2D) -> void:
	var parameter: String = ATLAS_PARAMETERS[kind]
	if texture == material.get_shader_parameter(parameter):
		return
	if texture == null:
		var effect: String = "lit on their flat quads" if kind == "depths" else "drawn untextured"
		push_warning(
			(
				"SunflowerField: no impostor %s texture; the far plants are %s (bake the plant's impostors)"
				% [kind, effect]
			)
		)
	_set_all(parameter, texture)
	if kind == "views":
		var layout: Vector2i = atlas_layout(texture)
		var problem: String = atlas_problem(texture)
		if not problem.is_empty():
			push_warning(
				(
					"SunflowerField: the impostor views texture %s %s; it is read as %d × %d views (re-bake the plant's impostors)"
					% [texture.resource_path if texture.resource_path else "(unsaved)", problem, layout.x, layout.y]
				)
			)
		_set_all("atlas_views", layout)
		var bounds: PackedVector4Array = view_bounds(texture, layout)
		_set_all("view_bounds_up", joined_view_bounds(bounds, layout, Vector2i(1, 2)))
		_set_all("view_bounds_block", joined_view_bounds(bounds, layout, Vector2i(2, 2)))


## Makes the impostors glow with the light [param texture] holds ([member SunflowerPlant.impostor_emission]),
## divided by [param energy_range] ([member SunflowerPlant.impostor_emission_range]); null: none.
func set_emission(texture: Texture2D, energy_range: float) -> void:
	_set_all("emission_atlas", texture)
	_set_all("emission_range", energy_range if texture else 0.0)


## Lets light through the impostors from behind as [param texture] says
## ([member SunflowerPlant.impostor_backlight]); null: none.
func set_backlight(texture: Texture2D) -> void:
	_set_all("backlight_atlas", texture)
	_set_all("has_backlight", texture != null)


## The views across and down the atlas [param texture]: [constant SunflowerPlant.ATLAS_VIEWS]'s columns,
## and as many rows of elevation as its shape holds, so that an atlas baked with fewer rows (the
## baker made 4, 30° apart, then 7, 15° apart, before it made 10) is still drawn right.
## [constant SunflowerPlant.ATLAS_VIEWS] without a texture.
static func atlas_layout(texture: Texture2D) -> Vector2i:
	var columns: int = SunflowerPlant.ATLAS_VIEWS.x
	if texture == null or texture.get_width() <= 0:
		return SunflowerPlant.ATLAS_VIEWS
	var rows: int = roundi(float(texture.get_height()) * columns / texture.get_width())
	return Vector2i(columns, clampi(rows, 2, SunflowerPlant.ATLAS_VIEWS.y))


## What is wrong with the shape of the atlas [param texture], or "" when it is one the baker makes:
## exactly the [method atlas_layout] it is read in, of square views.
static func atlas_problem(texture: Texture2D) -> String:
	if texture == null:
		return ""
	var size: Vector2i = Vector2i(texture.get_width(), texture.get_height())
	var layout: Vector2i = atlas_layout(texture)
	var square: int = size.x / layout.x
	if square > 0 and size == layout * square:
		return ""
	return (
		"is %d × %d pixels, not %d square views across and 2–%d rows down"
		% [size.x, size.y, layout.x, SunflowerPlant.ATLAS_VIEWS.y]
	)


## Where each view of the atlas [param texture] ([param views] squares across and down) has
## anything drawn: per square, in rows, its non-transparent pixels' rectangle as shares of the square
## (x, y, end x, end y). Empty (the shader then draws whole squares) when the texture has no image.
static func view_bounds(texture: Texture2D, views: Vector2i) -> PackedVector4Array:
	var bounds: PackedVector4Array = []
	var image: Image = texture.get_image() if texture else null
	if image == null or image.is_empty():
		return bounds
	if image.is_compressed():
		image.decompress()
	image.clear_mipmaps()
	var square: Vector2i = image.get_size() / views
	for row: int in views.y:
		for column: int in views.x:
			var used: Rect2i = image.get_region(Rect2i(Vector2i(column, row) * square, square)).get_used_rect()
			var start: Vector2 = Vector2(used.position) / Vector2(square)
			var end: Vector2 = Vector2(used.end) / Vector2(square)
			bounds.append(Vector4(start.x, start.y, end.x, end.y))
	return bounds


## The rectangles of [method view_bounds] joined [param block] views at a time: per view (in rows
## of [param views].x), the smallest rectangle holding what it and the views beside it (block.x
## columns, the last one wrapping around to the first) and above it (block.y rows, the top row
## standing for the rows beyond it) draw. The shader cuts a quad to the views it blends with one or
## a few of these instead of one per view ([code]vertex()[/code]: a lookup a view was a quarter of
## the far plants' vertex work). Where none of them draws anything, an empty rectangle
## ([code]Vector4(1, 1, 0, 0)[/code]); empty when [param bounds] is.
static func joined_view_bounds(bounds: PackedVector4Array, views: Vector2i, block: Vector2i) -> PackedVector4Array:
	var joined: PackedVector4Array = []
	if bounds.size() != views.x * views.y:
		return joined
	for row: int in views.y:
		for column: int in views.x:
			var union: Vector4 = Vector4(1, 1, 0, 0)
			for up: int in block.y:
				for across: int in block.x:
					var view: Vector4 = bounds[mini(row + up, views.y - 1) * views.x + (column + across) % views.x]
					if view.z > view.x and view.w > view.y:
						union = Vector4(
							minf(union.x, view.x), minf(union.y, view.y), maxf(union.z, view.z), maxf(union.w, view.w)
						)
			joined.append(union)
	return joined


## Sets a shader parameter of the impostor material ([code]alpha_scissor[/code],
## [code]thinning_start[/code], [code]thinning_min_density[/code]).
func set_shared(parameter: StringName, value: Variant) -> void:
	_set_all(parameter, value)


## Sways the far plants this frame: the field-wide wind [param state] (the simulation's
## [code]get_wind_state()[/code]), the [param wind]'s stiffnesses and the field's
## [param field_transform] (the wind is computed in the field's own frame, as the core does).
func sway(state: PackedFloat32Array, wind: SunflowerWind, field_transform: Transform3D) -> void:
	_set_all("wind_state_a", Vector4(state[0], state[1], state[2], state[3]))
	_set_all("wind_state_b", Vector4(state[4], state[5], state[6], state[7]))
	_set_all("bend_stiffness", Vector2(wind.stiffness_bottom, wind.stiffness_middle) * _stiffness)
	place(field_transform)


## Hides the far tiles' plants in the chunks the near buckets draw: [param mask] holds a byte per
## chunk cell (rows of [param grid_width]), non-zero where the chunk is active.
func set_active_chunks(mask: Texture2D, grid_width: int) -> void:
	for tiles: ShaderMaterial in [tile_material, tile_caster_material]:
		tiles.set_shader_parameter("active_chunks", mask)
		tiles.set_shader_parameter("chunk_grid_width", grid_width)


## Places the impostors with the field node's [param field_transform] (the far tiles' records
## are in the field's frame, as is the wind). Call it whenever the field moves.
func place(field_transform: Transform3D) -> void:
	if field_transform != _field_transform:
		_field_transform = field_transform
		_set_all("world_from_field", Projection(field_transform))
		_set_all("field_from_world", Projection(field_transform.affine_inverse()))


## A unit square the shader turns to the observer and scales to the frame, with [member material],
## or with [member tile_material] when [param for_tiles]. (What it shows lies in the plant's
## cylinder, inside the cull radius the chunks' bounds are made from.)
func mesh(for_tiles: bool = false) -> ArrayMesh:
	var index: int = 1 if for_tiles else 0
	if _quads[index] == null:
		var quad: ArrayMesh = ArrayMesh.new()
		var arrays: Array = []
		arrays.resize(Mesh.ARRAY_MAX)
		arrays[Mesh.ARRAY_VERTEX] = PackedVector3Array(
			[Vector3(-0.5, -0.5, 0), Vector3(0.5, -0.5, 0), Vector3(0.5, 0.5, 0), Vector3(-0.5, 0.5, 0)]
		)
		arrays[Mesh.ARRAY_NORMAL] = PackedVector3Array([Vector3.BACK, Vector3.BACK, Vector3.BACK, Vector3.BACK])
		arrays[Mesh.ARRAY_TEX_UV] = PackedVector2Array([Vector2(0, 1), Vector2(1, 1), Vector2(1, 0), Vector2(0, 0)])
		arrays[Mesh.ARRAY_INDEX] = PackedInt32Array([0, 2, 1, 0, 3, 2])
		quad.add_surface_from_arrays(Mesh.PRIMITIVE_TRIANGLES, arrays)
		quad.surface_set_material(0, tile_material if for_tiles else material)
		_quads[index] = quad
	return _quads[index]


## The shadow casters' material of [method mesh]'s nodes.
func caster(for_tiles: bool = false) -> ShaderMaterial:
	return tile_caster_material if for_tiles else caster_material


func _set_all(parameter: StringName, value: Variant) -> void:
	for each: ShaderMaterial in [material, tile_material, caster_material, tile_caster_material]:
		each.set_shader_parameter(parameter, value)
