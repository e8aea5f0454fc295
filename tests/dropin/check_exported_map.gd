extends SceneTree
## An exported game ships the imported map, not its .field source. `record FILE` writes a digest of the
## field that load_map_file("res://demo.field") builds; `compare FILE` (run after the source is
## deleted) builds it again and prints "exported map: ok" when the digest is the same.


func _initialize() -> void:
	_run.call_deferred()


func _run() -> void:
	var args: PackedStringArray = OS.get_cmdline_user_args()
	var field: SunflowerField = SunflowerField.new()
	root.add_child(field)
	if field.load_map_file("res://demo.field") != OK:
		print("exported map: load_map_file failed")
		quit(1)
		return
	var digest: String = "%d" % field.get_plant_count()
	for i: int in range(0, field.get_plant_count(), 7):
		digest += " %s" % field.get_plant_info(i)["position"]
	digest = digest.sha256_text()
	if args[0] == "record":
		FileAccess.open(args[1], FileAccess.WRITE).store_string(digest)
		print("exported map: recorded %d plants" % field.get_plant_count())
	else:
		var expected: String = FileAccess.get_file_as_string(args[1])
		var source_gone: bool = not FileAccess.file_exists("res://demo.field")
		var same: bool = digest == expected
		print(
			(
				"exported map: %s (source gone: %s, %d plants)"
				% ["ok" if same and source_gone else "DIFFERENT", source_gone, field.get_plant_count()]
			)
		)
	field.queue_free()
	quit()
