@tool
@icon("icons/field_plant.svg")
class_name SunflowerPlant
extends Resource
## One kind of plant for a [SunflowerField]: its three parts at each mesh level, how they stack,
## its height and variety, and the impostor textures of its far levels.
##
## Parts are modelled with their root at the origin and their height along +y; a plant stands as
## bottom, middle and head, each starting at the previous one's tip ([member part_lengths] model
## units up it). The whole plant is [member height] metres from the root to the top of its parts.
## The far levels draw a multi-view impostor: the level-1 parts rendered from [constant ATLAS_VIEWS]
## directions (around the plant, and from the side up to straight above) into [member impostor_views],
## [member impostor_normals], [member impostor_depths] and, for a plant that glows or lets light
## through its leaves, [member impostor_emission] and [member impostor_backlight] (the editor's
## "Bake impostors"); each view frames the cylinder
## [member impostor_width] wide and [member height_units] tall that holds the plant.
## An empty part slot draws nothing: a plant of one or two parts leaves the slots above them empty
## (their [member part_lengths] then count 0), and a mesh level with no parts at all draws the level
## above it. The built-in sunflower is [method default_plant]: the plant a field grows when it is
## given none, never a source of parts for another plant.

const Native: GDScript = preload("native/native.gd")
const DEFAULT_PATH: String = "res://addons/sunflower_field/plants/sunflower.tres"
const PartMeshes: GDScript = preload("plant/part_meshes.gd")
const ImpostorBaker: GDScript = preload("plant/impostor_baker.gd")
const ScenePlant: GDScript = preload("plant/scene_plant.gd")
const PlantParts: GDScript = preload("plant/plant_parts.gd")
## The impostor atlases' views: columns around the plant (the first from its front, +z, turning
## towards +x), rows of elevation from the side (0°, top row) to straight above (90°, bottom row).
const ATLAS_VIEWS: Vector2i = Vector2i(12, 10)
## The impostor textures, as [method texture_drawn] names them.
const IMPOSTOR_TEXTURES: PackedStringArray = ["views", "normals", "depths"]
## The optional impostor texture of the light a plant's parts give off (see [member impostor_emission]).
const EMISSION_TEXTURE: String = "emission"
## The optional impostor texture of the light a plant's leaves let through (see [member impostor_backlight]).
const BACKLIGHT_TEXTURE: String = "backlight"

static var _default: SunflowerPlant

## A name for the plant (menus, warnings).
@export var name: String = "Sunflower":
	set(value):
		if value != name:
			name = value
			emit_changed()
## Height from the root to the top of the parts, metres.
@export_range(0.01, 50.0, 0.01, "or_greater", "suffix:m") var height: float = 2.0:
	set(value):
		var accepted: float = Native.accept("SunflowerPlant.height", value, height)
		if accepted != height:
			height = accepted
			emit_changed()

@export_group("Meshes")
## The most detailed level's parts: bottom, middle, head.
@export var mesh_level_1: Array[Mesh] = [null, null, null]:
	set(value):
		mesh_level_1 = PlantParts.three(value)
		emit_changed()  # always: the same array or texture may hold new contents
## The middle level's parts.
@export var mesh_level_2: Array[Mesh] = [null, null, null]:
	set(value):
		mesh_level_2 = PlantParts.three(value)
		emit_changed()  # always: the same array or texture may hold new contents
## The simplest level's parts.
@export var mesh_level_3: Array[Mesh] = [null, null, null]:
	set(value):
		mesh_level_3 = PlantParts.three(value)
		emit_changed()  # always: the same array or texture may hold new contents
## Draw each near plant as one instance, its parts merged into one mesh per level and placed by the
## shader, instead of one instance per part: a third of the draw calls and less per-frame work, and
## a plant of one part bends with its height instead of leaning whole. Only parts drawn with the
## addon's plant material ([code]shaders/plant_parts.gdshader[/code], as the built-in plants' are, or
## a plain StandardMaterial3D it takes over: [member use_plant_material]) or with a ShaderMaterial of
## your own made to fade by it (drawn by a copy that bends too) can be merged; any other plant is
## drawn part by part whatever this says ([method drawn_whole]).
@export var draw_whole: bool = true:
	set(value):
		if value != draw_whole:
			draw_whole = value
			emit_changed()
