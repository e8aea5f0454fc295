@tool
extends RefCounted
## What a plant scene draws, as the editor shows it, in pieces for [code]scene_plant.gd[/code] to
## merge: each visible [MeshInstance3D] (its blend shapes at the node's weights), each instance of a
## [MultiMeshInstance3D], and each CSG shape at the top of its tree (its baked mesh), placed by the
## node transforms relative to the scene's root, in the root's rotation and scale, from its origin
## ([code]top_level[/code] nodes where they stand), with
## the materials it shows and the mesh level it belongs to: a level-of-detail suffix in its name
## ([code]_LOD0[/code], [code]-lod1[/code] …) or, for Godot's own manual levels of detail, its
## [member GeometryInstance3D.visibility_range_begin]/[code]_end[/code] (the nearest range level 1).
## What it cannot take is a problem naming the node and the reason: a shadow proxy (a node that only
## casts a shadow) and nodes that draw nothing a plant carries (lights, decals, probes) are left out;
## a node's [member GeometryInstance3D.material_overlay], [member GeometryInstance3D.transparency] and
## a shadow it does not cast are not carried.

## The mesh levels a scene's variants fill.
const LEVELS: int = 3

static var _suffix: RegEx
static var _instance_uniform: RegEx


## The pieces [param root] draws: each a Dictionary of [code]"name"[/code] (the node's path in the
## scene), [code]"mesh"[/code], [code]"materials"[/code] (one a surface, as shown),
## [code]"transform"[/code] (to the root's frame), [code]"weights"[/code] (blend shape values; empty:
## none), [code]"level"[/code] (0–2, or -1 for every level) and [code]"instance_parameters"[/code]
## (the node's values of its materials' [code]instance uniform[/code]s). What is left out, and why, is
## appended to [param problems].
static func of(root: Node, problems: PackedStringArray) -> Array[Dictionary]:
	var pieces: Array[Dictionary] = []
	_collect(root, root, _root_frame(root), pieces, problems)
	_levels_from_suffixes(pieces, problems)
	if not pieces.any(func(piece: Dictionary) -> bool: return piece.level >= 0):
		_levels_from_ranges(pieces, problems)
	for piece: Dictionary in pieces:
		piece.erase("suffix")
		piece.erase("range")
	return pieces


## The frame a plant's pieces are placed in: [param root]'s rotation and scale (the editor shows the
## scene with them, and an instance of it starts with them: a model turned upright or scaled to metres
## by its root), not its place (the root's origin is the plant's root).
static func _root_frame(root: Node) -> Transform3D:
	return Transform3D((root as Node3D).basis, Vector3.ZERO) if root is Node3D else Transform3D.IDENTITY


## The level of detail a node's name marks (0, 1, 2 …), or -1 for none.
static func level_of_name(node_name: String) -> int:
	if _suffix == null:
		_suffix = RegEx.create_from_string("(?i)[_\\-. ]lod[_\\-]?(\\d+)$")
	var found: RegExMatch = _suffix.search(node_name)
	return found.get_string(1).to_int() if found else -1


static func _collect(
	node: Node, root: Node, to_root: Transform3D, pieces: Array[Dictionary], problems: PackedStringArray
) -> void:
	var here: Transform3D = to_root
	if node is Node3D:
		var spatial: Node3D = node as Node3D
		if not spatial.visible:
			return
		if node != root and spatial.top_level:  # where it stands, from the scene root's origin
			var origin: Vector3 = (root as Node3D).position if root is Node3D else Vector3.ZERO
			here = Transform3D(Basis.IDENTITY, -origin) * spatial.transform
		elif node != root:
			here = to_root * spatial.transform
	var path: String = String(root.get_path_to(node)) if node != root else String(root.name)
	if node is GeometryInstance3D:
		_add_geometry(node as GeometryInstance3D, path, here, pieces, problems)
		if node is CSGShape3D:
			return  # the shapes below are part of its mesh
	elif node is VisualInstance3D:
		problems.append("%s: a %s is not carried into a field's plants; left out" % [path, node.get_class()])
	for child: Node in node.get_children():
		_collect(child, root, here, pieces, problems)


