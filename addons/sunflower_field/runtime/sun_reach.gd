@tool
extends RefCounted
## How far the sun's shadows reach in a node's viewport: the farthest
## [member DirectionalLight3D.directional_shadow_max_distance] of its shadow-casting suns. Asked
## once a frame, it reads a few properties of the suns it knows, and looks for suns again only when
## the scene tree gained or lost a DirectionalLight3D.

## Godot's default DirectionalLight3D.directional_shadow_max_distance: how far the sun's shadows
## reach when the viewport has no shadow-casting directional light (yet).
const SUN_SHADOW_DISTANCE: float = 100.0

var _owner: Node
var _suns: Array = []  # DirectionalLight3D nodes, some perhaps freed since
var _stale: bool = true


## The suns of [param owner]'s viewport.
func _init(owner: Node) -> void:
	_owner = owner


## How far the sun's shadows reach now; [constant SUN_SHADOW_DISTANCE] when no sun casts shadows.
func reach() -> float:
	if _stale:
		_find_suns()
	var farthest: float = 0.0
	for entry: Variant in _suns:
		if not is_instance_valid(entry):
			continue
		var sun: DirectionalLight3D = entry
		if sun.shadow_enabled and sun.is_visible_in_tree():
			farthest = maxf(farthest, sun.directional_shadow_max_distance)
	return farthest if farthest > 0.0 else SUN_SHADOW_DISTANCE


func _find_suns() -> void:
	_stale = false
	_suns.clear()
	if not _owner.is_inside_tree():
		_stale = true  # look again once the owner is in a tree
		return
	var tree: SceneTree = _owner.get_tree()
	if not tree.node_added.is_connected(_on_tree_changed):
		tree.node_added.connect(_on_tree_changed)
		tree.node_removed.connect(_on_tree_changed)
	for sun: Node in _owner.get_viewport().find_children("*", "DirectionalLight3D", true, false):
		_suns.append(sun)


func _on_tree_changed(node: Node) -> void:
	if node is DirectionalLight3D:
		_stale = true
