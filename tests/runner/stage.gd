extends RefCounted
## The scene the render tests and measurements draw fields in: a procedural sky that lights the
## scene, filmic tone mapping, a sun with shadows from the south-east (behind a camera looking
## north) and a plane of soil.

var root: Node3D
var environment: Environment
var ground: MeshInstance3D


## Builds the stage under [param parent]; the ground is [param size] metres square about [param centre].
func _init(parent: Node, size: float = 200.0, centre: Vector3 = Vector3(10.0, 0.0, 7.5)) -> void:
	root = Node3D.new()
	parent.add_child(root)
	environment = Environment.new()
	environment.background_mode = Environment.BG_SKY
	var sky: Sky = Sky.new()
	sky.sky_material = ProceduralSkyMaterial.new()
	environment.sky = sky
	environment.ambient_light_source = Environment.AMBIENT_SOURCE_SKY
	environment.tonemap_mode = Environment.TONE_MAPPER_FILMIC
	var world: WorldEnvironment = WorldEnvironment.new()
	world.environment = environment
	root.add_child(world)
	var sun: DirectionalLight3D = DirectionalLight3D.new()
	sun.rotation_degrees = Vector3(-40.0, 25.0, 0.0)
	sun.shadow_enabled = true
	root.add_child(sun)
	ground = MeshInstance3D.new()
	var plane: PlaneMesh = PlaneMesh.new()
	plane.size = Vector2(size, size)
	var soil: StandardMaterial3D = StandardMaterial3D.new()
	soil.albedo_color = Color(0.36, 0.27, 0.17)
	plane.material = soil
	ground.mesh = plane
	ground.position = centre
	root.add_child(ground)


## Shows the ground and the sky, or (false) hides the ground and makes the sky black, so that only
## what is drawn in front stands out.
func show_scenery(shown: bool) -> void:
	ground.visible = shown
	environment.background_mode = Environment.BG_SKY if shown else Environment.BG_COLOR
	environment.background_color = Color.BLACK


## A field of one [param plant] ([param map]: one cell) on the stage, calm, its levels not faded, built
## and not processed (the test advances it), with the scenery hidden and the sun casting no shadow,
## and a camera made current that sees 2 km: a lone plant to look at from any distance.
func lone_plant(plant: SunflowerPlant, map: SunflowerFieldMap) -> SunflowerField:
	show_scenery(false)
	for light: Node in root.find_children("*", "DirectionalLight3D", true, false):
		(light as DirectionalLight3D).shadow_enabled = false
	var field: SunflowerField = SunflowerField.new()
	field.plant = plant
	field.map = map
	field.wind_power = 0.0
	field.lod_fade = 0.0
	root.add_child(field)
	field.finish_build()
	field.set_process(false)
	var camera: Camera3D = Camera3D.new()
	camera.far = 2000.0
	root.add_child(camera)
	camera.make_current()
	return field
