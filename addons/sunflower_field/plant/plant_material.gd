@tool
extends RefCounted
## A plant's own part materials drawn through the addon's plant material
## ([code]shaders/plant_parts.gdshader[/code]), so that its near levels cross-fade (the shader's
## screen door) and the plant can be drawn whole ([code]whole_plant_mesh.gd[/code]). A plain
## [StandardMaterial3D] is carried over: albedo colour and texture, UV1 scale and offset (x, y),
## roughness and metallic (and their textures and channels), specular, a normal map and its scale,
## emission (colour, energy multiplier, texture and operator; not with physical light units),
## back-light (colour and texture: light let through a leaf from behind), ambient occlusion (texture,
## channel, light affect), alpha scissor or hash, vertex colours as albedo and their encoding, back
## faces culled or not (the plant material draws both). A material with anything else set (other
## textures, anything read from UV2, blended transparency, another shading mode, a next
## pass...) is kept as it is: that part is drawn by its own material, without fades, and its plant
## part by part. A surface with no material is drawn with the engine's default look
## ([method _engine_default]). A spatial ShaderMaterial of your own is kept too, drawn by a copy whose
## shader fades ([method fading]) and, when its plant is drawn whole, bends ([method bending]). (The far impostors
## are baked from the albedo, the light given off and the back-light of the parts drawn through the
## plant material.)

const PARTS_SHADER: Shader = preload("../shaders/plant_parts.gdshader")
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
	"alpha_hash_scale",
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

## The addon's folder: a shader there is the addon's own (the plant material's and its includes).
const ADDON_FOLDER: String = "res://addons/sunflower_field/"

## The project setting under which a material's emission energy also depends on emission_intensity.
const PHYSICAL_LIGHT_UNITS: String = "rendering/lights_and_shadows/use_physical_light_units"

## The line that gives a shader of your own the fades ([method fading]), and the call that makes its
## fragment() keep only its level's share of the pixels in a cross-fade (COLOR.a: the field's share).
const FADE_INCLUDE_PATH: String = ADDON_FOLDER + "shaders/screen_door.gdshaderinc"
const FADE_INCLUDE: String = '#include "' + FADE_INCLUDE_PATH + '"'
const FADE_CALL: String = "if (plant_fade_discards(FRAGCOORD.xy, COLOR.a)) { discard; }"
const SHADER_TYPE_PATTERN: String = "(?m)^\\s*shader_type\\s+(\\w+)\\s*;"
const RENDER_MODE_PATTERN: String = "(?m)^\\s*render_mode\\s[^;]*;"
const INCLUDE_PATTERN: String = '(?m)^\\s*#include\\s+"([^"]*)"'
## A uniform declared (of any kind: global, instance, group members).
const UNIFORM_PATTERN: String = "(?m)^\\s*(global\\s+|instance\\s+)?uniform\\s"

## A shader function's head, by the function's name (%s).
const FUNCTION_PATTERN: String = "void\\s+%s\\s*\\(\\s*\\)\\s*\\{"
## The line that lets a shader of your own bend as a plant drawn whole ([method bending]), the call
## that places each vertex first in its [code]vertex()[/code], and what keeps a shader from it: UV2
## (which the merged mesh's vertices hold their part in), world-space vertices, a call of its own.
const BEND_INCLUDE_PATH: String = ADDON_FOLDER + "shaders/plant_bend.gdshaderinc"
const BEND_INCLUDE: String = '#include "' + BEND_INCLUDE_PATH + '"'
const BEND_ARGUMENTS: String = "VERTEX, NORMAL, TANGENT, BINORMAL, INSTANCE_CUSTOM, UV2.x, MODEL_MATRIX[3].xz, TIME"
const BEND_CALL: String = "plant_place(" + BEND_ARGUMENTS + ");"
const NOT_BENDING_PATTERN: String = "\\b(UV2|world_vertex_coords|plant_place)\\b"

static var _plain: StandardMaterial3D
static var _faded_shaders: Dictionary = {}  # your shader → [its code, the fading copy or null]
static var _bent_shaders: Dictionary = {}  # a fading shader → [its code, the bending copy or null]
static var _patterns: Dictionary = {}  # pattern → RegEx


