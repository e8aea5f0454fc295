extends TestCase
## Bodies among the plants: pushers part the field and it recovers; stalk colliders stand within
## reach only, ray casts hit the right plant, and the colliders go with the field.

var field: SunflowerField
var observer: Node3D
var pusher: Node3D


func before_each() -> void:
	pusher = Node3D.new()
	pusher.name = "Pusher"
	tree.root.add_child(pusher)
	observer = Node3D.new()
	observer.name = "Observer"
	observer.position = Vector3(10.0, 1.7, 8.0)
	field = field_in_tree(observer, load("res://fields/demo.field") as SunflowerFieldMap)
	field.wind_power = 0.0  # calm air: only the pusher moves plants
	for i: int in 40:  # natural wind eases the change in
		field.advance(0.05)


func after_each() -> void:
	field.free()
	observer.free()
	pusher.free()


## The horizontal offset of a plant's head from its root, in the field's space.
func _lean(plant: int) -> Vector2:
	var parts: Array = field.get_plant_info(plant)["parts"]
	var root: Vector3 = (parts[0] as Transform3D).origin
	var head: Transform3D = parts[2]
	var top: Vector3 = head.origin + head.basis.y
	return Vector2(top.x - root.x, top.z - root.z)


func test_a_pusher_parts_the_plants_and_they_recover_once_it_leaves() -> void:
	var near: int = 500
	var centre: Vector3 = field.get_plant_info(near)["position"] - Vector3(0.3, -1.0, 0.1)  # a body beside it
	check_eq(field.get_plant_at(centre + Vector3(0.3, -1.0, 0.1), 0.05), near, "get_plant_at finds it")
	pusher.position = centre
	pusher.add_to_group(&"sunflower_pushers")
	for i: int in 60:
		field.advance(1.0 / 60.0)
	var away: Vector3 = field.get_plant_info(near)["position"] - centre
	var lean: Vector2 = _lean(near)
	check(lean.dot(Vector2(away.x, away.z)) > 0.0, "the plant leans away from the body: %s vs %s" % [lean, away])
	check(lean.length() > 0.05, "and visibly (%.3f m at the head)" % lean.length())
	check(field.get_pushed_count() >= 2, "several plants are pushed (%d)" % field.get_pushed_count())
	pusher.remove_from_group(&"sunflower_pushers")
	for i: int in int(field.push_recovery_time * 60.0 * 1.2):
		field.advance(1.0 / 60.0)
	check_eq(field.get_pushed_count(), 0, "every plant recovered")
	check(_lean(near).length() < 0.001, "upright again (%.4f m)" % _lean(near).length())


func test_stalk_colliders_stand_within_reach_and_ray_casts_hit_the_plant() -> void:
	field.collision_reach = 2.0
	field.collision_layer = 4
	field.advance(1.0 / 60.0)
	var expected: int = field.get_simulation().get_plants_near(observer.position, 2.0, true).size()
	check(expected > 10, "plants within 2 m of the observer (%d)" % expected)
	check_eq(field.get_collider_count(), expected, "a collider per plant within reach, none outside")
	await tree.physics_frame
	await tree.physics_frame
	var target: int = field.get_plant_at(observer.position + Vector3(1.0, 0.0, 0.0), 0.4)
	var root: Vector3 = field.get_plant_info(target)["position"]
	var query: PhysicsRayQueryParameters3D = PhysicsRayQueryParameters3D.create(
		root + Vector3(0.0, 0.5, -0.2), root + Vector3(0.0, 0.5, 0.2), 4
	)
	var hit: Dictionary = field.get_world_3d().direct_space_state.intersect_ray(query)
	if check(not hit.is_empty(), "the ray across plant %d's stalk hits something" % target):
		check(hit["collider"] == field, "the field is the collider's object")
		check_eq(field.get_plant_for_body(hit["rid"]), target, "the collider tells which plant was hit")
		var cell: PackedInt32Array = [field.play.get_cell_of_plant(target)]
		field.play.change_plants(cell, SunflowerFieldPlay.Change.CUT)
		check_eq(field.get_plant_for_body(hit["rid"]), -1, "a plant cut since its collider stood is no plant")
		field.play.change_plants(cell, SunflowerFieldPlay.Change.RESTORE)
	# The capsule reaches the head's root, as the core stacks this plant's parts, and no higher.
	var stalk: Vector2 = field.get_simulation().get_plant_stalk(target)
	var parts: Array = field.get_plant_info(target)["parts"]
	check(
		is_equal_approx(stalk.y, parts[SunflowerField.Part.HEAD].origin.y - root.y),
		"the stalk ends at the head (%.3f m)" % stalk.y
	)
	for probe: Array in [[stalk.y - 0.05, true], [stalk.y + 0.05, false]]:
		var across: PhysicsRayQueryParameters3D = PhysicsRayQueryParameters3D.create(
			root + Vector3(0.0, probe[0], -0.2), root + Vector3(0.0, probe[0], 0.2), 4
		)
		var touched: bool = not (field.get_world_3d().direct_space_state.intersect_ray(across).is_empty())
		check_eq(touched, probe[1], "a ray %.2f m up the stalk hits it" % probe[0])
	query.collision_mask = 2
	check(field.get_world_3d().direct_space_state.intersect_ray(query).is_empty(), "not on another layer")
	observer.position = Vector3(-50.0, 1.7, -50.0)
	field.advance(1.0 / 60.0)
	check_eq(field.get_collider_count(), 0, "no colliders once nothing is within reach")
	observer.position = Vector3(10.0, 1.7, 8.0)
	field.advance(1.0 / 60.0)
	check(field.get_collider_count() > 0, "back within reach")
	tree.root.remove_child(field)
	check_eq(field.get_collider_count(), 0, "the colliders go when the field leaves the tree")
	tree.root.add_child(field)