## Draw the parts' plain StandardMaterial3D surfaces with the addon's plant material of the same
## settings ([code]plant_material.gd[/code] says which settings carry over), so that the near levels
## cross-fade into each other and the impostors and the plant can be drawn whole, and the parts'
## spatial ShaderMaterials of your own with a copy of their shader that fades too (the plant material's
## one line added at the start of its [code]fragment()[/code]) and, drawn whole, bends (one call added
## at the start of its [code]vertex()[/code]: [method PlantMaterial.bending]). Off: every part keeps
## its own material.
@export var use_plant_material: bool = true:
	set(value):
		if value != use_plant_material:
			use_plant_material = value
			emit_changed()

## Values the field gives the [code]instance uniform[/code]s of the parts' shaders on every node that
## draws this plant's meshes (and the impostor bake), by name — what a scene's nodes set as their
## [code]instance_shader_parameters/…[/code] ([method from_scene] takes them). Every part of the plant
## gets the same value of a parameter.
@export var instance_shader_parameters: Dictionary = {}:
	set(value):
		instance_shader_parameters = value
		emit_changed()

@export_group("Form")
## Model units from each part's root to the next one's: bottom → middle, middle → head, and the
## head's own length. [member height] spans their sum, the lengths of empty slots above the top
## level-1 part left out ([method stacked_lengths]).
@export var part_lengths: Vector3 = Vector3(1.0, 1.0, 1.0):
	set(value):
		var accepted: Vector3 = Vector3(
			Native.accept("SunflowerPlant.part_lengths", value.x, part_lengths.x),
			Native.accept("SunflowerPlant.part_lengths", value.y, part_lengths.y),
			Native.accept("SunflowerPlant.part_lengths", value.z, part_lengths.z)
		)
		if accepted != part_lengths:
			part_lengths = accepted
			emit_changed()
## Model units from the root to the top of anything drawn (the parts and what stands out above
## them, such as petals): the impostor quads' height.
@export_range(0.01, 100.0, 0.01, "or_greater") var height_units: float = 3.2:
	set(value):
		var accepted: float = Native.accept("SunflowerPlant.height_units", value, height_units)
		if accepted != height_units:
			height_units = accepted
			emit_changed()
## Radius, in model units, of the sphere about the plant's middle that holds it leaning by the
## largest bend with its leaves: culling and chunk bounds use it.
@export_range(0.01, 100.0, 0.01, "or_greater") var cull_radius_units: float = 1.9:
	set(value):
		var accepted: float = Native.accept("SunflowerPlant.cull_radius_units", value, cull_radius_units)
		if accepted != cull_radius_units:
			cull_radius_units = accepted
			emit_changed()
## The width of the upright cylinder about the stem that holds the plant (twice its farthest reach
## from the stem), model units: what the impostor views frame.
@export_range(0.01, 100.0, 0.01, "or_greater") var impostor_width: float = 1.6:
	set(value):
		var accepted: float = value if value > 0.0 and is_finite(value) else impostor_width
		if accepted != impostor_width:
			impostor_width = accepted
			emit_changed()

## The plant's level-of-detail switch distances are the field's [member SunflowerField.lod_distances]
## (set for the 2 m sunflower) times this. 0 (the default): its size over the sunflower's, the larger
## of its [member height] and its width in metres ([method lod_scale_used]), so that a 5 m tree keeps
## its meshes 2.5× as far and a 0.5 m grass clump turns into impostors at a quarter of the distance,
## each where it covers as many pixels as the sunflower does at its switches.
@export_range(0.0, 100.0, 0.01, "or_greater") var lod_scale: float = 0.0:
	set(value):
		var accepted: float = value if value >= 0.0 and is_finite(value) else lod_scale
		if accepted != value:
			push_warning("SunflowerPlant.lod_scale: %s is not a scale (0 or more); keeping %s" % [value, lod_scale])
		if accepted != lod_scale:
			lod_scale = accepted
			emit_changed()