## Adds what [param instance] draws (a MeshInstance3D, MultiMeshInstance3D or CSG shape), naming what
## of its look the plant does not carry; any other geometry, or a shadow proxy, is named and left out.
static func _add_geometry(
	instance: GeometryInstance3D,
	path: String,
	here: Transform3D,
	pieces: Array[Dictionary],
	problems: PackedStringArray
) -> void:
	if not (instance is MeshInstance3D or instance is MultiMeshInstance3D or instance is CSGShape3D):
		problems.append(
			(
				"%s: a %s is not read (only MeshInstance3D, MultiMeshInstance3D and CSG shapes are); left out"
				% [path, instance.get_class()]
			)
		)
		return
	if instance.cast_shadow == GeometryInstance3D.SHADOW_CASTING_SETTING_SHADOWS_ONLY:
		problems.append(
			"%s: it only casts a shadow (a shadow proxy); left out: the plant's levels cast from what they draw" % path
		)
		return
	if instance.material_overlay:
		problems.append("%s: its material_overlay is not carried; drawn without it" % path)
	if instance.transparency > 0.0:
		problems.append("%s: its transparency (%.2f) is not carried; drawn opaque" % [path, instance.transparency])
	if instance.cast_shadow == GeometryInstance3D.SHADOW_CASTING_SETTING_OFF:
		problems.append("%s: it casts no shadow in the scene, but a field's plants cast from all they draw" % path)
	if instance is MeshInstance3D:
		_add_mesh_instance(instance as MeshInstance3D, path, here, pieces, problems)
	elif instance is MultiMeshInstance3D:
		_add_multimesh(instance as MultiMeshInstance3D, path, here, pieces, problems)
	else:
		_add_csg(instance as CSGShape3D, path, here, pieces, problems)


static func _add_mesh_instance(
	instance: MeshInstance3D, path: String, here: Transform3D, pieces: Array[Dictionary], problems: PackedStringArray
) -> void:
	if instance.mesh == null:
		return
	var weights: PackedFloat32Array = []
	var blends: int = instance.mesh.get_blend_shape_count() if instance.mesh is ArrayMesh else 0
	for shape: int in blends:
		weights.append(instance.get_blend_shape_value(shape))
	var materials: Array[Material] = _materials_shown(instance, instance.mesh)
	var mesh: Mesh = instance.mesh
	if _has_bone_weights(mesh):
		var skeleton: Skeleton3D = instance.get_node_or_null(instance.skeleton) as Skeleton3D
		if skeleton == null:
			problems.append(
				(
					"%s: a skinned mesh whose skeleton (%s) is not in the scene; taken unposed (as modelled)"
					% [path, instance.skeleton]
				)
			)
		else:
			mesh = posed(mesh as ArrayMesh, skeleton, instance.skin, weights)
			weights = []  # applied before the pose, as the engine does
	pieces.append(_piece(path, mesh, materials, here, weights, instance))


