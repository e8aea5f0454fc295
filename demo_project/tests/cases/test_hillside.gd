extends TestCase
## The demo's Hillside map is what its placement rules give: generated again on the demo's hills
## (scripts/hillside.gd), it equals fields/hillside.field byte for byte, and the track stays clear.

var stage: Node3D


func before_each() -> void:
	stage = Node3D.new()
	tree.root.add_child(stage)


func after_each() -> void:
	stage.free()


func test_the_rules_give_the_hillside_map_byte_for_byte() -> void:
	var field: SunflowerField = await DemoHillside.stage(stage)
	var text: PackedByteArray = await DemoHillside.generate(field)
	var committed: PackedByteArray = FileAccess.get_file_as_bytes(DemoHillside.MAP_PATH)
	check(not text.is_empty(), "the rules gave a map")
	check(
		text == committed,
		"fields/hillside.field is what the rules give (run tools/make_hillside_field.sh after changing them)"
	)
	# The track: no plant within its half width (1.5 m) of its curve.
	var track: Path3D = stage.get_node("Track") as Path3D
	var lines: PackedStringArray = committed.get_string_from_utf8().split("\n")
	var first_row: int = 0
	while lines[first_row].begins_with("#"):
		first_row += 1
	first_row += 1
	var on_track: int = 0
	var plants: Dictionary = {}
	for row: int in DemoHillside.ROWS:
		var line: String = lines[first_row + row]
		for column: int in line.length():
			if line[column] == ".":
				continue
			plants[line[column]] = plants.get(line[column], 0) + 1
			var centre: Vector3 = Vector3((column + 0.5) * 0.5, 0.0, (row + 0.5) * 0.5)
			var nearest: Vector3 = track.curve.get_closest_point(centre)
			if Vector2(centre.x, centre.z).distance_to(Vector2(nearest.x, nearest.z)) <= 1.5:
				on_track += 1
	print("     hillside: %s" % plants)
	check_eq(on_track, 0, "no plant on the track")
	for symbol: String in ["t", "b", "g", "*"]:
		check(plants.get(symbol, 0) > 50, "'%s' placed (%d)" % [symbol, plants.get(symbol, 0)])
