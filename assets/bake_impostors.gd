extends SceneTree
## Renders a plant's impostor atlases with the addon's baker (addons/sunflower_field/impostor_baker.gd,
## the editor's "Bake impostors"), into the given folder as <name>_views.png, <name>_normals.png and <name>_depths.png:
## the built-in sunflower ("sunflower"), or the plant resource given with its name.
##
## Needs a real renderer (not --headless): xvfb-run godot --path <project with the addon> \
##     --script assets/bake_impostors.gd -- <output folder> [<plant .tres> <name>]


func _init() -> void:
	var args: PackedStringArray = OS.get_cmdline_user_args()
	if args.is_empty():
		printerr("usage: xvfb-run godot --path <project> --script bake_impostors.gd -- <output folder>")
		quit(2)
		return
	_bake.call_deferred(args[0], args[1] if args.size() > 2 else "", args[2] if args.size() > 2 else "sunflower")


func _bake(out_dir: String, plant_path: String, base_name: String) -> void:
	var source: FieldPlant = FieldPlant.default_plant() if plant_path.is_empty() else load(plant_path) as FieldPlant
	if source == null:
		printerr("cannot load the plant %s" % plant_path)
		quit(1)
		return
	var plant: FieldPlant = source.duplicate() as FieldPlant
	var result: Error = await plant.bake_impostors(root, out_dir, base_name)
	for kind: String in FieldPlant.IMPOSTOR_TEXTURES:
		print("%s: %s %s" % [kind, out_dir.path_join("%s_%s.png" % [base_name, kind]), error_string(result)])
	quit(0 if result == OK else 1)
