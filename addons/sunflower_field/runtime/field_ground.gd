@tool
extends RefCounted
## Where a field's plants stand: turns the node's Ground settings into the native simulation's ground.
## A height map is read into the simulation on the build's worker; colliders are found by rays cast
## straight down on the main thread, a budget's worth per frame, after the bodies have had a physics
## frame to enter the space.

## The ground sources (the node's [code]ground_source[/code]).
enum Source { FLAT, COLLIDERS, HEIGHT_MAP }

const NativeField: GDScript = preload("../native/native_field.gd")
## Rays cast between two clock reads (about 0.1 ms of them); a step stops when one more batch
## would overrun its budget.
const RAYS_PER_CLOCK_READ: int = 64

## What the worker needs of the node's ground: copied on the main thread, so the node may change.
var source: Source = Source.FLAT
var tilt: float = 0.0
var height_map: Image
var height_map_rect: Rect2
var height_range: Vector2
var texture_path: String

## Collider rays: the field's transform and query, the ground points and what they hit so far.
var _space: PhysicsDirectSpaceState3D
var _to_world: Transform3D
var _to_local: Transform3D
var _query: PhysicsRayQueryParameters3D
var _points: PackedFloat32Array
var _heights: PackedFloat32Array
var _normals: PackedFloat32Array
var _next: int = 0
var _above: float = 0.0
var _below: float = 0.0
var _ready_frame: int = 0
var _ray_usec: int = 0


## The ground of [param field] as its properties set it now.
static func for_field(field: Node3D) -> RefCounted:
	var ground: RefCounted = new()
	ground.source = field.ground_source
	ground.tilt = field.ground_tilt
	if ground.source == Source.HEIGHT_MAP and field.height_map:
		ground.height_map = field.height_map.get_image()
		ground.texture_path = field.height_map.resource_path
	ground.height_map_rect = field.height_map_rect
	ground.height_range = field.height_range
	return ground


## Before the map is read (on the worker): a flat field as before, or no ground at all until the
## real one is known, so reading the map lays out no plant twice.
func prepare(simulation: NativeField) -> void:
	if source == Source.FLAT:
		simulation.set_ground_flat()
	else:
		simulation.set_ground_heights(PackedFloat32Array(), PackedFloat32Array(), tilt)


## After the map is read (on the worker): the height map's ground. Returns what is wrong, or "".
func apply_height_map(simulation: NativeField, cell_size: float) -> String:
	if source != Source.HEIGHT_MAP:
		return ""
	if height_map == null or height_map.is_empty():
		return "SunflowerField.height_map: the ground source is Height Map but no height map is set"
	var image: Image = height_map.duplicate() as Image
	if image.is_compressed() and image.decompress() != OK:
		return "SunflowerField.height_map: %s is compressed in a format that cannot be read back" % _name()
	image.convert(Image.FORMAT_RGBAF)
	var rect: Rect2 = height_map_rect
	if not rect.has_area():  # the whole field
		rect = Rect2(0.0, 0.0, simulation.get_map_columns() * cell_size, simulation.get_map_rows() * cell_size)
	var message: String = simulation.set_ground_height_map(
		image.get_data().to_float32_array(),
		image.get_width(),
		image.get_height(),
		rect.position,
		rect.size,
		height_range.x,
		height_range.y,
		tilt
	)
	return "" if message.is_empty() else "SunflowerField.height_map (%s): %s" % [_name(), message]


## Whether the plants wait for collider rays on the main thread.
func needs_rays() -> bool:
	return source == Source.COLLIDERS


## After the map is read (on the worker): the ground points the rays go through, when on colliders.
func prepare_rays(simulation: NativeField) -> void:
	if not needs_rays():
		return
	set_ray_points(simulation.get_ground_points())
	_normals.resize(_points.size() / 2 * 3 if tilt > 0.0 else 0)


## The points the rays go through (x, z pairs in the field's space), without normals: the build's
## ground points ([method prepare_rays]) or any others (placement rules: every cell's centre).
func set_ray_points(points: PackedFloat32Array) -> void:
	_points = points
	_heights.resize(_points.size() / 2)
	_normals.resize(0)
	_next = 0


## The heights the rays found, one a point, in the field's space (NaN where a ray hit nothing).
func get_ray_heights() -> PackedFloat32Array:
	return _heights


## Readies the rays (on the main thread), cast from [param above] metres above the field's origin
## down to [param below] metres under it, hitting bodies in [param mask].
func start_rays(field: Node3D, above: float, below: float, mask: int) -> void:
	_to_world = field.global_transform
	_to_local = _to_world.affine_inverse()
	_space = field.get_world_3d().direct_space_state
	_query = PhysicsRayQueryParameters3D.create(Vector3(), Vector3(0.0, -1.0, 0.0), mask)
	_query.hit_back_faces = false
	_above = above
	_below = below
	# Bodies entering the tree this frame join the physics space at its next step.
	_ready_frame = Engine.get_physics_frames() + 1


## Casts rays until [param budget_usec] is spent (negative: all of them, now), hitting none of
## [param exclude] (the field's own stalks). True when all are cast. Waits for a physics frame after
## [method start_rays] unless it must finish now.
func cast_rays(budget_usec: int, exclude: Array[RID]) -> bool:
	if budget_usec >= 0 and Engine.get_physics_frames() < _ready_frame:
		return false
	var start: int = Time.get_ticks_usec()
	_query.exclude = exclude
	var count: int = _heights.size()
	var slowest: int = 0  # the longest a batch took, to stop before the budget is overrun
	while _next < count:
		var batch_start: int = Time.get_ticks_usec()
		var last: int = mini(_next + RAYS_PER_CLOCK_READ, count)
		for i: int in range(_next, last):
			var x: float = _points[2 * i]
			var z: float = _points[2 * i + 1]
			_query.from = _to_world * Vector3(x, _above, z)
			_query.to = _to_world * Vector3(x, -_below, z)
			var hit: Dictionary = _space.intersect_ray(_query)
			if hit.is_empty():
				_heights[i] = NAN
				continue
			_heights[i] = (_to_local * (hit["position"] as Vector3)).y
			if not _normals.is_empty():
				var normal: Vector3 = (_to_local.basis * (hit["normal"] as Vector3)).normalized()
				_normals[3 * i] = normal.x
				_normals[3 * i + 1] = normal.y
				_normals[3 * i + 2] = normal.z
		_next = last
		var now: int = Time.get_ticks_usec()
		slowest = maxi(slowest, now - batch_start)
		if budget_usec >= 0 and now - start + slowest >= budget_usec:
			break
	_ray_usec += Time.get_ticks_usec() - start
	return _next >= count


## How far the rays are, 0 to 1.
func get_ray_progress() -> float:
	return 1.0 if _heights.is_empty() else float(_next) / _heights.size()


## Main-thread time spent casting rays, in milliseconds.
func get_ray_ms() -> float:
	return _ray_usec / 1000.0


## Hands the rays' hits to [param simulation] (on the worker: it lays the plants out). Returns what
## is wrong, or "".
func apply_rays(simulation: NativeField) -> String:
	var message: String = simulation.set_ground_heights(_heights, _normals, tilt)
	_points = PackedFloat32Array()
	return message


func _name() -> String:
	return texture_path if not texture_path.is_empty() else "the height map"
