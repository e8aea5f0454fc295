extends RefCounted
## Scenes the tests build in code.


## [param root] and everything under it packed as a scene (every node owned by the root, so that it
## is saved); the nodes are freed.
static func packed(root: Node) -> PackedScene:
	for node: Node in root.find_children("*", "", true, false):
		node.owner = root
	var scene: PackedScene = PackedScene.new()
	scene.pack(root)
	root.free()
	return scene
