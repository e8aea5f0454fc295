@tool
extends RefCounted
## A plant's own part materials drawn through the addon's plant material
## ([code]shaders/plant_parts.gdshader[/code]), so that its near levels cross-fade (the shader's
## screen door) and the plant can be drawn whole ([code]whole_plant_mesh.gd[/code]). A plain
## [StandardMaterial3D] is carried over: albedo colour and texture, UV1 scale and offset (x, y),
## roughness and metallic (and their textures and channels), specular, a normal map and its scale,
## emission (colour, energy multiplier, texture and operator; not with physical light units), back-light
## (colour and texture: light let through a leaf from behind), ambient occlusion (texture, channel,
## light affect), alpha scissor, vertex colours as albedo and their
## encoding, back faces culled or not (the plant material draws both). A material with anything else
## set (other textures, anything read from UV2, transparency other than alpha scissor, another
## shading mode, a next pass...) is kept as it is: that part is drawn by its own material, without
## fades, and its plant part by part. (The far impostors are baked from the albedo, the light given off
## and the back-light of the parts drawn through the plant material.)

const PARTS_SHADER: Shader = preload("shaders/plant_parts.gdshader")
## The StandardMaterial3D properties carried over (or, for cull_mode, allowed either way).
const CARRIED: PackedStringArray = [
	"albedo_color",
	"albedo_texture",
	"uv1_scale",
	"uv1_offset",
	"roughness",
	"roughness_texture",
	"roughness_texture_channel",
	"metallic",
	"metallic_texture",
	"metallic_texture_channel",
	"metallic_specular",
	"normal_enabled",
	"normal_texture",
	"normal_scale",
	"emission_enabled",
	"emission",
	"emission_energy_multiplier",
	"emission_operator",
	"emission_texture",
	"backlight_enabled",
	"backlight",
	"backlight_texture",
	"ao_enabled",
	"ao_texture",
	"ao_texture_channel",
	"ao_light_affect",
	"transparency",
	"alpha_scissor_threshold",
	"vertex_color_use_as_albedo",
	"vertex_color_is_srgb",
	"cull_mode",
]

## BaseMaterial3D.TextureChannel (red, green, blue, alpha, grayscale) as the weights that read it.
const CHANNELS: Array[Vector4] = [
	Vector4(1.0, 0.0, 0.0, 0.0),
	Vector4(0.0, 1.0, 0.0, 0.0),
	Vector4(0.0, 0.0, 1.0, 0.0),
	Vector4(0.0, 0.0, 0.0, 1.0),
	Vector4(0.333333, 0.333333, 0.333333, 0.0),
]

## The project setting under which a material's emission energy also depends on emission_intensity.
const PHYSICAL_LIGHT_UNITS: String = "rendering/lights_and_shadows/use_physical_light_units"

static var _plain: StandardMaterial3D


## [param mesh] with every surface whose material can be carried over drawn with the plant material
## of the same settings (a copy; [param mesh] itself when no surface changes, or when it is not an
## [ArrayMesh]).
static func adopt_mesh(mesh: Mesh) -> Mesh:
	if not mesh is ArrayMesh:
		return mesh
	var copy: ArrayMesh = null
	for surface: int in mesh.get_surface_count():
		var has_colours: bool = mesh.surface_get_format(surface) & Mesh.ARRAY_FORMAT_COLOR != 0
		var adopted: ShaderMaterial = adopt(mesh.surface_get_material(surface), has_colours)
		if adopted == null:
			continue
		if copy == null:
			copy = mesh.duplicate() as ArrayMesh
		copy.surface_set_material(surface, adopted)
	return copy if copy else mesh