## [param mesh] with every surface whose material can be carried over drawn with the plant material
## of the same settings, and every surface with a spatial ShaderMaterial of its own drawn with it
## fading as the plant material does ([method fading]) (a copy; [param mesh] itself when no surface
## changes, or when it is not an [ArrayMesh]).
static func adopt_mesh(mesh: Mesh) -> Mesh:
	if not mesh is ArrayMesh:
		return mesh
	var copy: ArrayMesh = null
	for surface: int in mesh.get_surface_count():
		var has_colours: bool = mesh.surface_get_format(surface) & Mesh.ARRAY_FORMAT_COLOR != 0
		var material: Material = mesh.surface_get_material(surface)
		var adopted: ShaderMaterial = adopt(material, has_colours)
		if adopted == null:
			adopted = fading(material)
		if adopted == null:
			continue
		if copy == null:
			copy = mesh.duplicate() as ArrayMesh
		copy.surface_set_material(surface, adopted)
	return copy if copy else mesh


## The plant material drawing [param material] as it looks on a surface with vertex colours
## ([param has_vertex_colours]) or without, or null when it cannot (see the script's description and
## [method not_carried]).
static func adopt(material: Material, has_vertex_colours: bool) -> ShaderMaterial:
	if material == null and not has_vertex_colours:
		material = _engine_default()
	if not material is StandardMaterial3D or not not_carried(material, has_vertex_colours).is_empty():
		return null
	var standard: StandardMaterial3D = material as StandardMaterial3D
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
	var hashed: bool = standard.transparency == BaseMaterial3D.TRANSPARENCY_ALPHA_HASH
	adopted.set_shader_parameter(&"alpha_hash_scale", maxf(standard.alpha_hash_scale, 1e-3) if hashed else 0.0)
	adopted.set_shader_parameter(&"vertex_colour_is_srgb", standard.vertex_color_is_srgb)
	return adopted


## What of [param material] on a surface with vertex colours ([param has_vertex_colours]) or without
## keeps the plant material from drawing it, or "" when nothing does: the field then draws that part
## with the plant material (a StandardMaterial3D, or no material) or a copy of your shader that fades
## ([method fading]; a spatial ShaderMaterial). Otherwise the part is drawn by the material as it is,
## without the levels' cross-fades, and its plant part by part (scene_plant.gd names it).
static func not_carried(material: Material, has_vertex_colours: bool) -> String:
	if material == null:
		return "vertex colours, which the engine's default material does not show" if has_vertex_colours else ""
	if material is ShaderMaterial:
		var code: String = (material as ShaderMaterial).shader.code if (material as ShaderMaterial).shader else ""
		if code.is_empty() or code.contains("plant_fade_discards") or _copyable(code):
			return ""
		return "its shader is not a spatial one, or includes a file by a relative path (a copy could not find it)"
	var standard: StandardMaterial3D = material as StandardMaterial3D
	if standard == null:
		return "it is a %s (only StandardMaterial3D and ShaderMaterial are carried)" % material.get_class()
	var other: String = _first_not_carried(standard)
	if not other.is_empty():
		return "its %s is set" % other
	var cuts: Array[int] = [
		BaseMaterial3D.TRANSPARENCY_DISABLED,
		BaseMaterial3D.TRANSPARENCY_ALPHA_SCISSOR,
		BaseMaterial3D.TRANSPARENCY_ALPHA_HASH,
	]
	if standard.transparency not in cuts:
		return (
			"it blends its alpha (transparency %s; Alpha Scissor and Alpha Hash are carried)"
			% [["", "Alpha", "", "", "Alpha Depth Pre-Pass"][standard.transparency]]
		)
	if standard.cull_mode == BaseMaterial3D.CULL_FRONT:
		return "it culls front faces"
	if standard.emission_enabled and ProjectSettings.get_setting(PHYSICAL_LIGHT_UNITS, false):
		return "it gives off light with physical light units on (its energy depends on emission_intensity too)"
	if has_vertex_colours and not standard.vertex_color_use_as_albedo:
		# The plant shader multiplies vertex and instance colours: it cannot leave the first out.
		return "its surface has vertex colours it does not use as albedo"
	return ""


