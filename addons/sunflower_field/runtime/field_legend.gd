@tool
extends RefCounted
## A field's legend ([member SunflowerField.legend]: symbol → PackedScene or SunflowerPlant) read as the
## native map parser needs it: the object symbols, the plant types' symbols (species 1, 2, … in
## order) and their plants. A key that is not one character other than '*', ' ' and '.' is warned
## about and left out.


## The legend's object symbols (scenes) as one string, warning about any unusable key.
static func object_symbols(legend: Dictionary) -> String:
	var symbols: String = ""
	for key: Variant in _usable_keys(legend, true):
		if not (legend[key] is SunflowerPlant):
			symbols += str(key)
	return symbols


## The legend's symbols that are plant types (species 1, 2, … in this order).
static func plant_symbols(legend: Dictionary) -> String:
	var symbols: String = ""
	for key: Variant in _usable_keys(legend, false):
		if legend[key] is SunflowerPlant:
			symbols += str(key)
	return symbols


## The legend's plant types, in the order of [method plant_symbols].
static func plants(legend: Dictionary) -> Array[SunflowerPlant]:
	var plants: Array[SunflowerPlant] = []
	for key: Variant in _usable_keys(legend, false):
		if legend[key] is SunflowerPlant:
			plants.append(legend[key] as SunflowerPlant)
	return plants


## The keys that are one character other than '*', ' ' and '.' (warning about the others).
static func _usable_keys(legend: Dictionary, warn: bool) -> Array:
	var keys: Array = []
	for key: Variant in legend:
		var symbol: String = str(key)
		if symbol.length() != 1 or symbol in ["*", " ", "."]:
			if warn:
				push_warning(
					"SunflowerField.legend: key '%s' must be one character other than '*', ' ' and '.'" % symbol
				)
			continue
		keys.append(key)
	return keys