## How stiff the plant is against the wind's stiffnesses ([member SunflowerWind.stiffness_middle],
## [member SunflowerWind.stiffness_bottom]): 2 bends half as far as the sunflower, 0.5 twice as far.
@export_range(0.05, 20.0, 0.01) var stiffness: float = 1.0:
	set(value):
		var accepted: float = Native.accept("SunflowerPlant.stiffness", value, stiffness)
		if accepted != stiffness:
			stiffness = accepted
			emit_changed()
## Leaves in the wind, for a plant of one part drawn whole (a tree, a bush, a grass clump): its upper
## part moves back and forth about its bent place, a few times a second, each place of the crown in
## its own phase, by up to this share of the bend's sway at the top (growing with the square of the
## height, so the trunk stands). 0 keeps it still; a sunflower's three parts ignore it. The far
## impostors do not flutter (their sway follows the bend).
@export_range(0.0, 1.0, 0.01) var flutter: float = 0.0:
	set(value):
		var accepted: float = Native.accept("SunflowerPlant.flutter", value, flutter)
		if accepted != flutter:
			flutter = accepted
			emit_changed()

@export_group("Variety")
## The middle part is stretched to (1 + α × this) of its length, α ∈ [0, 0.5) per plant (the
## thesis' s' = s + α/10).
@export_range(0.0, 10.0, 0.01) var middle_variation: float = 0.1:
	set(value):
		var accepted: float = Native.accept("SunflowerPlant.middle_variation", value, middle_variation)
		if accepted != middle_variation:
			middle_variation = accepted
			emit_changed()
## Each plant turns up to this much either side of facing +z (seeded).
@export_range(0.0, 180.0, 0.1, "radians_as_degrees") var yaw_range: float = 0.35:
	set(value):
		var accepted: float = Native.accept("SunflowerPlant.yaw_range", value, yaw_range)
		if accepted != yaw_range:
			yaw_range = accepted
			emit_changed()
## Each plant's size factor is drawn from [member scale_min] to [member scale_max] (seeded).
@export_range(0.01, 100.0, 0.01) var scale_min: float = 1.0:
	set(value):
		var accepted: float = Native.accept("SunflowerPlant.scale_min", value, scale_min)
		if accepted != scale_min:
			scale_min = accepted
			emit_changed()
## See [member scale_min].
@export_range(0.01, 100.0, 0.01) var scale_max: float = 1.0:
	set(value):
		var accepted: float = Native.accept("SunflowerPlant.scale_max", value, scale_max)
		if accepted != scale_max:
			scale_max = accepted
			emit_changed()

## Each plant's brightness varies by up to ± this share (seeded): the instance colour multiplies
## the albedo of materials that use vertex colour as albedo (the built-in plants do) and of the
## impostors.
@export_range(0.0, 1.0, 0.01) var brightness_variation: float = 0.0:
	set(value):
		var accepted: float = Native.accept("SunflowerPlant.brightness_variation", value, brightness_variation)
		if accepted != brightness_variation:
			brightness_variation = accepted
			emit_changed()
## Each plant is tinted warmer or cooler by up to ± this share (red up and blue down, or the other
## way; seeded), like [member brightness_variation].
@export_range(0.0, 1.0, 0.01) var tint_variation: float = 0.0:
	set(value):
		var accepted: float = Native.accept("SunflowerPlant.tint_variation", value, tint_variation)
		if accepted != tint_variation:
			tint_variation = accepted
			emit_changed()

@export_group("Play")
## Seconds on the field's clock until a plant of this type that was flattened (trampled, see
## [member SunflowerField.trample_share], or [method SunflowerFieldPlay.change_plants]) stands again; 0:
## it lies for good.
@export_range(0.0, 3600.0, 0.1, "or_greater", "suffix:s") var recover_after: float = 0.0:
	set(value):
		var accepted: float = Native.accept("SunflowerPlant.recover_after", value, recover_after)
		if accepted != recover_after:
			recover_after = accepted
			emit_changed()
## Seconds on the field's clock until a cut plant of this type has grown again; 0: it stays cut.
@export_range(0.0, 3600.0, 0.1, "or_greater", "suffix:s") var regrow_after: float = 0.0:
	set(value):
		var accepted: float = Native.accept("SunflowerPlant.regrow_after", value, regrow_after)
		if accepted != regrow_after:
			regrow_after = accepted
			emit_changed()
