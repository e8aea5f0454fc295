@tool
extends RefCounted
## A shader of your own that reads positions in its [code]vertex()[/code] ([code]VERTEX[/code], to
## colour by height, say) sees the model space it was authored in, though the merge puts its node's
## transform into the plant's vertices: the part is drawn by a copy of the shader whose
## [code]vertex()[/code] takes [code]VERTEX[/code], [code]NORMAL[/code], [code]TANGENT[/code] and
## [code]BINORMAL[/code] into the node's space first and back into the plant's after, the node's
## transform a uniform of the copy (one copy per material and transform). What cannot be carried is
## named: a shader that reads [code]MODEL_MATRIX[/code] or [code]NODE_POSITION_*[/code] (each plant
## of a field is an instance of its own). (A processor function cannot return early, so the last
## line of its body is its end.)

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
const READS_MATRIX: String = "\\b(MODEL_MATRIX|NODE_POSITION_WORLD|NODE_POSITION_VIEW)\\b"


## Gives each piece (ScenePieces.of) on a moved node whose shader reads positions in its vertex() a
## copy of its material that sees the node's space; names in [param problems] the pieces whose
## shader cannot be given it.
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
			var why: String = _why_not(material.shader.code)
			if why == "reads none":
				continue
			if why.is_empty():
				var key: Array = [material, transform]
				if not copies.has(key):
					copies[key] = _copy(material, transform)
				if copies[key] != null:
					piece.materials[index] = copies[key]
					continue
				why = "a copy of it does not compile"
			if named.has(piece.name):
				continue
			named[piece.name] = true
			problems.append(
				(
					(
						"%s: its shader %s reads model-space positions (%s), and the node's transform is merged"
						+ " into the plant's vertices: it sees the plant's model space, not the node's (keep the node"
						+ " at the scene root's transform, or read positions the plant's way)"
					)
					% [piece.name, PlantMaterial.named(material.shader), why]
				)
			)


## [param code] with its vertex() in the node's space (see the script's description), or "".
static func node_space_code(code: String) -> String:
	if not _why_not(code).is_empty():
		return ""
	var body: Vector2i = PlantMaterial.function_body(code, "vertex")
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


## Why [param code]'s positions cannot be carried into the node's space: "" when they can, "reads
## none" when it reads no model-space position.
static func _why_not(code: String) -> String:
	var matrix: RegExMatch = PlantMaterial.regex(READS_MATRIX).search(code)
	if matrix:
		return "it reads %s, which is each plant's in a field" % matrix.get_string(1)
	var body: Vector2i = PlantMaterial.function_body(code, "vertex")
	if body.x < 0 or PlantMaterial.regex("\\bVERTEX\\b").search(code.substr(body.x, body.y - body.x)) == null:
		return "reads none"
	return ""


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
