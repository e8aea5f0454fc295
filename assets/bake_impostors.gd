extends SceneTree
## Renders a plant's impostor atlases with the addon's baker (addons/sunflower_field/plant/impostor_baker.gd,
## the editor's "Bake impostors"), into the given folder as <name>_views.png, <name>_normals.png and <name>_depths.png:
## the built-in sunflower ("sunflower"), or the plant resource given with its name; the alpha cuts
## the bake measures go into the plant's .tres ([member SunflowerPlant.impostor_alpha_cuts]).
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
	var source: SunflowerPlant = (
		SunflowerPlant.default_plant() if plant_path.is_empty() else load(plant_path) as SunflowerPlant
	)
	if source == null:
		printerr("cannot load the plant %s" % plant_path)
		quit(1)
		return
	var plant: SunflowerPlant = source.duplicate() as SunflowerPlant
	var result: Error = await plant.bake_impostors(root, out_dir, base_name)
	for kind: String in SunflowerPlant.IMPOSTOR_TEXTURES:
		print("%s: %s %s" % [kind, out_dir.path_join("%s_%s.png" % [base_name, kind]), error_string(result)])
	if result == OK:
		result = _write_alpha_cuts(source.resource_path, plant.impostor_alpha_cuts)
	quit(0 if result == OK else 1)


## Writes the baker's measured alpha cuts into the plant's hand-written .tres as its
## impostor_alpha_cuts line (replaced where it is, else added after impostor_depths), keeping the
## rest of the file as it is.
func _write_alpha_cuts(plant_path: String, cuts: PackedFloat32Array) -> Error:
	var text: String = FileAccess.get_file_as_string(plant_path)
	if text.is_empty():
		printerr("cannot read %s" % plant_path)
		return ERR_FILE_CANT_READ
	var values: PackedStringArray = []
	for cut: float in cuts:
		values.append("%.4f" % cut)
	var line: String = "impostor_alpha_cuts = PackedFloat32Array(%s)" % ", ".join(values)
	var lines: PackedStringArray = text.split("\n")
	var at: int = -1
	for i: int in lines.size():
		if lines[i].begins_with("impostor_alpha_cuts = "):
			lines[i] = line
			at = i
	if at < 0:
		for i: int in lines.size():
			if lines[i].begins_with("impostor_depths = "):
				at = i + 1
		if at < 0:
			printerr("%s has no impostor_depths line to put the alpha cuts after" % plant_path)
			return ERR_PARSE_ERROR
		lines.insert(at, line)
	var file: FileAccess = FileAccess.open(plant_path, FileAccess.WRITE)
	if file == null:
		printerr("cannot write %s" % plant_path)
		return FileAccess.get_open_error()
	file.store_string("\n".join(lines))
	print("alpha cuts: %s" % line)
	return OK