## The plant material drawing [param material] as it looks on a surface with vertex colours
## ([param has_vertex_colours]) or without, or null when it cannot (see the script's description).
static func adopt(material: Material, has_vertex_colours: bool) -> ShaderMaterial:
	var standard: StandardMaterial3D = material as StandardMaterial3D
	if standard == null or not _only_carried(standard):
		return null
	if standard.transparency not in [BaseMaterial3D.TRANSPARENCY_DISABLED, BaseMaterial3D.TRANSPARENCY_ALPHA_SCISSOR]:
		return null
	if standard.cull_mode == BaseMaterial3D.CULL_FRONT:
		return null
	if standard.emission_enabled and ProjectSettings.get_setting(PHYSICAL_LIGHT_UNITS, false):
		return null  # its energy then depends on emission_intensity too
	if has_vertex_colours and not standard.vertex_color_use_as_albedo:
		return null  # the shader multiplies vertex and instance colours: it cannot leave the first out
	var adopted: ShaderMaterial = ShaderMaterial.new()
	adopted.shader = PARTS_SHADER
	adopted.resource_name = standard.resource_name
	adopted.set_shader_parameter(&"albedo_colour", standard.albedo_color)
	adopted.set_shader_parameter(&"use_albedo_texture", standard.albedo_texture != null)
	adopted.set_shader_parameter(&"albedo_texture", standard.albedo_texture)
	adopted.set_shader_parameter(&"uv_scale", Vector2(standard.uv1_scale.x, standard.uv1_scale.y))
	adopted.set_shader_parameter(&"uv_offset", Vector2(standard.uv1_offset.x, standard.uv1_offset.y))
	adopted.set_shader_parameter(&"roughness", standard.roughness)
	adopted.set_shader_parameter(&"metallic", standard.metallic)
	for map: String in ["roughness", "metallic"]:
		var texture: Texture2D = standard.get(map + "_texture")
		adopted.set_shader_parameter("use_%s_texture" % map, texture != null)
		adopted.set_shader_parameter(map + "_texture", texture)
		adopted.set_shader_parameter(map + "_channel", CHANNELS[standard.get(map + "_texture_channel")])
	adopted.set_shader_parameter(&"specular", standard.metallic_specular)
	adopted.set_shader_parameter(&"use_normal_texture", standard.normal_enabled and standard.normal_texture != null)
	adopted.set_shader_parameter(&"normal_texture", standard.normal_texture)
	adopted.set_shader_parameter(&"normal_scale", standard.normal_scale)
	if standard.emission_enabled:
		adopted.set_shader_parameter(&"emission_colour", standard.emission)
		adopted.set_shader_parameter(&"emission_energy", standard.emission_energy_multiplier)
		adopted.set_shader_parameter(
			&"emission_multiply", standard.emission_operator == BaseMaterial3D.EMISSION_OP_MULTIPLY
		)
		adopted.set_shader_parameter(&"emission_texture", standard.emission_texture)
	if standard.backlight_enabled:
		adopted.set_shader_parameter(&"backlight_colour", standard.backlight)
		adopted.set_shader_parameter(&"use_backlight_texture", standard.backlight_texture != null)
		adopted.set_shader_parameter(&"backlight_texture", standard.backlight_texture)
	if standard.ao_enabled and standard.ao_texture != null:
		adopted.set_shader_parameter(&"use_ao_texture", true)
		adopted.set_shader_parameter(&"ao_texture", standard.ao_texture)
		adopted.set_shader_parameter(&"ao_channel", CHANNELS[standard.ao_texture_channel])
		adopted.set_shader_parameter(&"ao_light_affect", standard.ao_light_affect)
	var scissor: bool = standard.transparency == BaseMaterial3D.TRANSPARENCY_ALPHA_SCISSOR
	adopted.set_shader_parameter(&"alpha_scissor", standard.alpha_scissor_threshold if scissor else 0.0)
	adopted.set_shader_parameter(&"vertex_colour_is_srgb", standard.vertex_color_is_srgb)
	return adopted


## Whether every stored property of [param material] other than [constant CARRIED] is as a new
## StandardMaterial3D has it.
static func _only_carried(material: StandardMaterial3D) -> bool:
	if _plain == null:
		_plain = StandardMaterial3D.new()
	if material.next_pass != null:
		return false
	for property: Dictionary in material.get_property_list():
		var name: String = property.name
		if property.usage & PROPERTY_USAGE_STORAGE == 0 or name in CARRIED or name.begins_with("resource_"):
			continue
		if name == "script" or name == "next_pass":
			continue
		if material.get(name) != _plain.get(name):
			return false
	return true