## [param mesh] as its [param skeleton] poses it (each vertex moved by its bones' poses times their
## bind poses, weighted; its blend shapes at [param weights] first), in the mesh instance's frame,
## with no bones left. [param skin] binds the mesh's bone indices to the skeleton's bones; null: the
## skeleton's bones in order, bound at their rest (as the engine makes one).
static func posed(mesh: ArrayMesh, skeleton: Skeleton3D, skin: Skin, weights: PackedFloat32Array) -> ArrayMesh:
	var binds: Array[Transform3D] = []
	var bind_count: int = skin.get_bind_count() if skin else skeleton.get_bone_count()
	for bind: int in bind_count:
		var bone: int = bind
		var bind_pose: Transform3D = skeleton.get_bone_global_rest(bind).affine_inverse() if not skin else Transform3D()
		if skin:
			bone = skin.get_bind_bone(bind)
			if bone < 0:
				bone = skeleton.find_bone(skin.get_bind_name(bind))
			bind_pose = skin.get_bind_pose(bind)
		binds.append(skeleton.get_bone_global_pose(bone) * bind_pose if bone >= 0 else Transform3D())
	var out: ArrayMesh = ArrayMesh.new()
	for surface: int in mesh.get_surface_count():
		var arrays: Array = mesh.surface_get_arrays(surface)
		if not weights.is_empty():
			arrays = blended(arrays, mesh.surface_get_blend_shape_arrays(surface), weights)
		var positions: PackedVector3Array = arrays[Mesh.ARRAY_VERTEX]
		var bones: Variant = arrays[Mesh.ARRAY_BONES]
		var bone_weights: Variant = arrays[Mesh.ARRAY_WEIGHTS]
		if bones != null and bone_weights != null and positions.size() > 0:
			var per_vertex: int = bones.size() / positions.size()
			var normals: Variant = arrays[Mesh.ARRAY_NORMAL]
			var moved: PackedVector3Array = positions.duplicate()
			var turned: PackedVector3Array = normals.duplicate() if normals != null else PackedVector3Array()
			for v: int in positions.size():
				var position: Vector3 = Vector3.ZERO
				var normal: Vector3 = Vector3.ZERO
				for k: int in per_vertex:
					var weight: float = bone_weights[v * per_vertex + k]
					var bind: int = int(bones[v * per_vertex + k])
					if weight == 0.0 or bind < 0 or bind >= binds.size():
						continue
					position += weight * (binds[bind] * positions[v])
					if normals != null:
						normal += weight * (binds[bind].basis * (normals as PackedVector3Array)[v])
				moved[v] = position
				if normals != null:
					turned[v] = normal.normalized()
			arrays[Mesh.ARRAY_VERTEX] = moved
			if normals != null:
				arrays[Mesh.ARRAY_NORMAL] = turned
		arrays[Mesh.ARRAY_BONES] = null
		arrays[Mesh.ARRAY_WEIGHTS] = null
		out.add_surface_from_arrays(mesh.surface_get_primitive_type(surface), arrays)
		out.surface_set_material(surface, mesh.surface_get_material(surface))
	return out


## A surface's [param arrays] with its blend shapes ([param shapes], their target arrays) applied at
## [param weights], as the engine draws them: each position and normal moved by weight × (target −
## base).
static func blended(arrays: Array, shapes: Array, weights: PackedFloat32Array) -> Array:
	var out: Array = arrays.duplicate()
	for kind: int in [Mesh.ARRAY_VERTEX, Mesh.ARRAY_NORMAL]:
		if arrays[kind] == null:
			continue
		var base: PackedVector3Array = arrays[kind]
		var moved: PackedVector3Array = base.duplicate()
		for shape: int in mini(shapes.size(), weights.size()):
			var target: Variant = (shapes[shape] as Array)[kind]
			if weights[shape] == 0.0 or target == null:
				continue
			var values: PackedVector3Array = target
			for k: int in mini(values.size(), moved.size()):
				moved[k] += weights[shape] * (values[k] - base[k])
		if kind == Mesh.ARRAY_NORMAL:
			for k: int in moved.size():
				moved[k] = moved[k].normalized()
		out[kind] = moved
	return out


