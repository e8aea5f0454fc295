@tool
extends RefCounted
## Bodies among the plants: gathers the pushers (the nodes in the field's pusher group) for the
## native core, which bends the plants near them away, and keeps the stalks' collision bubble —
## a static capsule on the physics server for each plant within reach of a pusher or the observer,
## made as plants come into reach and freed as they leave (no nodes per plant).

const NativeField: GDScript = preload("../native/native_field.gd")
## Meta key a pusher may carry to set its own radius (metres); else the field's pusher_radius.
const RADIUS_META: StringName = &"push_radius"

## The pushers gathered last, in the order of their floats in [method gather_pushers].
var pusher_nodes: Array[Node3D] = []
var _field: Node3D
var _bodies: Dictionary = {}  # plant index -> body RID
var _plants_of_bodies: Dictionary = {}  # body RID -> plant index
var _pushers: PackedFloat32Array = PackedFloat32Array()


func _init(field: Node3D) -> void:
	_field = field


## The pushers' positions in the field's space and their radii: 4 floats each (x, y, z, radius).
func gather_pushers(group: StringName, default_radius: float) -> PackedFloat32Array:
	_pushers.clear()
	pusher_nodes.clear()
	if group.is_empty() or not _field.is_inside_tree():
		return _pushers
	var to_local: Transform3D = _field.global_transform.affine_inverse()
	for node: Node in _field.get_tree().get_nodes_in_group(group):
		var body: Node3D = node as Node3D
		if body == null or not body.is_inside_tree():
			continue
		var radius: float = float(body.get_meta(RADIUS_META, default_radius))
		var local: Vector3 = to_local * body.global_position
		_pushers.append_array([local.x, local.y, local.z, radius])
		pusher_nodes.append(body)
	return _pushers


## Keeps a capsule (the plant's stalk, as the core sizes it for its plant type and size) standing on
## every standing plant (not one flattened, cut or removed at run time) within [param reach] of the
## gathered pushers and of [param observer] (if any), in the field's physics space, with the given
## collision layer and mask. [param reach] 0 frees them all.
func update_colliders(simulation: NativeField, observer: Node3D, reach: float, layer: int, mask: int) -> void:
	if reach <= 0.0 or not _field.is_inside_tree():
		free_colliders()
		return
	var wanted: Dictionary = {}
	var centres: Array[Vector3] = []
	if observer:
		centres.append(_field.to_local(observer.global_position))
	for i: int in range(0, _pushers.size(), 4):
		centres.append(Vector3(_pushers[i], _pushers[i + 1], _pushers[i + 2]))
	for centre: Vector3 in centres:
		for plant: int in simulation.get_plants_near(centre, reach, true):
			wanted[plant] = true
	for plant: int in _bodies.keys():
		if not wanted.has(plant):
			_free_body(plant)
	var space: RID = _field.get_world_3d().space
	for plant: int in wanted:
		if not _bodies.has(plant):
			_make_body(
				plant, simulation.get_plant_position(plant), simulation.get_plant_stalk(plant), space, layer, mask
			)


## The plant whose stalk collider is [param body] (a ray cast's [code]rid[/code]), or -1.
func get_plant_of_body(body: RID) -> int:
	return _plants_of_bodies.get(body, -1)


## The stalk colliders' bodies (which the ground's rays must not take for the ground).
func get_body_rids() -> Array[RID]:
	var rids: Array[RID] = []
	rids.assign(_bodies.values())
	return rids


## How many stalk colliders exist now.
func get_collider_count() -> int:
	return _bodies.size()


## Frees every collider and its shape.
func free_colliders() -> void:
	for plant: int in _bodies.keys():
		_free_body(plant)


## A static body for [param plant] at [param root] with a capsule of [param stalk] (radius, height).
func _make_body(plant: int, root: Vector3, stalk: Vector2, space: RID, layer: int, mask: int) -> void:
	var shape: RID = PhysicsServer3D.capsule_shape_create()
	var height: float = maxf(stalk.y, 2.0 * stalk.x)  # a capsule is at least its two caps tall
	PhysicsServer3D.shape_set_data(shape, {"radius": stalk.x, "height": height})
	var body: RID = PhysicsServer3D.body_create()
	PhysicsServer3D.body_set_mode(body, PhysicsServer3D.BODY_MODE_STATIC)
	PhysicsServer3D.body_add_shape(body, shape, Transform3D(Basis(), Vector3(0.0, height * 0.5, 0.0)))
	PhysicsServer3D.body_set_collision_layer(body, layer)
	PhysicsServer3D.body_set_collision_mask(body, mask)
	PhysicsServer3D.body_attach_object_instance_id(body, _field.get_instance_id())
	PhysicsServer3D.body_set_state(
		body, PhysicsServer3D.BODY_STATE_TRANSFORM, _field.global_transform * Transform3D(Basis(), root)
	)
	PhysicsServer3D.body_set_space(body, space)
	_bodies[plant] = body
	_plants_of_bodies[body] = plant


func _free_body(plant: int) -> void:
	var body: RID = _bodies[plant]
	var shape: RID = PhysicsServer3D.body_get_shape(body, 0)
	_plants_of_bodies.erase(body)
	_bodies.erase(plant)
	PhysicsServer3D.free_rid(body)
	PhysicsServer3D.free_rid(shape)
