@tool
extends RefCounted
## Whom a field measures distances from: the node named in its [code]observer[/code] property, else
## the viewport's camera (in the editor, the editor's), and what the simulation needs of it (the
## position and, for a camera, the view's planes) in the field's space.

const NativeField: GDScript = preload("../native/native_field.gd")


## The observer node of [param field], or null when there is none.
static func resolve(field: Node3D, observer: NodePath) -> Node3D:
	if not observer.is_empty():
		var node: Node3D = field.get_node_or_null(observer) as Node3D
		if node:
			return node
	if Engine.is_editor_hint():
		var editor: Object = Engine.get_singleton("EditorInterface")
		if editor:
			var viewport: Viewport = editor.call("get_editor_viewport_3d", 0)
			if viewport and viewport.get_camera_3d():
				return viewport.get_camera_3d()
	var own_viewport: Viewport = field.get_viewport()
	return own_viewport.get_camera_3d() if own_viewport else null


## Hands the observer's position (and with [param culling], a camera's frustum planes) to
## [param simulation], in [param field]'s space, and returns the observer. Nothing happens without
## one (null).
static func push(field: Node3D, observer: NodePath, culling: bool, simulation: NativeField) -> Node3D:
	var node: Node3D = resolve(field, observer)
	if node == null:
		return null
	var to_local: Transform3D = field.global_transform.affine_inverse()
	var frustum: PackedFloat32Array = PackedFloat32Array()
	var camera: Camera3D = node as Camera3D
	if culling and camera and camera.is_inside_tree():
		for plane: Plane in camera.get_frustum():
			var local_plane: Plane = to_local * plane
			frustum.append_array([local_plane.normal.x, local_plane.normal.y, local_plane.normal.z, local_plane.d])
	simulation.set_observer(to_local * node.global_position, frustum)
	return node
