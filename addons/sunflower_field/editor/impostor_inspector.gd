@tool
extends EditorInspectorPlugin
## The "Bake impostors" button at the top of the inspector of a [SunflowerPlant], and of a
## [SunflowerField] growing a plant of its own: renders the plant's level-1 parts into its sprite
## and billboard textures, saves them beside the plant and reimports them.


func _can_handle(object: Object) -> bool:
	return object is SunflowerPlant or object is SunflowerField


func _parse_begin(object: Object) -> void:
	var button: Button = Button.new()
	button.text = "Bake impostors"
	button.tooltip_text = "Render the plant's level-1 parts from 120 views into its impostor atlases."
	if object is SunflowerField and (object as SunflowerField).plant == null:
		# Nothing of the field's own to bake: shown, but not offered.
		button.disabled = true
		button.tooltip_text = "The field grows the built-in sunflower, whose impostors ship baked: give it a plant first."
	button.pressed.connect(_bake.bind(object, button))
	add_custom_control(button)


func _bake(object: Object, button: Button) -> void:
	var plant: SunflowerPlant = object as SunflowerPlant
	if object is SunflowerField:
		plant = (object as SunflowerField).plant
		if plant == null:
			push_warning("Bake impostors: the field grows the built-in sunflower, whose impostors ship baked")
			return
	button.disabled = true
	button.text = "Baking…"
	var result: Error = await plant.bake_impostors(EditorInterface.get_base_control())
	if is_instance_valid(button):
		button.disabled = false
		button.text = "Bake impostors"
	if result == OK:
		print("Bake impostors: %s's textures are %s" % [plant.name, plant.impostor_views.resource_path])
		if plant.resource_path.contains("::") or plant.resource_path.is_empty():
			EditorInterface.mark_scene_as_unsaved()