## For each material of [param meshes]' surfaces that the plant material cannot draw, or whose shader
## of your own the field cannot bend as one plant (it reads UV2 or uses world_vertex_coords), a
## message naming it, why ([method not_carried]) and what follows (each once).
static func kept_materials(meshes: Array) -> PackedStringArray:
	var messages: PackedStringArray = []
	for mesh: Mesh in meshes:
		for surface: int in mesh.get_surface_count() if mesh else 0:
			var material: Material = mesh.surface_get_material(surface)
			var why: String = not_carried(material, mesh.surface_get_format(surface) & Mesh.ARRAY_FORMAT_COLOR != 0)
			var message: String = ""
			if not why.is_empty():
				message = (
					(
						"%s: %s; the field draws that part with it as it is, without the levels' cross-fades, and"
						+ " the plant part by part (it leans in the wind as one piece)"
					)
					% [_named(material), why]
				)
			elif material is ShaderMaterial and (material as ShaderMaterial).shader:
				var unbent: RegExMatch = null  # the first use the field cannot bend (bending already can)
				for found: RegExMatch in regex(NOT_BENDING_PATTERN).search_all(
					(material as ShaderMaterial).shader.code
				):
					if found.get_string(1) != "plant_place":
						unbent = found
						break
				if unbent:
					message = (
						(
							"%s: its shader uses %s, so the field cannot bend it as one plant: it draws the plant part"
							+ " by part (it leans in the wind as one piece; its levels still cross-fade)"
						)
						% [_named(material), unbent.get_string(1)]
					)
			if not message.is_empty() and message not in messages:
				messages.append(message)
	return messages


## [param material] as a warning names it: its class and file (or name).
static func _named(material: Material) -> String:
	if material == null:
		return "no material"
	var file: String = material.resource_path.get_file() if material.resource_path else material.resource_name
	return "%s '%s'" % [material.get_class(), file]


## The look the engine gives a surface without a material (its default material's shader: albedo 0.6,
## roughness 0.8, metallic 0.2), as a StandardMaterial3D the plant material carries over: a plant
## made of meshes with no material (shapes put together in the editor) is drawn as its scene shows it,
## and fades and bends. (A surface with vertex colours is kept: the engine's default does not show
## them, the plant material would.)
static func _engine_default() -> StandardMaterial3D:
	var grey: StandardMaterial3D = StandardMaterial3D.new()
	grey.albedo_color = Color(0.6, 0.6, 0.6)
	if RenderingServer.get_current_rendering_method() != "gl_compatibility":
		grey.albedo_color = grey.albedo_color.linear_to_srgb()  # a shader's ALBEDO is linear there
	grey.roughness = 0.8
	grey.metallic = 0.2
	grey.resource_name = "the engine's default"
	return grey


## A copy of [param material], a ShaderMaterial of your own, whose shader fades as the plant
## material does (the level-of-detail cross-fades), or null when it needs no copy or cannot be made
## to: the copy's shader is yours with [constant FADE_INCLUDE] after its [code]shader_type[/code] and
## [code]render_mode[/code] lines and [constant FADE_CALL] first in its [code]fragment()[/code] (see
## [method fading_code]). Made once per shader and code.
static func fading(material: Material) -> ShaderMaterial:
	var own: ShaderMaterial = material as ShaderMaterial
	if own == null or own.shader == null or own.shader == PARTS_SHADER:
		return null
	return _copy(own, false)


## [param code], a shader's, with the plant material's fade added (see [method fading]); empty when it
## is not a spatial shader, already calls [code]plant_fade_discards[/code], or includes a file by a
## relative path (a copy of the code has no folder to find it from).
static func fading_code(code: String) -> String:
	if code.contains("plant_fade_discards") or not _copyable(code):
		return ""
	return _with_include(_first_in(code, "fragment", FADE_CALL), FADE_INCLUDE_PATH, FADE_INCLUDE)