## What a cut plant of this type leaves: a stump this many metres tall (its bottom part, upright,
## shortened to that height — at most that part's length — drawn near as a mesh); 0: nothing. A plant
## of one part (a tree or a bush from a scene: no middle or head in [member part_lengths]) has no
## bottom part of its own and leaves nothing (the field warns).
@export_range(0.0, 2.0, 0.01, "or_greater", "suffix:m") var stump_height: float = 0.0:
	set(value):
		var accepted: float = Native.accept("SunflowerPlant.stump_height", value, stump_height)
		if accepted != stump_height:
			stump_height = accepted
			emit_changed()

@export_group("Impostors")
## The far levels' views of the plant (colour and alpha), an atlas of [constant ATLAS_VIEWS] squares.
@export var impostor_views: Texture2D:
	set(value):
		impostor_views = value
		emit_changed()  # always: the same array or texture may hold new contents
## The plant's normals in the same views, in the plant's own frame (x, y, z as red, green, blue,
## 0–1 for −1–1): the far levels are lit through them like the meshes.
@export var impostor_normals: Texture2D:
	set(value):
		impostor_normals = value
		emit_changed()  # always: the same array or texture may hold new contents
## How far each pixel of the views lies in front of (lighter) or behind (darker) the plant's middle,
## along the view (0–1 for −½ to +½ of the view's square): the far levels are lit and shadowed where
## the plant's leaves and head are, not on the flat quad.
@export var impostor_depths: Texture2D:
	set(value):
		impostor_depths = value
		emit_changed()  # always: the same array or texture may hold new contents
## The light the plant's parts give off (their materials' emission) in the same views, divided by
## [member impostor_emission_range], so that the far levels glow as the meshes do; none
## ([code]null[/code]) when no part gives off light. Baked with the others, only for a plant that
## glows.
@export var impostor_emission: Texture2D:
	set(value):
		impostor_emission = value
		emit_changed()  # always: the same array or texture may hold new contents
## The light the plant's parts let through from behind (their materials' back-light) in the same
## views, so that the far levels glow against the sun as the meshes' leaves do; none
## ([code]null[/code]) when no part lets light through. Baked with the others, only for such a plant.
@export var impostor_backlight: Texture2D:
	set(value):
		impostor_backlight = value
		emit_changed()  # always: the same array or texture may hold new contents
## What [member impostor_emission] was divided by: 8-bit colours keep energies up to it. The baker sets
## it, the smallest of 8, 64, 512 … in which no pixel of the atlas saturates (a brighter light would
## make the far levels glow less than the meshes); set it yourself for an atlas made elsewhere.
@export_range(1.0, 32768.0, 1.0) var impostor_emission_range: float = 8.0:
	set(value):
		var accepted: float = Native.accept("SunflowerPlant.impostor_emission_range", value, impostor_emission_range)
		if accepted != impostor_emission_range:
			impostor_emission_range = accepted
			emit_changed()

## The alpha each mip level of [member impostor_views] is cut at so that the impostors cover what
## the views cover: at level [i]k[/i], the cut that the same share of that level's texels reaches as
## the views' mean alpha (what a pixel of the plant's thin leaves covers, which a fixed cut loses).
## The baker measures it (empty for an atlas baked before it did: the field's
## [member SunflowerField.alpha_scissor], raised with distance); a cut above the field's is not used.
@export var impostor_alpha_cuts: PackedFloat32Array = []:
	set(value):
		if value != impostor_alpha_cuts:
			impostor_alpha_cuts = value
			emit_changed()

## The mip level of [member impostor_views] from which the plant is [i]thin[/i]: where a plain alpha
## cut keeps less than half of what the views' texels cover (a crown of leaves smaller than a texel).
## From there, and for such a plant from mip −0.5 on in any case (a texel over at most 1.4 pixels), its
## impostors' alpha test is hashed (each pixel drawn as often as its texel is covered,
## speckled as the meshes' far leaves are) and each view is read at the quad's own place (reading it
## where the depths say spreads a sparse crown's cover). The baker measures it, and bakes a thin
## plant's views twice as fine (256 pixels a view: its leaves stay whole texels drawn larger), so its
## level is one more there (the Sapling maple's 1.84); −1: not before the far test is hashed anyway
## (the built-in sunflower, or an atlas baked before it was measured).
@export_range(-1.0, 4.0, 0.01) var impostor_thin_from: float = -1.0:
	set(value):
		if value != impostor_thin_from:
			impostor_thin_from = value
			emit_changed()

