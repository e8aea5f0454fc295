extends SceneTree
## Renders the built-in sunflower's sprite and billboard textures with the addon's baker
## (addons/sunflower_field/impostor_baker.gd, the editor's "Bake impostors"), into the given folder
## as sunflower_front.png and sunflower_side.png.
##
## Needs a real renderer (not --headless): xvfb-run godot --path <project with the addon> \
##     --script assets/bake_impostors.gd -- <output folder>


func _init() -> void:
	var args: PackedStringArray = OS.get_cmdline_user_args()
	if args.is_empty():
		printerr("usage: xvfb-run godot --path <project> --script bake_impostors.gd -- <output folder>")
		quit(2)
		return
	_bake.call_deferred(args[0])


func _bake(out_dir: String) -> void:
	var plant: FieldPlant = FieldPlant.default_plant().duplicate() as FieldPlant
	var result: Error = await plant.bake_impostors(root, out_dir, "sunflower")
	for view: String in ["front", "side"]:
		print("%s: %s %s" % [view, out_dir.path_join("sunflower_%s.png" % view), error_string(result)])
	quit(0 if result == OK else 1)