## Whether a part drawn with [param material], a ShaderMaterial that fades ([method fading]'s copy
## or one of your own with the fade line), can be bent as a plant drawn whole ([method bending]).
static func can_bend(material: Material) -> bool:
	var own: ShaderMaterial = material as ShaderMaterial
	if own == null or own.shader == null or not own.shader.code.contains("plant_fade_discards"):
		return false
	return _made_shader(own.shader, true) != null


## A copy of [param material] ([method can_bend]) whose shader bends the plant drawn whole as the
## field's own plant shader does: [constant BEND_INCLUDE] after its [code]shader_type[/code] and
## [code]render_mode[/code] lines and [constant BEND_CALL] first in its [code]vertex()[/code] (see
## [method bending_code]); null when it cannot. Made once per shader and code. The caller sets the
## include's [code]plant_part_lengths[/code] and [code]plant_flutter[/code].
static func bending(material: Material) -> ShaderMaterial:
	if not can_bend(material):
		return null
	return _copy(material as ShaderMaterial, true)


## [param code], a spatial shader's, with each vertex bent and stacked as a plant drawn whole (see
## [method bending]); empty when it is not a spatial shader, reads UV2, has world-space vertices,
## places the plant already, or includes a file by a relative path. Wind of your own in
## [code]vertex()[/code] comes on top of the field's unless it stands inside
## [code]#ifndef PLANT_BENT_BY_FIELD[/code] … [code]#endif[/code] (the include defines it).
static func bending_code(code: String) -> String:
	if regex(NOT_BENDING_PATTERN).search(code) != null or not _copyable(code):
		return ""
	return _with_include(_first_in(code, "vertex", BEND_CALL), BEND_INCLUDE_PATH, BEND_INCLUDE)


## Whether [param code] is a spatial shader whose includes a copy can still find (by res:// paths).
static func _copyable(code: String) -> bool:
	var head: RegExMatch = regex(SHADER_TYPE_PATTERN).search(code)
	if head == null or head.get_string(1) != "spatial":
		return false
	for include: RegExMatch in regex(INCLUDE_PATTERN).search_all(code):
		if not include.get_string(1).begins_with("res://"):
			return false
	return true


## [param code] with [param line] first in its function [param function] (or a function of that line
## added when it has none).
static func _first_in(code: String, function: String, line: String) -> String:
	var head: RegExMatch = regex(FUNCTION_PATTERN % function).search(code)
	if head:
		return code.insert(head.get_end(), " " + line)  # on the head's line: your line numbers stay
	return code + "\nvoid %s() {\n\t%s\n}\n" % [function, line]


## Where the body of [param code]'s function [param function] begins (after its opening brace) and
## ends (at its closing brace); x −1 when it has none.
static func function_body(code: String, function: String) -> Vector2i:
	var head: RegExMatch = regex(FUNCTION_PATTERN % function).search(code)
	if head == null:
		return Vector2i(-1, -1)
	var depth: int = 1
	var at: int = head.get_end()
	while at < code.length() and depth > 0:
		depth += 1 if code[at] == "{" else (-1 if code[at] == "}" else 0)
		at += 1
	return Vector2i(head.get_end(), at - 1)


## [param code] with [param line], the include of [param path], after its [code]shader_type[/code]
## line and the [code]render_mode[/code] line right after it (unless it includes the file already):
## in the blank line that follows them when there is one, so the shader's errors keep your line numbers.
static func _with_include(code: String, path: String, line: String) -> String:
	if code.contains(path):
		return code
	var head: RegExMatch = regex(SHADER_TYPE_PATTERN).search(code)
	var after: int = head.get_end()
	var modes: RegExMatch = regex(RENDER_MODE_PATTERN).search(code, after)
	if modes and code.substr(after, modes.get_start() - after).strip_edges().is_empty():
		after = modes.get_end()
	var line_end: int = code.find("\n", after)
	if line_end < 0:
		return code + "\n" + line + "\n"
	var next_end: int = code.find("\n", line_end + 1)
	next_end = code.length() if next_end < 0 else next_end
	if code.substr(line_end + 1, next_end - line_end - 1).strip_edges().is_empty():
		return code.substr(0, line_end + 1) + line + code.substr(next_end)
	return code.insert(line_end, "\n" + line)