## Near plants of this type cast their shadows from its far impostors from the field's
## [member SunflowerField.impostor_shadows_from] on (fewer primitives). Off: they cast from their
## meshes at every mesh level, the meshes' own specks of shade at the meshes' cost (a thin tree's
## impostor shadows are as dark and as dappled, their specks elsewhere; docs/plants.md compares them).
@export var impostor_shadows: bool = true:
	set(value):
		if value != impostor_shadows:
			impostor_shadows = value
			emit_changed()
## How far the far levels' shadow casters stand out towards the light, as a share of the impostor's
## frame, beyond the depth the plant has at each pixel: a little shades a field of it as its meshes
## shade each other (0.03 suits the sunflower; more shades a lone plant's own leaves with specks).
@export_range(0.0, 0.5, 0.01) var impostor_shadow_shift: float = 0.03:
	set(value):
		var accepted: float = Native.accept("SunflowerPlant.impostor_shadow_shift", value, impostor_shadow_shift)
		if accepted != impostor_shadow_shift:
			impostor_shadow_shift = accepted
			emit_changed()

var _parts: PlantParts = PlantParts.new()  # the copies of its meshes the field draws, made once


## A plant of one part made from [param scene] (a glTF, .blend or .tscn plant): its meshes with
## their node transforms and material overrides merged per mesh level, its level-of-detail variants
## ([code]_LOD0[/code], [code]_LOD1[/code] … node names) as mesh levels, or levels 2 and 3 generated
## from level 1, with fewer and bigger leaves and fewer twigs (see [code]scene_plant.gd[/code]); framed
## by [method fit_to_meshes], and as tall as the scene models it (a unit a metre). Null, with an
## error, for a scene that draws nothing (no mesh, or no triangle with area); a warning for what it
## leaves out and for a plant that stands wholly below or far above its root.
## Bake its impostors next ([method bake_impostors]; the editor's plant inspector does it at once).
static func from_scene(scene: PackedScene) -> SunflowerPlant:
	return ScenePlant.plant_of(scene)


## Frames the plant from its level-1 parts as they stack, upright: [member height_units] (the root
## to the top), [member impostor_width] (twice the farthest reach from the stem) and
## [member cull_radius_units] (the sphere about the middle that holds the plant tilted by the wind's
## largest bend). A plant of one part also gets that part's top as [member part_lengths].x.
func fit_to_meshes() -> void:
	PlantParts.fit(self)


## The built-in sunflower (shared: duplicate it before changing it).
static func default_plant() -> SunflowerPlant:
	if _default == null:
		_default = load(DEFAULT_PATH) as SunflowerPlant
	return _default


## The mesh of a part (level 0–2, part 0–2); null where none is set.
func get_part_mesh(level: int, part: int) -> Mesh:
	return PlantParts.level_parts(self, level)[part]


## The mesh a part is drawn with: its own, or at a level with no parts at all the nearest level
## above that has some (a plant of one set of meshes draws it at all three levels); null for an
## empty slot, which draws nothing.
func mesh_drawn(level: int, part: int) -> Mesh:
	return PlantParts.drawn(self, level, part)


## The triangles of one plant at mesh [param level] (0–2), its parts as drawn ([method mesh_drawn]).
func triangle_count(level: int) -> int:
	return PlantParts.triangles(self, level)


## [member part_lengths] as the parts stack: the slots above the top level-1 part are empty, and
## their lengths count 0, so that [member height] spans the parts there are.
func stacked_lengths() -> Vector3:
	var lengths: Vector3 = part_lengths
	for part: int in [2, 1]:
		if mesh_level_1[part] != null:
			break
		lengths[part] = 0.0
	return lengths


## What keeps the parts from stacking as a plant, a sentence each naming the slot: no level-1 part,
## or an empty slot below a filled one (the parts above it float over the gap). Empty when it stacks.
func stacking_problems() -> PackedStringArray:
	return PlantParts.stacking_problems(self)


