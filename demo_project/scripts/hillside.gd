class_name DemoHillside
extends RefCounted
## The demo's "Hillside" map: generated from placement rules (res://rules/hillside_rules.tres) on
## the demo's hills — maples in patches of noise and bushes at their edges, sunflowers in the low,
## level meadows, grass where the slope allows, none of them on the winding track — into
## fields/hillside.field, a map like any other (read it, diff it, paint it). Written again by
##
##     tools/make_hillside_field.sh
##
## and the demo's tests check that the rules still give that file byte for byte.

const MAP_PATH: String = "res://fields/hillside.field"
const RULES_PATH: String = "res://rules/hillside_rules.tres"
const COLUMNS: int = 240
const ROWS: int = 240
const HEADER: String = (
	"# Hillside: 240 x 240 cells of 0.5 m on the demo's hills, generated from placement rules\n"
	+ "# (demo_project/rules/hillside_rules.tres) by tools/make_hillside_field.sh. 't' maple, 'b' bottlebrush\n"
	+ "# bush, 'g' grass clump (DemoPlants), '*' sunflower; a track winds through, kept clear."
)


## The winding track the rules keep clear, a Path3D named "Track" in the field's space (the field
## stands at the origin): west to east across the field, swinging north and south.
static func track() -> Path3D:
	var path: Path3D = Path3D.new()
	path.name = "Track"
	path.curve = Curve3D.new()
	for step: int in 25:
		var x: float = step * 5.0
		path.curve.add_point(Vector3(x, 0.0, 62.0 + 24.0 * sin(x / 19.0)))
	return path


## The demo's hills (as main.tscn places them, their collision on), the track and a field on the
## hills' colliders with the demo plants' symbols in its legend (plants of no form: only their
## symbols are read), under [param parent]; awaits the physics frame the hills' collision needs.
static func stage(parent: Node) -> SunflowerField:
	var hills: DemoHills = DemoHills.new()
	hills.name = "Hills"
	hills.position = Vector3(60.0, 0.0, 60.0)
	parent.add_child(hills)
	hills.set_enabled(true)
	parent.add_child(track())
	var field: SunflowerField = SunflowerField.new()
	field.name = "Field"
	field.ground_source = SunflowerField.GroundSource.COLLIDERS
	var legend: Dictionary = {}
	for symbol: String in DemoPlants.SCENES:
		legend[symbol] = SunflowerPlant.new()
	field.legend = legend
	parent.add_child(field)
	await parent.get_tree().physics_frame
	await parent.get_tree().physics_frame
	return field


## The hillside's map text as the rules give it on [param field] (on the hills, ground source
## Colliders, with the demo plants' symbols in its legend and the track beside it); awaits the
## physics frame the hills' collision needs. Empty after an error.
static func generate(field: SunflowerField) -> PackedByteArray:
	var empty: SunflowerFieldMap = SunflowerFieldMap.new()
	empty.source_path = MAP_PATH
	empty.text = ("%s\n%d %d\n" % [HEADER, COLUMNS, ROWS]).to_utf8_buffer()
	empty.check_format()
	field.map = empty
	await field.get_tree().physics_frame
	await field.get_tree().physics_frame
	var made: SunflowerFieldMap = (load(RULES_PATH) as SunflowerPlacementRules).generate_map(field)
	return made.text if made else PackedByteArray()