static func _add_multimesh(
	instance: MultiMeshInstance3D,
	path: String,
	here: Transform3D,
	pieces: Array[Dictionary],
	problems: PackedStringArray
) -> void:
	var multimesh: MultiMesh = instance.multimesh
	if multimesh == null or multimesh.mesh == null:
		return
	if multimesh.transform_format != MultiMesh.TRANSFORM_3D:
		problems.append("%s: a MultiMesh of 2D transforms; left out" % path)
		return
	var materials: Array[Material] = _materials_shown(instance, multimesh.mesh)
	var count: int = multimesh.instance_count
	if multimesh.visible_instance_count >= 0:
		count = mini(count, multimesh.visible_instance_count)
	if count > 0 and multimesh.buffer.is_empty():
		problems.append(
			(
				(
					"%s: this run's renderer keeps no MultiMesh instance transforms (--headless?); its %d instances"
					+ " are left out: make the plant where the scene renders (the editor, or a run with a display)"
				)
				% [path, count]
			)
		)
		return
	# Lost only where the materials show them: instance colours come through COLOR (a StandardMaterial3D
	# shows it as albedo when told to), custom data through INSTANCE_CUSTOM.
	var coloured: bool = (
		multimesh.use_colors
		and materials.any(func(material: Material) -> bool: return _reads(material, "COLOR"))
		and range(count).any(func(k: int) -> bool: return multimesh.get_instance_color(k) != Color.WHITE)
	)
	var customised: bool = (
		multimesh.use_custom_data
		and materials.any(func(material: Material) -> bool: return _reads(material, "INSTANCE_CUSTOM"))
		and range(count).any(
			func(k: int) -> bool: return multimesh.get_instance_custom_data(k) != Color(0.0, 0.0, 0.0, 0.0)
		)
	)
	var lost: PackedStringArray = []
	if coloured:
		lost.append("colours")
	if customised:
		lost.append("custom data")
	if not lost.is_empty():
		problems.append(
			(
				(
					"%s: its instances' own %s are not carried (a field's plant is one mesh; the field sets each"
					+ " plant's custom data for the wind): every instance is drawn alike"
				)
				% [path, " and ".join(lost)]
			)
		)
	for k: int in count:
		var placed: Transform3D = here * multimesh.get_instance_transform(k)
		pieces.append(_piece("%s (instance %d)" % [path, k], multimesh.mesh, materials, placed, [], instance))


static func _add_csg(
	shape: CSGShape3D, path: String, here: Transform3D, pieces: Array[Dictionary], problems: PackedStringArray
) -> void:
	var baked: ArrayMesh = shape.bake_static_mesh() if shape.is_root_shape() else null
	if baked == null or baked.get_surface_count() == 0:
		problems.append(
			"%s: the CSG shape gives no mesh outside the scene tree; left out (bake it to a MeshInstance3D)" % path
		)
		return
	pieces.append(_piece(path, baked, _materials_shown(shape, baked), here, [], shape))


static func _piece(
	path: String,
	mesh: Mesh,
	materials: Array[Material],
	here: Transform3D,
	weights: PackedFloat32Array,
	instance: GeometryInstance3D
) -> Dictionary:
	return {
		"name": path,
		"mesh": mesh,
		"materials": materials,
		"transform": here,
		"weights": weights,
		"level": -1,
		"suffix": level_of_name(instance.name),
		"range": Vector2(instance.visibility_range_begin, instance.visibility_range_end),
		"instance_parameters": instance_parameters(instance, materials),
	}


## The values [param instance] gives the [code]instance uniform[/code]s its [param materials]'
## shaders declare (its [code]instance_shader_parameters/…[/code]), by name; those it leaves at the
## shader's default are not in it.
static func instance_parameters(instance: GeometryInstance3D, materials: Array[Material]) -> Dictionary:
	if _instance_uniform == null:
		_instance_uniform = RegEx.create_from_string("instance\\s+uniform\\s+(?:\\w+\\s+)+?(\\w+)\\s*[:;=]")
	var found: Dictionary = {}
	for material: Material in materials:
		var shader: Shader = (material as ShaderMaterial).shader if material is ShaderMaterial else null
		if shader == null:
			continue
		for uniform: RegExMatch in _instance_uniform.search_all(shader.code):
			var value: Variant = instance.get_instance_shader_parameter(uniform.get_string(1))
			if value != null:
				found[uniform.get_string(1)] = value
	return found


