extends RefCounted
## Maps the tests and benchmarks make in memory.


## A map of [param columns] × [param rows] cells, [param symbol] in every one (a sunflower; "." for
## none), as if read from [param source_path].
static func filled(columns: int, rows: int, source_path: String, symbol: String = "*") -> SunflowerFieldMap:
	var lines: PackedStringArray = ["%d %d" % [columns, rows]]
	for row: int in rows:
		lines.append(symbol.repeat(columns))
	var field_map: SunflowerFieldMap = SunflowerFieldMap.new()
	field_map.source_path = source_path
	field_map.text = "\n".join(lines).to_utf8_buffer()
	return field_map
