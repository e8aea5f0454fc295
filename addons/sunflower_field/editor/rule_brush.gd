@tool
extends RefCounted
## The painter's brush following a layer of the field's [SunflowerPlacementRules]: a stroke paints
## (or erases) a cell with the brush's density times the layer's filter weight there (height, slope,
## mask, noise, paths, exclusion; none within its spacing of a plant of the layer it names), so a
## hand-painted patch keeps to the slopes, heights and verges the rules keep to. The layer's own
## density is not used: the brush has its own.
##
## The field's ground is read once, when a layer is chosen (a few milliseconds a frame, as Generate
## reads it) and again after the field's settings change; the layers themselves are read again at
## every stroke, so an edited rule applies at the next stroke.

const FieldLegend: GDScript = preload("../runtime/field_legend.gd")

## The layer followed, counted from 0; -1: none (the brush paints anywhere).
var layer: int = -1

var _field: SunflowerField
var _heights: Variant = null  # the ground's heights once read (PackedFloat32Array), else null
var _reading: int = 0  # bumped by every new read; a read that finds it changed stops
var _reading_now: bool = false
var _read_share: float = 0.0
var _placement: RefCounted  # the rules' native placement for the stroke under way
var _cells: PackedByteArray  # the stroke's map as cells (0 empty, 1 + plant type), for the spacing
var _symbols: String  # the field's legend plant symbols


## Follows layer [param index] of [param field]'s rules from now on (-1: none) and starts reading
## its ground. Awaitable: returns when the ground is read (or the read was replaced or failed).
func follow(field: SunflowerField, index: int) -> void:
	layer = index
	_field = field
	_heights = null
	_read_share = 0.0
	_reading += 1
	_reading_now = false
	if layer < 0 or field == null or field.placement_rules == null:
		return
	var reading: int = _reading
	_reading_now = true
	var heights: Variant = await field.placement_rules.read_ground_in_steps(
		field,
		SunflowerPlacementRules.GROUND_READ_BUDGET_USEC,
		func(share: float) -> bool:
			_read_share = share
			return _reading == reading and is_instance_valid(field)
	)
	if _reading == reading:
		_heights = heights
		_reading_now = false


## Forgets the ground read (the field's settings changed); it is read again for the next stroke.
func invalidate() -> void:
	if layer >= 0 and is_instance_valid(_field):
		follow(_field, layer)


## Whether the ground is being read.
func is_reading() -> bool:
	return _reading_now


## What keeps a stroke from following the layer now, or "" (also when no layer is followed).
func problem(field: SunflowerField) -> String:
	if layer < 0:
		return ""
	if field != _field or field.placement_rules == null or layer >= field.placement_rules.layers.size():
		return "the field has no placement rule %d to follow; choose another in the toolbar" % (layer + 1)
	var heights: PackedFloat32Array = _heights if _heights is PackedFloat32Array else PackedFloat32Array()
	if not heights.is_empty() and field.map and heights.size() != field.map.columns * field.map.rows:
		invalidate()  # the map was resized since: its ground is read again
	if is_reading():
		return (
			"the field's ground is still being read for its rules (%d %%); paint again in a moment"
			% roundi(_read_share * 100.0)
		)
	if _heights == null:
		return "the field's ground could not be read for its rules (the error above says why)"
	return ""


## Readies a stroke on [param map_text] (the map as the stroke begins); returns what is wrong, or "".
func begin(field: SunflowerField, map_text: PackedByteArray) -> String:
	_placement = null
	var wrong: String = problem(field)
	if layer < 0 or not wrong.is_empty():
		return wrong
	_placement = field.placement_rules.placement_for(field, _heights)
	if _placement == null:
		return "the field's placement rules cannot run (the error above says why)"
	_symbols = FieldLegend.plant_symbols(field.legend)
	_cells = _placement.read_map_cells(map_text, _symbols)
	return ""


## Whether the stroke under way follows a layer.
func is_following() -> bool:
	return _placement != null


## [param rect] of cells as SunflowerMap.paint takes it: column, row, columns, rows.
static func rect_cells(rect: Rect2i) -> PackedInt32Array:
	return PackedInt32Array([rect.position.x, rect.position.y, rect.size.x, rect.size.y])


## The layer's weights over the cells a dab at [param center] of [param reach] cells touches (both
## in cells): [weights (PackedFloat32Array), their Rect2i of cells], clipped to the map.
func weights_at(center: Vector2, reach: float) -> Array:
	var low: Vector2i = Vector2i(floori(center.x - reach), floori(center.y - reach)).max(Vector2i.ZERO)
	var high: Vector2i = Vector2i(floori(center.x + reach), floori(center.y + reach)).min(
		Vector2i(_field.map.columns - 1, _field.map.rows - 1)
	)
	var rect: Rect2i = Rect2i(low, (high - low + Vector2i.ONE).max(Vector2i.ZERO))
	var weights: PackedFloat32Array = _placement.layer_weights(
		layer, rect.position.x, rect.position.y, rect.size.x, rect.size.y, _cells
	)
	return [weights, rect]


## Keeps the stroke's cells in step after a dab set [param changed] (column, row pairs) to
## [param painted] ('*', a legend symbol, or "" when erased).
func note_changed(changed: PackedInt32Array, painted: String) -> void:
	var value: int = 0
	if painted == "*":
		value = 1
	elif not painted.is_empty() and _symbols.contains(painted):
		value = _symbols.find(painted) + 2
	for i: int in range(0, changed.size(), 2):
		_cells[changed[i + 1] * _field.map.columns + changed[i]] = value


## Ends the stroke.
func end() -> void:
	_placement = null
	_cells = PackedByteArray()
