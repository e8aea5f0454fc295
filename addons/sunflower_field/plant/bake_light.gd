@tool
extends RefCounted
## The bake's light passes (impostor_baker.gd): what the parts let through from behind (their
## back-light) and what they give off (emission), each drawn on the bake's stage and read by the
## baker's pass reader; and what of a plant's own shaders the views, drawn unshaded, cannot capture.

const PlantMaterial: GDScript = preload("plant_material.gd")
const PartMeshes: GDScript = preload("part_meshes.gd")
## What a shader of your own writes to let light through: its back-light is baked
## ([method backlight]); its SSS transmittance is not.
const BACKLIGHT_WRITE: String = "\\bBACKLIGHT\\s*="
const TRANSMITTANCE_WRITE: String = "\\bSSS_TRANSMITTANCE_\\w+\\s*="
## The emission pass is rendered again with a range this many times wider while a pixel saturates,
## at most this many times in all: 8 to 8 × 8⁴ = 32 768, [member SunflowerPlant.impostor_emission_range]'s
## top.
const EMISSION_RANGE_STEP: float = 8.0
const EMISSION_RANGE_STEPS: int = 5


## The emission pass: its picture (null when nothing glows) and the range its light was divided by
## (the default when nothing glows).
class Glow:
	var image: Image
	var energy_range: float = 0.0


## What of [param plant]'s own shaders at mesh [param level] (the one baked) the bake cannot capture,
## a sentence per material naming it:
## the views are drawn unshaded (each surface's albedo), so a ShaderMaterial of its own that lights
## its surface itself (a [code]light()[/code] function) or lets light through as SSS transmittance
## ([code]SSS_TRANSMITTANCE_*[/code]) is baked without that light: its far plants are lit by the
## impostor shader's own model and may look darker or otherwise than its meshes. (The plant
## material's back-light, a shader's own [code]BACKLIGHT[/code] and any material's emission are
## baked.)
static func lighting_not_baked(plant: SunflowerPlant, level: int) -> PackedStringArray:
	var problems: PackedStringArray = []
	var seen: Dictionary = {}
	var light_function: RegEx = RegEx.create_from_string("\\bvoid\\s+light\\s*\\(")
	var transmittance: RegEx = RegEx.create_from_string(TRANSMITTANCE_WRITE)
	for part: int in PartMeshes.PART_NAMES.size():
		var mesh: Mesh = plant.mesh_drawn(level, part)
		for surface: int in mesh.get_surface_count() if mesh else 0:
			var material: ShaderMaterial = mesh.surface_get_material(surface) as ShaderMaterial
			if material == null or material.shader == null or seen.has(material):
				continue
			seen[material] = true
			if material.shader.resource_path.begins_with(PlantMaterial.ADDON_FOLDER):
				continue  # the plant material: its back-light is baked
			var own: PackedStringArray = []
			if light_function.search(material.shader.code):
				own.append("its light() function")
			if transmittance.search(material.shader.code):
				own.append("the light it lets through as SSS transmittance")
			if not own.is_empty():
				(
					problems
					. append(
						(
							"%s is baked as its albedo, without %s; far plants of this type are lit by the impostors' own model"
							% [_material_name(material, part), " and ".join(own)]
						)
					)
				)
	return problems


## A material as a warning names it: its file, its name, else its shader's file and the part it is on.
static func _material_name(material: ShaderMaterial, part: int) -> String:
	if not material.resource_path.is_empty():
		return "the material " + material.resource_path
	if not material.resource_name.is_empty():
		return "the material '%s'" % material.resource_name
	var shader: String = material.shader.resource_path
	return "the %s part's material (shader %s)" % [PartMeshes.PART_NAMES[part], shader if shader else "built in"]


## The light the parts let through from behind (their back-light), drawn as their colour, unshaded:
## each part's material as the plant material draws it ([code]plant_material.gd[/code]), with its
## back-light as the colour; a ShaderMaterial of your own that sets [code]BACKLIGHT[/code] drawn by a
## copy showing it as its colour; any other part is black where it covers (a StandardMaterial3D
## keeps its alpha cut; another material is drawn whole). No image when no part lets light through.
static func backlight(stage: RefCounted, read_pass: Callable) -> Image:
	var copies: Dictionary = {}  # material → the one drawn in this pass
	var lets_through: bool = false
	var instances: Array[Node] = stage.viewport.find_children("*", "MeshInstance3D", true, false)
	for node: Node in instances:
		var mesh: Mesh = (node as MeshInstance3D).mesh
		for surface: int in mesh.get_surface_count() if mesh else 0:
			var material: Material = mesh.surface_get_material(surface)
			if not copies.has(material):
				var through: ShaderMaterial = _through_material(material)
				lets_through = (
					lets_through
					or through != null and (through.shader != PlantMaterial.PARTS_SHADER or _has_backlight(through))
				)
				copies[material] = through if through else _black_material(material)
	if not lets_through:
		return null
	for node: Node in instances:
		var instance: MeshInstance3D = node as MeshInstance3D
		instance.material_override = null
		for surface: int in instance.mesh.get_surface_count() if instance.mesh else 0:
			instance.set_surface_override_material(surface, copies[instance.mesh.surface_get_material(surface)])
	var image: Image = await read_pass.call(stage)
	for node: Node in instances:
		var instance: MeshInstance3D = node as MeshInstance3D
		for surface: int in instance.mesh.get_surface_count() if instance.mesh else 0:
			instance.set_surface_override_material(surface, null)
	return image


