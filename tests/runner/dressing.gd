extends RefCounted
## Part meshes the tests give other materials.


## Every part mesh of [param owner] (a SunflowerField or a FieldPlant: the mesh each part is drawn
## with) replaced by a copy whose surfaces all use what [param material_of] returns for that part
## (a Callable taking level and part), through the owner's set_part_mesh.
static func dress_parts(owner: Object, material_of: Callable) -> void:
	for level: int in SunflowerSimulation.MESH_LEVEL_COUNT:
		for part: int in SunflowerSimulation.PART_COUNT:
			var drawn: Mesh = (
				owner.get_part_mesh(level, part) if owner is SunflowerField else owner.mesh_drawn(level, part)
			)
			var mesh: ArrayMesh = drawn.duplicate() as ArrayMesh
			var material: Material = material_of.call(level, part)
			for surface: int in mesh.get_surface_count():
				mesh.surface_set_material(surface, material)
			owner.set_part_mesh(level, part, mesh)
