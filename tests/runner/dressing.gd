extends RefCounted
## Part meshes the tests give other materials.


## Every part mesh of [param owner] (a SunflowerField or a SunflowerPlant: the mesh each part is drawn
## with) replaced by a copy whose surfaces all use what [param material_of] returns for that part
## (a Callable taking level and part), through the owner's set_part_mesh. Empty slots stay empty.
static func dress_parts(owner: Object, material_of: Callable) -> void:
	for level: int in SunflowerDrawing.MESH_LEVEL_COUNT:
		for part: int in SunflowerDrawing.PART_COUNT:
			var drawn: Mesh = (
				owner.get_part_mesh(level, part) if owner is SunflowerField else owner.mesh_drawn(level, part)
			)
			if drawn == null:
				continue
			var mesh: ArrayMesh = drawn.duplicate() as ArrayMesh
			var material: Material = material_of.call(level, part)
			for surface: int in mesh.get_surface_count():
				mesh.surface_set_material(surface, material)
			owner.set_part_mesh(level, part, mesh)


## Black, unshaded and two-sided: parts drawn with it leave only the impostors visible on a black
## stage ([method Stage.show_scenery]).
static func unlit_black() -> StandardMaterial3D:
	var black: StandardMaterial3D = StandardMaterial3D.new()
	black.shading_mode = BaseMaterial3D.SHADING_MODE_UNSHADED
	black.albedo_color = Color.BLACK
	black.cull_mode = BaseMaterial3D.CULL_DISABLED
	return black