## The copy of [param own] drawn with its shader made fading ([param bend] false) or bending (the
## shader from [method _made_shader]); null when that shader cannot be made.
static func _copy(own: ShaderMaterial, bend: bool) -> ShaderMaterial:
	var shader: Shader = _made_shader(own.shader, bend, own)
	return copy_with_shader(own, shader) if shader else null


## A copy of [param own] drawn by [param shader] (made from its shader): its name, render priority,
## next pass and the values of its shader's uniforms.
static func copy_with_shader(own: ShaderMaterial, shader: Shader) -> ShaderMaterial:
	var copy: ShaderMaterial = ShaderMaterial.new()
	copy.resource_name = own.resource_name
	copy.shader = shader
	copy.render_priority = own.render_priority
	copy.next_pass = own.next_pass
	for uniform: Dictionary in own.shader.get_shader_uniform_list():
		copy.set_shader_parameter(uniform.name, own.get_shader_parameter(uniform.name))
	return copy


## The shader made from [param shader] by [method bending_code] ([param bend]) or [method fading_code],
## kept per shader (in _bent_shaders or _faded_shaders) and made again only when its code changes; null
## when it cannot be made, or when [param shader] does not compile: the engine has reported its error
## once, with your line numbers (a copy would report it again); one warning names it and
## [param material], the first that draws with it.
static func _made_shader(shader: Shader, bend: bool, material: Material = null) -> Shader:
	var made_shaders: Dictionary = _bent_shaders if bend else _faded_shaders
	var made: Array = made_shaders.get(shader, [])
	if made.is_empty() or made[0] != shader.code:
		var broken: bool = _fails_to_compile(shader)
		if broken:
			push_warning(
				(
					(
						"SunflowerField: the shader %s of the material %s does not compile (the engine's shader error"
						+ " names the line); the plant's parts drawn with it keep it unchanged, without the levels'"
						+ " cross-fade"
					)
					% [named(shader), named(material) if material else "(none)"]
				)
			)
		var code: String = "" if broken else (bending_code(shader.code) if bend else fading_code(shader.code))
		var copy: Shader = null
		if not code.is_empty():
			copy = Shader.new()
			copy.code = code
			copy.resource_name = shader.resource_name
		made = [shader.code, copy]
		made_shaders[shader] = made
	return made[1]


## Whether [param shader] declares uniforms and the engine found none: its code failed to compile (the
## engine lists the uniforms of a shader it compiled, with any renderer; one without uniforms is not
## judged).
static func _fails_to_compile(shader: Shader) -> bool:
	return regex(UNIFORM_PATTERN).search(shader.code) != null and shader.get_shader_uniform_list().is_empty()


## [param resource] as a message names it: its file (or the file it is built into) and its name.
static func named(resource: Resource) -> String:
	var path: String = resource.resource_path if not resource.resource_path.is_empty() else "(built in, unsaved)"
	return path + (' "%s"' % resource.resource_name if not resource.resource_name.is_empty() else "")


## [param pattern] compiled, once per pattern.
static func regex(pattern: String) -> RegEx:
	if not _patterns.has(pattern):
		_patterns[pattern] = RegEx.create_from_string(pattern)
	return _patterns[pattern]


## The first stored property of [param material] other than [constant CARRIED] that is not as a new
## StandardMaterial3D has it ("next_pass" for a next pass), or "" when there is none.
static func _first_not_carried(material: StandardMaterial3D) -> String:
	if _plain == null:
		_plain = StandardMaterial3D.new()
	if material.next_pass != null:
		return "next_pass"
	for property: Dictionary in material.get_property_list():
		var name: String = property.name
		if property.usage & PROPERTY_USAGE_STORAGE == 0 or name in CARRIED or name.begins_with("resource_"):
			continue
		if name == "script" or name == "next_pass":
			continue
		if material.get(name) != _plain.get(name):
			return name
	return ""