## The mesh the field's nodes draw a part with: [method mesh_drawn], its plain StandardMaterial3D
## surfaces drawn with the plant material and its own ShaderMaterials made to fade when
## [member use_plant_material] (a copy made once per mesh: an edit inside the mesh or its materials
## shows once the part slot is set again).
func mesh_for_field(level: int, part: int) -> Mesh:
	return _parts.for_field(self, level, part)


## Whether the near levels draw this plant whole ([member draw_whole], and every level's parts as
## the field draws them can be merged).
func drawn_whole() -> bool:
	return _parts.drawn_whole(self)


## The mesh a plant drawn whole is drawn with at [param level] (its parts as drawn, merged), or null
## when they cannot be merged. Made once per set of parts, [member part_lengths] and
## [member flutter]: an edit inside a part mesh or its material shows once a part slot, the lengths
## or the flutter change (set the part again).
func whole_mesh(level: int) -> Mesh:
	return _parts.whole_mesh(self, level)


## The impostor texture drawn ([constant IMPOSTOR_TEXTURES], [constant EMISSION_TEXTURE] or
## [constant BACKLIGHT_TEXTURE]): the plant's own; none until its impostors are baked.
func texture_drawn(kind: String) -> Texture2D:
	return get("impostor_" + kind)


## The scale of the field's switch distances for this plant: [member lod_scale], or when that is 0
## the larger of [member height] and [method width_metres] over the default plant's height (2 m).
func lod_scale_used() -> float:
	if lod_scale > 0.0:
		return lod_scale
	return maxf(height, width_metres()) / float((SunflowerPlant as Script).get_property_default_value(&"height"))


## The plant's width in metres at its size factor 1: [member impostor_width] at [member height].
func width_metres() -> float:
	var lengths: Vector3 = stacked_lengths()
	return impostor_width * height / maxf(lengths.x + lengths.y + lengths.z, 1e-4)


## The cell size a field of this plant needs for neighbours not to stand in each other: its width
## ([method width_metres]) rounded up to 5 cm.
func spacing_metres() -> float:
	return snappedf(width_metres() + 0.049, 0.05)


## The square every impostor view frames and the height of its centre above the root, model units:
## the [member impostor_width] × [member height_units] cylinder fits it from every elevation
## (its outline seen at elevation e is w wide and h·cos e + w·sin e tall, at most √(h² + w²)).
func impostor_frame() -> Vector2:
	return Vector2(sqrt(height_units * height_units + impostor_width * impostor_width), height_units * 0.5)


## What a field's layout takes from the plant beyond its rows of the core's table (whose changes the
## core judges, field_settings.gd): whether it is drawn whole (the native buckets follow it), with
## the plant material, and the scale of its switch distances. A change of any of these builds the
## field anew.
func layout_key() -> Array:
	return [drawn_whole(), use_plant_material, lod_scale_used()]


## Sets the mesh of a part (level 0–2, part 0–2); null clears it.
func set_part_mesh(level: int, part: int, mesh: Mesh) -> void:
	var meshes: Array[Mesh] = PlantParts.level_parts(self, level).duplicate()
	meshes[part] = mesh
	set(PlantParts.LEVEL_PROPERTIES[level], meshes)


## Renders this plant's impostor textures from its level-1 parts and takes them (see
## ImpostorBaker: [code]impostor_baker.gd[/code]); await it. [param host] is any node in a tree that
## draws; the files go to [param folder] (default: beside this resource). Returns OK or an error.
## [param progress], when valid, is called with each step's name and the share done before it (0–1).
func bake_impostors(host: Node, folder: String = "", base_name: String = "", progress: Callable = Callable()) -> Error:
	return await ImpostorBaker.bake(self, host, folder, base_name, progress)


## The value the core's table row of [param property] gets ([code]field_settings.gd[/code]): the
## lengths as stacked, without empty slots above the plant's top part; others as they are.
func _row_value(property: StringName, value: Variant) -> Variant:
	return stacked_lengths() if property == &"part_lengths" else value


## The inspector's range hints take their limits from the core's table (native.gd: [code]range_hint[/code]).
func _validate_property(property: Dictionary) -> void:
	if property["hint"] == PROPERTY_HINT_RANGE:
		property["hint_string"] = Native.range_hint("SunflowerPlant." + property["name"], property["hint_string"])