## Levels from the names' suffixes: the suffixes present, lowest first, are levels 1, 2, 3 (a gap,
## and suffixes past the third, named).
static func _levels_from_suffixes(pieces: Array[Dictionary], problems: PackedStringArray) -> void:
	var suffixes: Array = []
	for piece: Dictionary in pieces:
		if piece.suffix >= 0 and not suffixes.has(piece.suffix):
			suffixes.append(piece.suffix)
	suffixes.sort()
	for k: int in suffixes.size():
		if suffixes[k] != k and k < LEVELS:
			problems.append(
				(
					"the level-of-detail suffixes go %s with no _LOD%d: _LOD%d is taken as mesh level %d"
					% [", ".join(suffixes.map(func(s: int) -> String: return "_LOD%d" % s)), k, suffixes[k], k + 1]
				)
			)
			break
	for piece: Dictionary in pieces:
		if piece.suffix < 0:
			continue
		var level: int = suffixes.find(piece.suffix)
		if level >= LEVELS:
			problems.append(
				"%s: level of detail %d is past the three mesh levels; left out" % [piece.name, piece.suffix]
			)
		piece.level = level
	for k: int in range(pieces.size() - 1, -1, -1):
		if pieces[k].level >= LEVELS:
			pieces.remove_at(k)


## Levels from visibility ranges (Godot's manual levels of detail): the distinct ranges, nearest
## first, are levels 1, 2, 3; a piece with no range is in every level; ranges past the third, named.
static func _levels_from_ranges(pieces: Array[Dictionary], problems: PackedStringArray) -> void:
	var ranges: Array[Vector2] = []
	for piece: Dictionary in pieces:
		if piece.range != Vector2.ZERO and not ranges.has(piece.range):
			ranges.append(piece.range)
	if ranges.is_empty():
		return
	ranges.sort_custom(func(a: Vector2, b: Vector2) -> bool: return a.x < b.x or a.x == b.x and a.y < b.y)
	for k: int in range(pieces.size() - 1, -1, -1):
		var piece: Dictionary = pieces[k]
		if piece.range == Vector2.ZERO:
			continue
		piece.level = ranges.find(piece.range)
		if piece.level >= LEVELS:
			(
				problems
				. append(
					(
						"%s: its visibility range %.1f–%.1f m is the %dth of the scene's; past the three mesh levels, left out"
						% [piece.name, piece.range.x, piece.range.y, piece.level + 1]
					)
				)
			)
			pieces.remove_at(k)


## The material [param instance] shows on each surface of [param mesh]: its material override, else
## (a MeshInstance3D) its surface override, else the mesh's own.
static func _materials_shown(instance: GeometryInstance3D, mesh: Mesh) -> Array[Material]:
	var materials: Array[Material] = []
	for surface: int in mesh.get_surface_count():
		var shown: Material = instance.material_override
		if shown == null and instance is MeshInstance3D:
			shown = (instance as MeshInstance3D).get_surface_override_material(surface)
		materials.append(shown if shown else mesh.surface_get_material(surface))
	return materials


## Whether [param material] shows what the shader reads as [param built_in] ("COLOR": a
## StandardMaterial3D that uses vertex colours as albedo; either: a ShaderMaterial whose code names it).
static func _reads(material: Material, built_in: String) -> bool:
	if material is BaseMaterial3D:
		return built_in == "COLOR" and (material as BaseMaterial3D).vertex_color_use_as_albedo
	var shader: Shader = (material as ShaderMaterial).shader if material is ShaderMaterial else null
	return shader != null and shader.code.contains(built_in)


static func _has_bone_weights(mesh: Mesh) -> bool:
	for surface: int in mesh.get_surface_count():
		if mesh.surface_get_arrays(surface)[Mesh.ARRAY_BONES] != null:
			return true
	return false