## [param material] drawn by the plant material showing its back-light as its colour, or null when
## the plant material cannot draw it. (Vertex colours do not matter: the pass does not read them.)
static func _through_material(material: Material) -> ShaderMaterial:
	var through: ShaderMaterial = material as ShaderMaterial
	if through and through.shader == PlantMaterial.PARTS_SHADER:
		through = through.duplicate() as ShaderMaterial
	else:
		through = PlantMaterial.adopt(material, false)
	if through == null:
		return _own_through(material)
	through.set_shader_parameter(&"backlight_as_albedo", true)
	return through


## A copy of [param material], a ShaderMaterial of your own that sets [code]BACKLIGHT[/code] in its
## [code]fragment()[/code], showing that light as its colour ([code]ALBEDO = BACKLIGHT;[/code] last
## in its [code]fragment()[/code], which cannot return early); null when it sets none.
static func _own_through(material: Material) -> ShaderMaterial:
	var own: ShaderMaterial = material as ShaderMaterial
	if own == null or own.shader == null or own.shader == PlantMaterial.PARTS_SHADER:
		return null
	var code: String = own.shader.code
	var body: Vector2i = PlantMaterial.function_body(code, "fragment")
	if body.x < 0:
		return null
	var inside: String = code.substr(body.x, body.y - body.x)
	if not PlantMaterial.regex(BACKLIGHT_WRITE).search(inside):
		return null
	var shader: Shader = Shader.new()
	shader.code = code.substr(0, body.y) + " ALBEDO = BACKLIGHT; " + code.substr(body.y)
	var copy: ShaderMaterial = own.duplicate() as ShaderMaterial
	copy.shader = shader
	return copy


## Whether the plant material [param material] has a back-light (a colour or a texture).
static func _has_backlight(material: ShaderMaterial) -> bool:
	var colour: Variant = material.get_shader_parameter(&"backlight_colour")  # null: never set
	return material.get_shader_parameter(&"use_backlight_texture") == true or colour is Color and colour != Color.BLACK


## [param material] drawn black where it covers (a BaseMaterial3D keeps its alpha cut).
static func _black_material(material: Material) -> BaseMaterial3D:
	var black: BaseMaterial3D = (
		(material as BaseMaterial3D).duplicate() as BaseMaterial3D
		if material is BaseMaterial3D
		else StandardMaterial3D.new()
	)
	black.albedo_color = Color(0.0, 0.0, 0.0, black.albedo_color.a)
	black.vertex_color_use_as_albedo = false
	black.emission_enabled = false
	return black


## The light the parts give off, from the baker's stage with the parts' own materials,
## lit by nothing (no lights, no ambient or reflected light), divided by the smallest range of
## [member SunflowerPlant.impostor_emission_range]'s default (8) × [constant EMISSION_RANGE_STEP]^k in
## which no pixel saturates (through the exposure; rendered again with the next range while one
## does). No image when no pixel glows, or, without rendering, when no part's material can give off
## light.
static func emission(stage: RefCounted, plant: SunflowerPlant, read_pass: Callable) -> Glow:
	var viewport: SubViewport = stage.viewport
	var glow: Glow = Glow.new()
	glow.energy_range = (SunflowerPlant as Script).get_property_default_value(&"impostor_emission_range")
	if not _can_glow(plant, stage.level):
		return glow
	for instance: Node in viewport.find_children("*", "MeshInstance3D", true, false):
		(instance as MeshInstance3D).material_override = null
	viewport.debug_draw = Viewport.DEBUG_DRAW_DISABLED
	var environments: Array[Environment] = []
	for world: Node in viewport.find_children("*", "WorldEnvironment", false, false):
		var environment: Environment = (world as WorldEnvironment).environment
		environment.ambient_light_source = Environment.AMBIENT_SOURCE_COLOR
		environment.ambient_light_color = Color.BLACK
		environment.ambient_light_energy = 0.0
		environment.reflected_light_source = Environment.REFLECTION_SOURCE_DISABLED
		environment.tonemap_mode = Environment.TONE_MAPPER_LINEAR
		environments.append(environment)
	for step: int in EMISSION_RANGE_STEPS:
		for environment: Environment in environments:
			environment.tonemap_exposure = 1.0 / glow.energy_range
		var image: Image = await read_pass.call(stage)
		if image == null:
			return glow
		# The brightest colour channel, from a comparison with black (the alpha left out).
		var colours: Image = image.duplicate() as Image
		colours.convert(Image.FORMAT_RGB8)
		var black: Image = Image.create(colours.get_width(), colours.get_height(), false, Image.FORMAT_RGB8)
		var brightest: float = float(colours.compute_image_metrics(black, false)["max"])
		if brightest < 2.0:
			return glow
		glow.image = image
		if brightest < 255.0 or step == EMISSION_RANGE_STEPS - 1:
			return glow
		glow.energy_range *= EMISSION_RANGE_STEP
	return glow


## Whether any of the parts' materials at mesh [param level] (or their next passes) may give off
## light: anything but a StandardMaterial3D or ORMMaterial3D with its emission off (a shader's is not
## known without rendering it).
static func _can_glow(plant: SunflowerPlant, level: int) -> bool:
	for part: int in 3:
		var mesh: Mesh = plant.mesh_drawn(level, part)
		if mesh == null:
			continue
		for surface: int in mesh.get_surface_count():
			var material: Material = mesh.surface_get_material(surface)
			while material:
				if not (material is BaseMaterial3D) or (material as BaseMaterial3D).emission_enabled:
					return true
				material = material.next_pass
	return false
