@tool
extends RefCounted
## The scenes a field's legend places on the map's object cells (a symbol → a PackedScene), each
## at its cell's middle on the ground there, as internal children of the field. A symbol without a
## scene, a scene that makes no node, or an object without ground under it is named in a warning,
## and its cell stays empty.

const NativeField: GDScript = preload("../native/native_field.gd")


## Places [param simulation]'s map objects under [param owner]; returns the nodes made.
static func place(owner: Node3D, simulation: NativeField, legend: Dictionary, cell_size: float) -> Array[Node]:
	var placed: Array[Node] = []
	var objects: PackedInt32Array = simulation.get_map_objects()
	var heights: PackedFloat32Array = simulation.get_object_heights()
	var grounded: int = 0
	for i: int in range(0, objects.size(), 3):
		if is_nan(heights[i / 3]):
			continue  # no ground under it: counted below
		grounded += 1
		var symbol: String = String.chr(objects[i + 2])
		var scene: PackedScene = legend.get(symbol) as PackedScene
		if scene == null:
			push_warning(
				(
					"SunflowerField.legend: '%s' has no PackedScene; cell (%d, %d) stays empty"
					% [symbol, objects[i], objects[i + 1]]
				)
			)
			continue
		var instance: Node = scene.instantiate() if scene.can_instantiate() else null
		if instance == null:
			push_warning(
				(
					"SunflowerField.legend: '%s' names a scene that makes no node (%s); cell (%d, %d) stays empty"
					% [
						symbol,
						scene.resource_path if not scene.resource_path.is_empty() else "an empty scene",
						objects[i],
						objects[i + 1]
					]
				)
			)
			continue
		instance.name = "%s_%d_%d" % [instance.name, objects[i], objects[i + 1]]
		if instance is Node3D:
			(instance as Node3D).position = Vector3(
				(objects[i] + 0.5) * cell_size, heights[i / 3], (objects[i + 1] + 0.5) * cell_size
			)
		owner.add_child(instance, false, Node.INTERNAL_MODE_BACK)
		placed.append(instance)
	if grounded < heights.size():
		push_warning(
			(
				"SunflowerField.legend: %d of %d objects have no ground under them and are not placed"
				% [heights.size() - grounded, heights.size()]
			)
		)
	return placed
