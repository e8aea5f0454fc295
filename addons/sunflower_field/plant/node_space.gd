@tool
extends RefCounted
## A shader of your own that reads model-space positions ([code]VERTEX[/code] in its
## [code]vertex()[/code] to colour by height, [code]MODEL_MATRIX[/code],
## [code]MODEL_NORMAL_MATRIX[/code] or [code]NODE_POSITION_*[/code]) sees the model space it was
## authored in, though the merge puts its node's transform into the plant's vertices: the part is
## drawn by a copy of the shader whose [code]vertex()[/code] takes [code]VERTEX[/code],
## [code]NORMAL[/code], [code]TANGENT[/code] and [code]BINORMAL[/code] into the node's space first and
## back into the plant's after, and whose node matrices are the plant's times the node's transform
## (the transform and its inverse uniforms of the copy; one copy per material and transform). A copy
## that does not compile is named. (A processor function cannot return early, so the last line of its
## body is its end.)

const PlantMaterial: GDScript = preload("plant_material.gd")
## The copy's uniforms: the node's transform in the plant, and its inverse.
const TRANSFORM_UNIFORM: String = "plant_node_transform"
const INVERSE_UNIFORM: String = "plant_node_inverse"
const UNIFORMS: String = "uniform mat4 plant_node_transform; uniform mat4 plant_node_inverse; "
## First in the copy's vertex(): the plant's space to the node's (normals by the inverse transpose).
const INTO_NODE: String = (
	" VERTEX = (plant_node_inverse * vec4(VERTEX, 1.0)).xyz;"
	+ " NORMAL = normalize(transpose(mat3(plant_node_transform)) * NORMAL);"
	+ " TANGENT = normalize(mat3(plant_node_inverse) * TANGENT);"
	+ " BINORMAL = normalize(mat3(plant_node_inverse) * BINORMAL);"
)
## Last in it: back to the plant's space.
const INTO_PLANT: String = (
	" VERTEX = (plant_node_transform * vec4(VERTEX, 1.0)).xyz;"
	+ " NORMAL = normalize(transpose(mat3(plant_node_inverse)) * NORMAL);"
	+ " TANGENT = normalize(mat3(plant_node_transform) * TANGENT);"
	+ " BINORMAL = normalize(mat3(plant_node_transform) * BINORMAL); "
)
const READS_MATRIX: String = "\\b(MODEL_MATRIX|MODEL_NORMAL_MATRIX|NODE_POSITION_WORLD|NODE_POSITION_VIEW)\\b"
## The node's matrices in the copy: the plant's (each plant's instance in a field) times the node's
## transform in the plant, in this order (the last two name MODEL_MATRIX after the first is replaced).
const NODE_MATRICES: Array[Array] = [
	["\\bMODEL_MATRIX\\b", "(MODEL_MATRIX * plant_node_transform)"],
	["\\bMODEL_NORMAL_MATRIX\\b", "(MODEL_NORMAL_MATRIX * transpose(mat3(plant_node_inverse)))"],
	["\\bNODE_POSITION_WORLD\\b", "(MODEL_MATRIX * plant_node_transform)[3].xyz"],
	["\\bNODE_POSITION_VIEW\\b", "(VIEW_MATRIX * MODEL_MATRIX * plant_node_transform)[3].xyz"],
]


## Gives each piece (ScenePieces.of) on a moved node whose shader reads model-space positions a copy
## of its material that sees the node's space; names in [param problems] the pieces whose shader
## cannot be given it (the copy does not compile).
static func keep(pieces: Array[Dictionary], problems: PackedStringArray) -> void:
	var copies: Dictionary = {}  # [material, transform] → its copy (null: cannot be made)
	var named: Dictionary = {}  # node path → true (a MultiMesh's instances are one node)
	for piece: Dictionary in pieces:
		var transform: Transform3D = piece.transform
		if transform.is_equal_approx(Transform3D.IDENTITY):
			continue
		for index: int in piece.materials.size():
			var material: ShaderMaterial = piece.materials[index] as ShaderMaterial
			if material == null or material.shader == null:
				continue
			if material.shader.resource_path.begins_with(PlantMaterial.ADDON_FOLDER):
				continue
			if _reads_none(material.shader.code):
				continue
			var key: Array = [material, transform]
			if not copies.has(key):
				copies[key] = _copy(material, transform)
			if copies[key] != null:
				piece.materials[index] = copies[key]
				continue
			if named.has(piece.name):
				continue
			named[piece.name] = true
			problems.append(
				(
					(
						"%s: its shader %s reads model-space positions, and the node's transform is merged into the"
						+ " plant's vertices: a copy of it that sees the node's space does not compile, so it sees the"
						+ " plant's model space (keep the node at the scene root's transform, or read positions the"
						+ " plant's way)"
					)
					% [piece.name, PlantMaterial.named(material.shader)]
				)
			)


## [param code] with its vertex() and node matrices in the node's space (see the script's
## description), or "" when it reads no model-space position.
static func node_space_code(code: String) -> String:
	if _reads_none(code):
		return ""
	for pair: Array in NODE_MATRICES:
		code = PlantMaterial.regex(pair[0]).sub(code, pair[1], true)
	var body: Vector2i = PlantMaterial.function_body(code, "vertex")
	if body.x < 0:  # the uniforms before its first function
		var first: RegExMatch = PlantMaterial.regex("\\bvoid\\s+(fragment|light)\\s*\\(").search(code)
		return code.substr(0, first.get_start()) + UNIFORMS + code.substr(first.get_start()) if first else ""
	var head: RegExMatch = PlantMaterial.regex(PlantMaterial.FUNCTION_PATTERN % "vertex").search(code)
	# On the lines they change: the shader's errors keep your line numbers.
	return (
		code.substr(0, head.get_start())
		+ UNIFORMS
		+ code.substr(head.get_start(), body.x - head.get_start())
		+ INTO_NODE
		+ code.substr(body.x, body.y - body.x)
		+ INTO_PLANT
		+ code.substr(body.y)
	)


## Whether [param code] reads no model-space position: no node matrix, no VERTEX in its vertex().
static func _reads_none(code: String) -> bool:
	if PlantMaterial.regex(READS_MATRIX).search(code):
		return false
	var body: Vector2i = PlantMaterial.function_body(code, "vertex")
	return body.x < 0 or PlantMaterial.regex("\\bVERTEX\\b").search(code.substr(body.x, body.y - body.x)) == null


static func _copy(own: ShaderMaterial, transform: Transform3D) -> ShaderMaterial:
	var code: String = node_space_code(own.shader.code)
	if code.is_empty():
		return null
	var shader: Shader = Shader.new()
	shader.code = code
	shader.resource_name = own.shader.resource_name
	if shader.get_shader_uniform_list().is_empty():
		return null  # it does not compile (it declares two uniforms, maybe not at a line's start)
	var copy: ShaderMaterial = PlantMaterial.copy_with_shader(own, shader)
	copy.set_shader_parameter(TRANSFORM_UNIFORM, Projection(transform))
	copy.set_shader_parameter(INVERSE_UNIFORM, Projection(transform.affine_inverse()))
	return copy
