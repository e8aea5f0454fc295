extends SceneTree
## Writes fields/hillside.field from the hillside's placement rules (scripts/hillside.gd):
##
##     godot --headless --path demo_project --script res://scripts/make_hillside.gd
##
## (tools/make_hillside_field.sh runs it.)


func _initialize() -> void:
	_make.call_deferred()


func _make() -> void:
	var field: SunflowerField = await DemoHillside.stage(root)
	var text: PackedByteArray = await DemoHillside.generate(field)
	if text.is_empty():
		printerr("make_hillside: the rules gave no map (the error above says why)")
		quit(1)
		return
	var file: FileAccess = FileAccess.open(DemoHillside.MAP_PATH, FileAccess.WRITE)
	file.store_buffer(text)
	file.close()
	print("make_hillside: wrote %s (%d bytes)" % [ProjectSettings.globalize_path(DemoHillside.MAP_PATH), text.size()])
	for child: Node in root.get_children():
		child.free()
	await process_frame
	quit(0)
