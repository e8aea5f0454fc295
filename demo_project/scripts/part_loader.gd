class_name PartLoader
extends RefCounted
## Loads a plant part from a glTF file (the thesis' "load your own parts while flying").
## A part is modelled with its root at the origin and height 1 along +y.


## Returns {"mesh": Mesh} or {"error": String} naming the file and what is wrong.
static func load_mesh(path: String) -> Dictionary:
	if not FileAccess.file_exists(path):
		return {"error": "%s: no such file" % path}
	var document: GLTFDocument = GLTFDocument.new()
	var state: GLTFState = GLTFState.new()
	var error: Error = document.append_from_file(path, state)
	if error != OK:
		return {"error": "%s: not a readable glTF file (%s)" % [path, error_string(error)]}
	var scene: Node = document.generate_scene(state)
	if scene == null:
		return {"error": "%s: the glTF file holds no scene" % path}
	var mesh: Mesh = _first_mesh(scene)
	scene.free()
	if mesh == null:
		return {"error": "%s: the glTF file holds no mesh" % path}
	var result: Dictionary = {"mesh": mesh}
	var box: AABB = mesh.get_aabb()
	if absf(box.position.y) > 0.1 or absf(box.end.y - 1.0) > 0.25:
		result["warning"] = (
			"%s: the part spans y %.2f to %.2f; parts should stand on the origin and be 1 unit tall"
			% [path, box.position.y, box.end.y]
		)
	return result


## Parses "LEVEL,PART,PATH" (level 1–3; part 1–3 or bottom/middle/head) into
## {"lod": int, "part": int, "path": String} or {"error": String}.
static func parse_argument(argument: String) -> Dictionary:
	var pieces: PackedStringArray = argument.split(",", true, 2)
	if pieces.size() != 3:
		return {"error": "--part %s: expected LEVEL,PART,PATH, e.g. 1,head,/tmp/head.glb" % argument}
	if not pieces[0].is_valid_int() or pieces[0].to_int() < 1 or pieces[0].to_int() > 3:
		return {"error": "--part %s: LEVEL must be 1, 2 or 3, not '%s'" % [argument, pieces[0]]}
	var names: PackedStringArray = ["bottom", "middle", "head"]
	var part: int = names.find(pieces[1].to_lower())
	if part < 0 and pieces[1].is_valid_int() and pieces[1].to_int() >= 1 and pieces[1].to_int() <= 3:
		part = pieces[1].to_int() - 1
	if part < 0:
		return {"error": "--part %s: PART must be bottom, middle, head or 1–3, not '%s'" % [argument, pieces[1]]}
	return {"lod": pieces[0].to_int() - 1, "part": part, "path": pieces[2]}


static func _first_mesh(node: Node) -> Mesh:
	if node is MeshInstance3D and (node as MeshInstance3D).mesh:
		return (node as MeshInstance3D).mesh
	for child: Node in node.get_children():
		var mesh: Mesh = _first_mesh(child)
		if mesh:
			return mesh
	return null
